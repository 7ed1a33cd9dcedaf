// Accurate flows of a subject's vector fields (slots called as black boxes), for the dynamic and
// variational properties: Gragg-Bulirsch-Stoer extrapolation.
//
// The Taylor oracle (oracle/taylor.hpp) needs the field as a polynomial template it can record;
// a subject's slot is an opaque std::function over one scalar, so its flow is computed here by
// Richardson extrapolation of Gragg's modified midpoint rule (Hairer, Norsett & Wanner, Solving
// ODEs I, II.9), which needs nothing but evaluations of the field:
//   - one step of size H runs the modified midpoint rule with n_r substeps, r = 0, 1, 2, ...
//     (Bulirsch's sequence 2, 4, 6, 8, 12, 16, 24, ...), whose results have an asymptotic
//     expansion in even powers of H / n_r;
//   - the Aitken-Neville tableau extrapolates them to H / n -> 0; row r has order 2(r + 1);
//   - the step is accepted at the first row r >= 2 (near the planned row) where two successive
//     extrapolants differ by at most `tol * max(1, |x|_inf)`; otherwise it is redone with a
//     smaller H;
//   - the next step and row are chosen to minimise field evaluations per unit time (the order
//     and step control of ODEX, simplified).
// The difference of the last two extrapolants overestimates the error of the accepted (better)
// one, so the local error per step is below tol. Bulirsch's sequence keeps the extrapolation's
// amplification of round-off (its Lebesgue constant) below 9.3 at any row, where the harmonic
// sequence 2, 4, 6, 8, 10, ... would reach 6e4 at 16 rows. The global error is then about
// (number of steps) x tol, amplified by the flow's conditioning (linear growth in t for the
// integrable rigid body). With the default tol = 16 eps(T) the flow of Euler's equations over
// t = 20 meets the exact elliptic solution to ~100 eps in double and in 50 digits
// (tests/elliptic_tests.cpp), at ~3000 field evaluations per unit time in 50 digits.
//
// Sample times are reached exactly by shortening a step (the planned step is kept for the next
// one), so dense output costs one short step per sample.
#pragma once

#include "core/linalg.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gm::flow {

struct GbsStats {
  long steps = 0;
  long rejected = 0;
  long evaluations = 0;
};

// Field: VecX<T>(const T& t, const VecX<T>& x).
template <class T>
using Field = std::function<VecX<T>(const T&, const VecX<T>&)>;

template <class T>
class Gbs {
 public:
  explicit Gbs(Field<T> f, T tol = T(16) * eps<T>(), int max_rows = default_rows())
      : f_(std::move(f)), tol_(tol), max_rows_(max_rows) {
    if (!(tol_ > T(0))) throw std::invalid_argument("Gbs: tolerance must be positive");
    if (max_rows_ < 3) throw std::invalid_argument("Gbs: at least 3 extrapolation rows");
  }

  // Rows of the tableau: order 2 * rows. More digits want a higher order.
  static int default_rows() {
    const double digits = -std::log10(eps_double<T>());
    return digits < 20 ? 10 : digits < 55 ? 14 : 16;
  }

  const GbsStats& stats() const { return stats_; }
  void set_initial_step(const T& h) { h_ = h; }

