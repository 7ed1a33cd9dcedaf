// A Taylor-series integrator for the polynomial vector fields of the notes (Euler, attitude,
// Clebsch, Manakov, Nambu (3.16)): the high-accuracy flow used as ground truth by the dynamic
// properties and to generate the golden trajectories. Independent of impl/: the fields it
// integrates are written out again in oracle/fields.hpp.
//
// How it works. A field is a function template
//     template <class S> void operator()(const S* x, S* dxdt) const
// using only +, -, unary -, S * S and S * T (T a constant). It is run once on Recorder<T> values,
// which records the computation as a tape of nodes. One step then computes the Taylor
// coefficients x_0 .. x_N of the solution by sweeping the tape once per order k:
//     x_{k+1} = [f(x)]_k / (k + 1),
// where the k-th coefficient of a product is the Cauchy sum sum_j a_j b_{k-j}. Cost per step:
// about (number of products in f) * N^2 / 2 multiplications.
//
// Order and step (Jorba & Zou 2005): N = ceil(-ln(tol) / 2) + 1, and
//     h = min over m in {N-1, N} of (tol * max(1, |x_0|) / |x_m|)^(1/m),
// so that the last terms kept are below the tolerance; the truncation error is then of the size
// of the first neglected term. Sample times inside a step are evaluated from the step's Taylor
// polynomial (Horner), so sampling does not shorten steps.
//
// Mixed precision (a multiprecision T only). The k-th coefficient enters the solution as
// x_k h^k, which falls geometrically from |x| to tol |x| over k = 0..N. It therefore needs only
// the digits that survive the factor h^k: the orders are split into three tiers,
//     k < K1: T,   K1 <= k < K2: double-double (oracle/double_double.hpp),   k >= K2: double,
// with K1, K2 the first orders whose terms, times the tier's unit roundoff u and a growth
// allowance G = 2^kGuardBits for the rounding errors accumulated through the Cauchy sums, stay
// below tol |x| / 16:
//     max_n |x_{n,k}| h^k * u_tier * G <= tol * max(1, |x|) / 16    for every k in the tier.
// A product of a tier-1 coefficient reads the lower orders through their double-double copies.
// The split is predicted from the previous step (with 2^kPredictionSlackBits to spare, since h
// may grow) and checked after the step size is known; a step whose terms break the bound is
// recomputed with the split that bound gives, and in T alone if that fails too. The first step is
// computed in T. The inequality is a bound on what the cheaper tiers add to the local error, so
// the tolerance keeps its meaning; tests/oracle_tests.cpp compares mixed and all-T trajectories,
// with a control that gives the tiers precision they do not have.
#pragma once

#include "oracle/double_double.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace gm::oracle {

template <class T>
class Tape {
 public:
  enum class Op { Var, Const, Add, Sub, Neg, Scale, Mul };
  struct Node {
    Op op;
    int a = -1, b = -1;
    T c{};  // Const: the value; Scale: the factor
  };

  int push(Op op, int a = -1, int b = -1, const T& c = T(0)) {
    nodes_.push_back(Node{op, a, b, c});
    return static_cast<int>(nodes_.size()) - 1;
  }
  const std::vector<Node>& nodes() const { return nodes_; }

 private:
  std::vector<Node> nodes_;
};

// A value being recorded on a tape.
template <class T>
struct Recorder {
  Tape<T>* tape = nullptr;
  int id = -1;

  friend Recorder operator+(const Recorder& x, const Recorder& y) {
    return {x.tape, x.tape->push(Tape<T>::Op::Add, x.id, y.id)};
  }
  friend Recorder operator-(const Recorder& x, const Recorder& y) {
    return {x.tape, x.tape->push(Tape<T>::Op::Sub, x.id, y.id)};
  }
  friend Recorder operator*(const Recorder& x, const Recorder& y) {
    return {x.tape, x.tape->push(Tape<T>::Op::Mul, x.id, y.id)};
  }
  friend Recorder operator-(const Recorder& x) { return {x.tape, x.tape->push(Tape<T>::Op::Neg, x.id)}; }
  friend Recorder operator*(const Recorder& x, const T& c) {
    return {x.tape, x.tape->push(Tape<T>::Op::Scale, x.id, -1, c)};
  }
  friend Recorder operator*(const T& c, const Recorder& x) { return x * c; }
  Recorder& operator+=(const Recorder& y) { return *this = *this + y; }
  Recorder& operator-=(const Recorder& y) { return *this = *this - y; }
};

