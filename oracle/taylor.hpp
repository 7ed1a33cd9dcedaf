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
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
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

  friend Recorder operator+(const Recorder& x, const Recorder& y) { return {x.tape, x.tape->push(Tape<T>::Op::Add, x.id, y.id)}; }
  friend Recorder operator-(const Recorder& x, const Recorder& y) { return {x.tape, x.tape->push(Tape<T>::Op::Sub, x.id, y.id)}; }
  friend Recorder operator*(const Recorder& x, const Recorder& y) { return {x.tape, x.tape->push(Tape<T>::Op::Mul, x.id, y.id)}; }
  friend Recorder operator-(const Recorder& x) { return {x.tape, x.tape->push(Tape<T>::Op::Neg, x.id)}; }
  friend Recorder operator*(const Recorder& x, const T& c) { return {x.tape, x.tape->push(Tape<T>::Op::Scale, x.id, -1, c)}; }
  friend Recorder operator*(const T& c, const Recorder& x) { return x * c; }
  Recorder& operator+=(const Recorder& y) { return *this = *this + y; }
  Recorder& operator-=(const Recorder& y) { return *this = *this - y; }
};

struct TaylorStats {
  long steps = 0;
  int order = 0;
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
  TaylorSolver(const Field& field, int dim, const T& tolerance, int order = 0)
      : dim_(dim), tol_(tolerance) {
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
    coef_.assign(tape_.nodes().size(), std::vector<T>(order_ + 1, T(0)));
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
      compute_coefficients(x);
      T h = step_size(x);
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
            throw std::runtime_error("TaylorSolver: the solution grows beyond " + text(to_d(max_norm_)) + " at t = " +
                                     text(to_d(t)) + " (it leaves every bound: a blow-up?)");
    }
    return out;
  }

  // The step the solver would take from state x (its first step from x): lets a caller estimate
  // how many steps an integration will need before starting it.
  T step_size_at(const std::vector<T>& x) {
    check_state(x);
    compute_coefficients(x);
    return step_size(x);
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
      using std::isfinite;
      using boost::multiprecision::isfinite;
      if (!isfinite(v)) throw std::invalid_argument("TaylorSolver: non-finite initial state");
    }
  }

  void compute_coefficients(const std::vector<T>& x) {
    using Op = typename Tape<T>::Op;
    const auto& nodes = tape_.nodes();
    int var = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) coef_[n][0] = x[var++];
    for (int k = 0; k <= order_; ++k) {
      if (k > 0) {
        int v = 0;
        const T inv_k = T(1) / T(k);
        for (std::size_t n = 0; n < nodes.size(); ++n)
          if (nodes[n].op == Op::Var) {
            coef_[n][k] = coef_[out_[v]][k - 1] * inv_k;
            ++v;
          }
      }
      for (std::size_t n = 0; n < nodes.size(); ++n) {
        const auto& nd = nodes[n];
        auto& c = coef_[n];
        switch (nd.op) {
          case Op::Var: break;
          case Op::Const: c[k] = k == 0 ? nd.c : T(0); break;
          case Op::Add: c[k] = coef_[nd.a][k] + coef_[nd.b][k]; break;
          case Op::Sub: c[k] = coef_[nd.a][k] - coef_[nd.b][k]; break;
          case Op::Neg: c[k] = -coef_[nd.a][k]; break;
          case Op::Scale: c[k] = coef_[nd.a][k] * nd.c; break;
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
  }

  T norm_of_order(int m) const {
    using Op = typename Tape<T>::Op;
    T best(0);
    const auto& nodes = tape_.nodes();
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) {
        const T a = taylor_abs(coef_[n][m]);
        if (a > best) best = a;
      }
    return best;
  }

  T step_size(const std::vector<T>& x) const {
    using std::pow;
    T size(1);
    for (const auto& v : x)
      if (taylor_abs(v) > size) size = taylor_abs(v);
    const T target = tol_ * size;
    T h = std::numeric_limits<T>::max();
    for (int m : {order_ - 1, order_}) {
      const T nm = norm_of_order(m);
      if (nm > T(0)) {
        const T hm = pow(T(target / nm), T(1) / T(m));
        if (hm < h) h = hm;
      }
    }
    if (h == std::numeric_limits<T>::max()) h = T(1e6);  // a polynomial solution of degree < N-1: any step is exact
    return h;
  }

  std::vector<T> evaluate(const T& tau) const {
    using Op = typename Tape<T>::Op;
    std::vector<T> y;
    y.reserve(dim_);
    const auto& nodes = tape_.nodes();
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (nodes[n].op == Op::Var) {
        const auto& c = coef_[n];
        T s = c[order_];
        for (int k = order_ - 1; k >= 0; --k) s = s * tau + c[k];
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
  TaylorStats stats_;
};

}  // namespace gm::oracle