  // States at each of `times` (monotone, all on one side of t0) from x(t0) = x0.
  std::vector<VecX<T>> sample(const VecX<T>& x0, const T& t0, const std::vector<T>& times) {
    std::vector<VecX<T>> out;
    out.reserve(times.size());
    if (times.empty()) return out;
    const bool forward = times.back() >= t0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      const T prev = i == 0 ? t0 : times[i - 1];
      if (forward ? times[i] < prev : times[i] > prev)
        throw std::invalid_argument("Gbs::sample: times must be monotone and on one side of t0");
    }
    for (Eigen::Index i = 0; i < x0.size(); ++i)
      if (!is_finite(x0(i))) throw std::invalid_argument("Gbs::sample: non-finite initial state");
    VecX<T> x = x0;
    T t = t0;
    const T dir = forward ? T(1) : T(-1);
    for (const T& target : times) {
      while (t != target) {
        const T remaining = target - t;
        const bool last = abs_value(remaining) <= h_;
        const T H = last ? remaining : T(h_ * dir);
        Attempt a = step(t, x, H, last);
        if (!a.accepted) {
          ++stats_.rejected;
          h_ = reduced_step(abs_value(H), a);
          if (h_ == T(0) || h_ <= abs_value(t) * eps<T>() * T(16))
            throw std::runtime_error("Gbs: step size underflow (the field is not smooth here, or returned NaN)");
          continue;
        }
        ++stats_.steps;
        if (stats_.steps > max_steps_)
          throw std::runtime_error("Gbs: more than " + std::to_string(max_steps_) +
                                   " steps (the solution blows up, or the field is not smooth)");
        x = std::move(a.x);
        t = last ? target : T(t + H);
        if (!last) plan_next(abs_value(H), a);
      }
      out.push_back(x);
    }
    return out;
  }

  VecX<T> flow(const VecX<T>& x0, const T& t0, const T& t1) { return sample(x0, t0, {t1}).front(); }

 private:
  struct Attempt {
    bool accepted = false;
    int row = 0;         // row of the accepted extrapolant
    std::vector<T> err;  // err[r] = |T_rr - T_r,r-1|, r >= 1
    VecX<T> x;
    T tol{0};
  };

  // One extrapolated step of size H. Rows are computed up to target_row_ + 1; the step is accepted
  // at the first row r >= max(2, target_row_ - 1) whose error estimate meets the tolerance (from
  // row 2 on for a step shortened to reach a sample time, which usually converges early).
  Attempt step(const T& t, const VecX<T>& x, const T& H, bool shortened) {
    Attempt a;
    const VecX<T> f0 = eval(t, x);
    T size(1);
    for (Eigen::Index i = 0; i < x.size(); ++i) size = std::max(size, abs_value(x(i)));
    const T target = tol_ * size;
    a.tol = target;
    const int last_row = std::min(max_rows_ - 1, target_row_ + 1);
    const int first_check = shortened ? 2 : std::max(2, target_row_ - 1);
    std::vector<std::vector<VecX<T>>> tab;
    a.err.assign(last_row + 1, T(0));
    for (int j = 0; j <= last_row; ++j) {
      const int n = substeps(j);
      const T h = H / T(n);
      VecX<T> z0 = x;
      VecX<T> z1 = x + h * f0;
      for (int m = 1; m < n; ++m) {
        VecX<T> z2 = z0 + T(2) * h * eval(t + T(m) * h, z1);
        z0 = std::move(z1);
        z1 = std::move(z2);
      }
      // Gragg's smoothing step.
      std::vector<VecX<T>> row;
      row.reserve(j + 1);
      row.push_back((z1 + z0 + h * eval(t + H, z1)) / T(2));
      for (int r = 1; r <= j; ++r) {
        const T ratio = T(n) / T(substeps(j - r));
        row.push_back(row[r - 1] + (row[r - 1] - tab[j - 1][r - 1]) / (ratio * ratio - T(1)));
      }
      tab.push_back(std::move(row));
      if (!all_finite(tab[j][j])) {
        a.err.resize(j);
        return a;
      }
      if (j >= 1) a.err[j] = max_abs((tab[j][j] - tab[j][j - 1]).eval());
      if (j >= first_check && a.err[j] <= target) {
        a.accepted = true;
        a.row = j;
        a.x = tab[j][j];
        a.err.resize(j + 1);
        return a;
      }
    }
    return a;
  }

  // Step and row for the next step, from the work per unit step of the rows just computed
  // (the order and step selection of Hairer & Wanner's ODEX, simplified).
  void plan_next(const T& H, const Attempt& a) {
    using std::pow;
    auto optimal_step = [&](int r) {
      if (a.err[r] == T(0)) return T(H * T(4));
      const T factor = pow(T(T(65) / T(100) * a.tol / a.err[r]), T(1) / T(2 * r + 1)) * T(94) / T(100);
      return T(H * std::min(T(2), std::max(T(1) / T(4), factor)));
    };
    const int j = a.row;
    const T hj = optimal_step(j);
    const T wj = T(work(j)) / hj;
    int row = j;
    T h = hj;
    if (j - 1 >= 2) {
      const T hm = optimal_step(j - 1);
      const T wm = T(work(j - 1)) / hm;
      if (wm < wj) {
        row = j - 1;
        h = hm;
      } else if (j + 1 < max_rows_ && wj < T(9) / T(10) * wm) {
        row = j + 1;
        h = hj * T(work(j + 1)) / T(work(j));
      }
    }
    target_row_ = row;
    h_ = std::min(h, T(H * T(2)));
  }

  // After a rejection: the step the last row's error estimate asks for, at most half of H.
  T reduced_step(const T& H, const Attempt& a) const {
    using std::pow;
    const int r = static_cast<int>(a.err.size()) - 1;
    if (r < 1 || !is_finite(a.err[r]) || a.err[r] == T(0) || a.tol == T(0)) return H / T(2);
    const T factor = pow(T(T(65) / T(100) * a.tol / a.err[r]), T(1) / T(2 * r + 1)) * T(94) / T(100);
    return H * std::max(T(1) / T(8), std::min(T(1) / T(2), factor));
  }

  // Field evaluations up to and including row r.
  static int work(int r) {
    int w = 1;
    for (int j = 0; j <= r; ++j) w += substeps(j) + 1;
    return w;
  }

  // Bulirsch's sequence 2, 4, 6, 8, 12, 16, 24, 32, ...: its extrapolation weights stay bounded
  // (Lebesgue constant < 9.3 for any number of rows), so the tableau does not amplify round-off;
  // the harmonic sequence 2, 4, 6, 8, 10, ... is cheaper per row but amplifies it by 6e4 at 16 rows.
  static int substeps(int j) {
    if (j < 3) return 2 * (j + 1);
    return (j % 2 == 1) ? 8 << ((j - 3) / 2) : 12 << ((j - 4) / 2);
  }

  VecX<T> eval(const T& t, const VecX<T>& x) {
    ++stats_.evaluations;
    return f_(t, x);
  }

  Field<T> f_;
  T tol_;
  int max_rows_;
  long max_steps_ = 20000;
  T h_ = T(1) / T(8);
  int target_row_ = 5;
  GbsStats stats_;
};

}  // namespace gm::flow