struct TaylorStats {
  long steps = 0;
  int order = 0;
  long mixed_steps = 0;  // steps whose higher orders were computed in double-double / double
  long recomputed = 0;   // steps computed again because the predicted split broke the bound
  int k1 = 0, k2 = 0;    // the last step's split: orders [k1, k2) in double-double, [k2, N] in double
};

template <class T>
T taylor_abs(const T& x) {
  return x < T(0) ? T(-x) : x;
}

template <class T, class Field>
class TaylorSolver {
 public:
  // `dim` state variables; `tolerance` is the local error target per step, relative to
  // max(1, |x|_inf); `order` 0 chooses N from the tolerance.
  TaylorSolver(const Field& field, int dim, const T& tolerance, int order = 0) : dim_(dim), tol_(tolerance) {
    if (dim < 1) throw std::invalid_argument("TaylorSolver: dimension must be positive");
    if (!(tolerance > T(0))) throw std::invalid_argument("TaylorSolver: tolerance must be positive");
    if (order <= 0) {
      using std::ceil;
      using std::log;
      const double lt = -std::log(to_d(tolerance));
      order = static_cast<int>(std::ceil(lt / 2)) + 1;
    }
    if (order < 2) order = 2;
    order_ = order;
    stats_.order = order;
    // Record the field.
    std::vector<Recorder<T>> x(dim), dx(dim);
    for (int i = 0; i < dim; ++i) x[i] = Recorder<T>{&tape_, tape_.push(Tape<T>::Op::Var)};
    field(x.data(), dx.data());
    for (int i = 0; i < dim; ++i) {
      if (dx[i].tape != &tape_) {
        // A component recorded as a plain constant expression (e.g. 0): make it a node.
        dx[i] = Recorder<T>{&tape_, tape_.push(Tape<T>::Op::Const, -1, -1, T(0))};
      }
      out_.push_back(dx[i].id);
    }
    const auto& nodes = tape_.nodes();
    coef_.assign(nodes.size(), std::vector<T>(order_ + 1, T(0)));
    k1_ = k2_ = next_k1_ = next_k2_ = order_ + 1;
    mixed_ = kTierDigits[1] > 0 || kTierDigits[2] > 0;
    if (mixed_) {
      dd_.assign(nodes.size(), std::vector<DoubleDouble>(order_ + 1));
      d_.assign(nodes.size(), std::vector<double>(order_ + 1, 0.0));
      shadow_.assign(nodes.size(), false);
      c_dd_.resize(nodes.size());
      c_d_.resize(nodes.size());
      for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (nodes[n].op == Tape<T>::Op::Mul) shadow_[nodes[n].a] = shadow_[nodes[n].b] = true;
        c_dd_[n] = to_dd(nodes[n].c);
        c_d_[n] = c_dd_[n].hi;
      }
    }
  }

  int order() const { return order_; }
  const TaylorStats& stats() const { return stats_; }

  // Optional limits (default: none). sample() throws std::runtime_error once it has taken
  // `max_steps` steps, or when |x|_inf exceeds `max_norm` (a solution escaping to infinity, as in
  // a finite-time blow-up, would otherwise take ever shorter steps without end).
  void set_limits(long max_steps, const T& max_norm) {
    max_steps_ = max_steps;
    max_norm_ = max_norm;
  }

  // Integrates from (t0, x0) and returns the state at each time of `times` (monotone in the
  // direction of integration, all on the same side of t0).
  std::vector<std::vector<T>> sample(const std::vector<T>& x0, const T& t0, const std::vector<T>& times) {
    check_state(x0);
    std::vector<std::vector<T>> out;
    out.reserve(times.size());
    std::vector<T> x = x0;
    T t = t0;
    std::size_t next = 0;
    while (next < times.size() && times[next] == t) out.push_back(x), ++next;
    if (next == times.size()) return out;
    const bool forward = times.back() > t0;
    for (std::size_t i = next; i < times.size(); ++i) {
      const bool ok = forward ? (times[i] > t0 && (i == next || times[i] >= times[i - 1]))
                              : (times[i] < t0 && (i == next || times[i] <= times[i - 1]));
      if (!ok) throw std::invalid_argument("TaylorSolver::sample: times must be monotone, away from t0");
    }
    while (next < times.size()) {
      T h = prepare_step(x);
      const T remaining = forward ? T(times.back() - t) : T(t - times.back());
      if (h >= remaining) h = remaining;
      const T signed_h = forward ? h : T(-h);
      const T t_new = t + signed_h;
      // Dense output for every sample inside (t, t_new].
      while (next < times.size() && (forward ? times[next] <= t_new : times[next] >= t_new)) {
        out.push_back(evaluate(T(times[next] - t)));
        ++next;
      }
      x = evaluate(signed_h);
      t = t_new;
      ++stats_.steps;
      if (max_steps_ > 0 && stats_.steps >= max_steps_ && next < times.size())
        throw std::runtime_error("TaylorSolver: " + std::to_string(max_steps_) + " steps taken before t = " +
                                 text(to_d(times.back())) + " (reached t = " + text(to_d(t)) + ")");
      if (max_norm_ > T(0))
        for (const auto& v : x)
          if (!(taylor_abs(v) <= max_norm_))
            throw std::runtime_error("TaylorSolver: the solution grows beyond " + text(to_d(max_norm_)) +
                                     " at t = " + text(to_d(t)) + " (it leaves every bound: a blow-up?)");
    }
    return out;
  }

  // The step the solver would take from state x (its first step from x): lets a caller estimate
  // how many steps an integration will need before starting it.
  T step_size_at(const std::vector<T>& x) {
    check_state(x);
    return prepare_step(x);
  }

  static constexpr int kGuardBits = 16;           // G = 2^16
  static constexpr int kPredictionSlackBits = 6;  // h may grow by up to 2^(6/k) per step

  // Mixed precision (see the top of this file) is on by default for a multiprecision T; off, every
  // order is computed in T. For tests: `guard_bits` is log2 of the growth allowance G (lowered, a
  // split with too little margin must be caught by comparing trajectories); `slack_bits` is the
  // prediction's margin (lowered, predictions fail and the recomputation is exercised).
  void set_mixed_precision(bool on, int guard_bits = kGuardBits, int slack_bits = kPredictionSlackBits) {
    mixed_ = on && (kTierDigits[1] > 0 || kTierDigits[2] > 0);
    guard_bits_ = guard_bits;
    slack_bits_ = slack_bits;
    k1_ = k2_ = next_k1_ = next_k2_ = order_ + 1;
  }

  // The state at time t1 from (t0, x0).
  std::vector<T> flow(const std::vector<T>& x0, const T& t0, const T& t1) {
    if (t1 == t0) return x0;
    return sample(x0, t0, std::vector<T>{t1}).front();
  }

 private:
  static std::string text(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }

  static double to_d(const T& x) {
    if constexpr (std::is_same_v<T, double>)
      return x;
    else
      return x.template convert_to<double>();
  }

  void check_state(const std::vector<T>& x) const {
    if (static_cast<int>(x.size()) != dim_)
      throw std::invalid_argument("TaylorSolver: state has " + std::to_string(x.size()) + " components, field has " +
                                  std::to_string(dim_));
    for (const auto& v : x) {
      using boost::multiprecision::isfinite;
      using std::isfinite;
      if (!isfinite(v)) throw std::invalid_argument("TaylorSolver: non-finite initial state");
    }
  }

  // Significant bits of the three tiers' arithmetic (0: a tier not used because T is not more
  // precise than it): T itself, double-double, double.
  static constexpr int kTdigits = std::numeric_limits<T>::digits;
  static constexpr int kTierDigits[3] = {kTdigits, kTdigits > 104 + 8 ? 104 : 0, kTdigits > 53 + 8 ? 53 : 0};
  static constexpr int kMarginBits = 4;  // the bound is tol |x| / 16

  static DoubleDouble to_dd(const T& x) {
    const double hi = to_d(x);
    return {hi, to_d(T(x - T(hi)))};
  }
  static T from_dd(const DoubleDouble& x) { return T(x.hi) + T(x.lo); }

  int tier(int k) const { return k < k1_ ? 0 : (k < k2_ ? 1 : 2); }

  // Coefficients, then the step size, with the split checked against the bound for that step
  // size (recomputed with the split it allows, then in T alone, if it does not hold); finally the
  // split for the next step is predicted.
  T prepare_step(const std::vector<T>& x) {
    k1_ = next_k1_;
    k2_ = next_k2_;
    compute_coefficients(x);
    T h = step_size(x);
    if (mixed_ && k1_ <= order_) {
      if (!split_holds(x, h)) {
        ++stats_.recomputed;
        std::tie(k1_, k2_) = choose_split(x, h, 0);
        compute_coefficients(x);
        h = step_size(x);
        if (!split_holds(x, h)) {
          k1_ = k2_ = order_ + 1;
          compute_coefficients(x);
          h = step_size(x);
        }
      }
      if (k1_ <= order_) ++stats_.mixed_steps;
      stats_.k1 = k1_, stats_.k2 = k2_;
    }
    if (mixed_) std::tie(next_k1_, next_k2_) = choose_split(x, h, slack_bits_);
    return h;
  }

  // The profile of a step: for each order k, binary exponents c_k with max_n |x_{n,k}| < 2^c_k and
  // e_k = c_k + (exponent of h^k), so that max_n |x_{n,k}| h^k < 2^e_k; kNone for an order that is
  // zero, kHuge for one that is not finite where it was computed. Exponents are taken from T itself
  // for orders computed in T, so no range is lost, and every step is exact (frexp), so the split
  // does not depend on a libm.
  static constexpr int kNone = std::numeric_limits<int>::min();
  static constexpr int kHuge = std::numeric_limits<int>::max() / 2;
  struct Profile {
    std::vector<int> term, coef;
  };
  static int exponent_of(const T& v) {
    using std::frexp;
    int e = 0;
    frexp(v, &e);
    return e;
  }
  int coefficient_exponent(std::size_t n, int k) const {
    switch (tier(k)) {
      case 0:
        return coef_[n][k] == T(0) ? kNone : exponent_of(coef_[n][k]);
      case 1:
        return std::isfinite(dd_[n][k].hi) ? (dd_[n][k].hi == 0 ? kNone : std::ilogb(dd_[n][k].hi) + 1) : kHuge;
      default:
        return std::isfinite(d_[n][k]) ? (d_[n][k] == 0 ? kNone : std::ilogb(d_[n][k]) + 1) : kHuge;
    }
  }
  Profile profile(const T& h) const {
    using Op = typename Tape<T>::Op;
    using std::frexp;
    const auto& nodes = tape_.nodes();
    Profile p{std::vector<int>(order_ + 1, kNone), std::vector<int>(order_ + 1, kNone)};
    int he = 0;
    const double hm = to_d(T(frexp(h, &he)));  // h = hm * 2^he, hm in [0.5, 1)
    double pm = 1;                             // h^k = pm * 2^pe, pm in [0.5, 1]
    int pe = 0;
    for (int k = 0; k <= order_; ++k) {
      if (k > 0) {
        int de = 0;
        pm = std::frexp(pm * hm, &de);
        pe += he + de;
      }
      int c = kNone;
      for (std::size_t n = 0; n < nodes.size(); ++n)
        if (nodes[n].op == Op::Var) c = std::max(c, coefficient_exponent(n, k));
      p.coef[k] = c;
      p.term[k] = c == kNone || c == kHuge ? c : c + pe;
    }
    return p;
  }
  int bound_exponent(const std::vector<T>& x) const {
    T size(1);
    for (const auto& v : x)
      if (taylor_abs(v) > size) size = taylor_abs(v);
    return exponent_of(T(tol_ * size)) - 1 - kMarginBits;
  }
  // Order k may be computed in tier t: its term is small enough for t's precision, and (below T)
  // its coefficients are well inside double's exponent range, so that neither they nor the low
  // parts of double-double numbers overflow or underflow.
  bool term_fits(const Profile& p, int k, int t, int b, int slack) const {
    if (t == 0 || p.term[k] == kNone) return true;
    if (p.term[k] == kHuge || p.coef[k] > 900 || p.coef[k] < -900) return false;
    return p.term[k] - kTierDigits[t] + guard_bits_ + slack <= b;
  }

  bool split_holds(const std::vector<T>& x, const T& h) const {
    const Profile p = profile(h);
    const int b = bound_exponent(x);
    for (int k = k1_; k <= order_; ++k)
      if (!term_fits(p, k, tier(k), b, 0)) return false;
    return true;
  }

  // The split (K1, K2) for step size h: K2 (K1) is the lowest order from which every term fits the
  // double (double-double) tier; order 0, the state itself, always stays in T.
  std::pair<int, int> choose_split(const std::vector<T>& x, const T& h, int slack) const {
    const Profile p = profile(h);
    const int b = bound_exponent(x);
    auto lowest = [&](int t) {
      if (kTierDigits[t] == 0) return order_ + 1;
      int k = order_ + 1;
      while (k - 1 >= 1 && term_fits(p, k - 1, t, b, slack)) --k;
      return k;
    };
    const int k2 = lowest(2);
    return {std::min(lowest(1), k2), k2};
  }

  // Coefficient k of node n as a double or a T, read from the tier it was computed in.
  double value_d(std::size_t n, int k) const {
    switch (tier(k)) {
      case 0:
        return to_d(coef_[n][k]);
      case 1:
        return dd_[n][k].hi;
      default:
        return d_[n][k];
    }
  }
  T value_T(std::size_t n, int k) const {
    switch (tier(k)) {
      case 0:
        return coef_[n][k];
      case 1:
        return from_dd(dd_[n][k]);
      default:
        return T(d_[n][k]);
    }
  }

  void compute_coefficients(const std::vector<T>& x) {
    using Op = typename Tape<T>::Op;
    const auto& nodes = tape_.nodes();
    int var = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) coef_[n][0] = x[var++];
    for (int k = 0; k <= order_; ++k) {
      const int t = tier(k);
      if (t == 0)
        coefficients_in_T(k);
      else if (t == 1)
        coefficients_in_dd(k);
      else
        coefficients_in_d(k);
      // Copies for the cheaper tiers' products, which read lower orders of their operands.
      if (k1_ <= order_ && k < k2_)
        for (std::size_t n = 0; n < nodes.size(); ++n)
          if (shadow_[n]) {
            if (t == 0) dd_[n][k] = to_dd(coef_[n][k]);
            d_[n][k] = dd_[n][k].hi;
          }
    }
  }

  void coefficients_in_T(int k) {
    using Op = typename Tape<T>::Op;
    const auto& nodes = tape_.nodes();
    if (k > 0) {
      int v = 0;
      const T inv_k = T(1) / T(k);
      for (std::size_t n = 0; n < nodes.size(); ++n)
        if (nodes[n].op == Op::Var) coef_[n][k] = coef_[out_[v++]][k - 1] * inv_k;
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const auto& nd = nodes[n];
      auto& c = coef_[n];
      switch (nd.op) {
        case Op::Var:
          break;
        case Op::Const:
          c[k] = k == 0 ? nd.c : T(0);
          break;
        case Op::Add:
          c[k] = coef_[nd.a][k] + coef_[nd.b][k];
          break;
        case Op::Sub:
          c[k] = coef_[nd.a][k] - coef_[nd.b][k];
          break;
        case Op::Neg:
          c[k] = -coef_[nd.a][k];
          break;
        case Op::Scale:
          c[k] = coef_[nd.a][k] * nd.c;
          break;
        case Op::Mul: {
          const auto& a = coef_[nd.a];
          const auto& b = coef_[nd.b];
          T s = a[0] * b[k];
          for (int j = 1; j <= k; ++j) s += a[j] * b[k - j];
          c[k] = s;
          break;
        }
      }
    }
  }

  // Order k >= 1 in a cheaper tier's arithmetic S (DoubleDouble or double), into `c` (dd_ or d_),
  // with the Scale factors `factors` in S. A product reads the lower orders of its operands through
  // their copies; `lower(o, k - 1)` gives order k - 1 of out node o in S.
  template <class S, class Lower>
  void coefficients_in(int k, std::vector<std::vector<S>>& c, const std::vector<S>& factors, Lower lower) {
    using Op = typename Tape<T>::Op;
    const auto& nodes = tape_.nodes();
    int v = 0;
    const double kk = k;
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) c[n][k] = lower(out_[v++], k - 1) / kk;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const auto& nd = nodes[n];
      switch (nd.op) {
        case Op::Var:
          break;
        case Op::Const:
          c[n][k] = S{};
          break;
        case Op::Add:
          c[n][k] = c[nd.a][k] + c[nd.b][k];
          break;
        case Op::Sub:
          c[n][k] = c[nd.a][k] - c[nd.b][k];
          break;
        case Op::Neg:
          c[n][k] = -c[nd.a][k];
          break;
        case Op::Scale:
          c[n][k] = c[nd.a][k] * factors[n];
          break;
        case Op::Mul: {
          const auto& a = c[nd.a];
          const auto& b = c[nd.b];
          S sum = a[0] * b[k];
          for (int j = 1; j <= k; ++j) sum += a[j] * b[k - j];
          c[n][k] = sum;
          break;
        }
      }
    }
  }
  void coefficients_in_dd(int k) {
    coefficients_in(k, dd_, c_dd_, [&](int o, int j) { return j < k1_ ? to_dd(coef_[o][j]) : dd_[o][j]; });
  }
  void coefficients_in_d(int k) {
    coefficients_in(k, d_, c_d_, [&](int o, int j) { return value_d(o, j); });
  }

  T norm_of_order(int m) const {
    using Op = typename Tape<T>::Op;
    T best(0);
    const auto& nodes = tape_.nodes();
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) {
        const T a = taylor_abs(value_T(n, m));
        if (a > best) best = a;
      }
    return best;
  }

  // ln |v| for v != 0, in double: from T's exponent and a double mantissa, so that no range is lost.
  static double log_abs(const T& v) {
    if constexpr (std::is_same_v<T, double>) {
      return std::log(std::fabs(v));
    } else {
      int e = 0;
      const T m = frexp(v, &e);
      return std::log(std::fabs(to_d(m))) + e * 0.69314718055994530942;
    }
  }

  // The Jorba-Zou step. Only its size matters (the error is that of the first neglected term
  // whatever h is, within a factor of about 2^(1/N)), so the root is taken in double on logarithms:
  // a 50-digit pow cost as much as a fifth of the step.
  T step_size(const std::vector<T>& x) const {
    T size(1);
    for (const auto& v : x)
      if (taylor_abs(v) > size) size = taylor_abs(v);
    const double log_target = log_abs(T(tol_ * size));
    double log_h = std::numeric_limits<double>::infinity();
    for (int m : {order_ - 1, order_}) {
      const T nm = norm_of_order(m);
      if (nm > T(0)) log_h = std::min(log_h, (log_target - log_abs(nm)) / m);
    }
    if (log_h == std::numeric_limits<double>::infinity())
      return T(1e6);  // a polynomial solution of degree < N-1: any step is exact
    using std::exp;
    return log_h > -700 ? T(std::exp(std::min(log_h, 700.0))) : T(exp(T(log_h)));
  }

  // Horner's rule from the top order down, each order in its tier: the partial sum at order k,
  // sum_{i >= k} x_i tau^(i-k), is of the size of x_k and needs the digits x_k has.
  std::vector<T> evaluate(const T& tau) const {
    using Op = typename Tape<T>::Op;
    std::vector<T> y;
    y.reserve(dim_);
    const double tau_d = mixed_ ? to_d(tau) : 0.0;
    const DoubleDouble tau_dd = mixed_ ? to_dd(tau) : DoubleDouble{};
    const auto& nodes = tape_.nodes();
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) {
        int k = order_;
        double sd = 0;
        for (; k >= k2_; --k) sd = sd * tau_d + d_[n][k];
        DoubleDouble sdd{sd, 0};
        for (; k >= k1_; --k) sdd = sdd * tau_dd + dd_[n][k];
        T s = k1_ <= order_ ? from_dd(sdd) : T(0);
        const auto& c = coef_[n];
        for (; k >= 0; --k) s = s * tau + c[k];
        y.push_back(s);
      }
    return y;
  }

  int dim_;
  T tol_;
  long max_steps_ = 0;
  T max_norm_ = T(0);
  int order_ = 0;
  Tape<T> tape_;
  std::vector<int> out_;
  std::vector<std::vector<T>> coef_;
  // Mixed precision: orders [k1_, k2_) in double-double, [k2_, N] in double; k1_ = k2_ = N + 1
  // when every order is in T.
  bool mixed_ = false;
  int guard_bits_ = kGuardBits;
  int slack_bits_ = kPredictionSlackBits;
  int k1_ = 0, k2_ = 0;
  int next_k1_ = 0, next_k2_ = 0;  // the split predicted for the next step
  std::vector<std::vector<DoubleDouble>> dd_;
  std::vector<std::vector<double>> d_;
  std::vector<bool> shadow_;
  std::vector<DoubleDouble> c_dd_;
  std::vector<double> c_d_;
  TaylorStats stats_;
};

}  // namespace gm::oracle
