// The golden trajectories' second integrator, and the integrator of the regression tests:
// Gragg-Bulirsch-Stoer extrapolation of the explicit midpoint rule, for any vector field given
// as a black box f(x) -> dx/dt and any floating scalar T (double, Real50, Real70).
//
// Independent of the Taylor oracle (oracle/taylor.hpp) by construction: it needs nothing but
// evaluations of f, so it runs equally on a field written out in golden/fields_geometric.hpp and on
// the slots of any subject (the reference implementation, a student's).
//
// One step of size H from x (Hairer, Norsett & Wanner, Solving ODEs I, section II.9):
//   for j = 1..K, with n_j = 2j (the harmonic sequence), the midpoint rule with n_j substeps
//     z_0 = x, z_1 = z_0 + h f(z_0), z_{m+1} = z_{m-1} + 2 h f(z_m), h = H / n_j,   T_{j,1} = z_{n_j};
//   (Gragg: T_{j,1} has an asymptotic expansion in even powers of h), then Aitken-Neville
//     T_{j,k} = T_{j,k-1} + (T_{j,k-1} - T_{j-1,k-1}) / ((n_j / n_{j-k+1})^2 - 1),
//   and T_{K,K} (order 2K) is accepted when err = |T_{K,K} - T_{K,K-1}|_inf / (tol max(1, |x|_inf)) <= 1.
// err estimates the error of the order-(2K-2) value, so the accepted one is more accurate than
// the tolerance says; the step size follows H_new = H * 0.9 * err^(-1/(2K-1)), clamped to [1/5, 4] H.
// Sample times are hit by shortening the step that would pass them (no dense output), so every
// sample is an end point of a step.
// Cost per step: K (K + 1) evaluations of f.
#pragma once

#include <boost/multiprecision/number.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace gm::golden {

struct ExtrapolationStats {
  long steps = 0;        // accepted steps
  long rejected = 0;     // rejected steps
  long evaluations = 0;  // evaluations of f
};

template <class T>
struct ExtrapolationSettings {
  int columns = 12;          // K: the accepted value has order 2K
  T tolerance = T(0);        // local error target per step, relative to max(1, |x|_inf)
  T initial_step = T(0);     // 0: chosen from the field at the initial point
  long max_steps = 1000000;  // a hard stop (accepted + rejected) against runaway step control
  T max_norm = T(0);         // > 0: stop when |x|_inf exceeds it (a solution escaping to infinity)
};

// Field: callable as f(const std::vector<T>& x, std::vector<T>& dxdt).
template <class T, class Field>
class ExtrapolationSolver {
 public:
  ExtrapolationSolver(Field field, int dim, ExtrapolationSettings<T> settings)
      : f_(std::move(field)), dim_(dim), s_(std::move(settings)) {
    if (dim < 1) throw std::invalid_argument("ExtrapolationSolver: dimension must be positive");
    if (s_.columns < 2 || s_.columns > 40)
      throw std::invalid_argument("ExtrapolationSolver: columns must be in [2, 40]");
    if (!(s_.tolerance > T(0))) throw std::invalid_argument("ExtrapolationSolver: tolerance must be positive");
    const int K = s_.columns;
    coeff_.resize(K);
    for (int j = 0; j < K; ++j) {
      coeff_[j].resize(j + 1);
      for (int k = 1; k <= j; ++k) {
        // n_j / n_{j-k} with n_j = 2 (j + 1)
        const T r = T(j + 1) / T(j + 1 - k);
        coeff_[j][k] = T(1) / (r * r - T(1));
      }
    }
  }

  const ExtrapolationStats& stats() const { return stats_; }
  const ExtrapolationSettings<T>& settings() const { return s_; }

  // The state at each of `times` (t0 <= times[0] <= times[1] <= ...), starting from x(t0) = x0.
  std::vector<std::vector<T>> sample(const std::vector<T>& x0, const T& t0, const std::vector<T>& times) {
    if (static_cast<int>(x0.size()) != dim_)
      throw std::invalid_argument("ExtrapolationSolver: state has " + std::to_string(x0.size()) +
                                  " components, the field has " + std::to_string(dim_));
    for (const auto& v : x0)
      if (!finite(v)) throw std::invalid_argument("ExtrapolationSolver: non-finite initial state");
    for (std::size_t i = 0; i < times.size(); ++i)
      if (times[i] < (i == 0 ? t0 : times[i - 1]))
        throw std::invalid_argument("ExtrapolationSolver: sample times must be increasing, from t0 on");
    std::vector<std::vector<T>> out;
    out.reserve(times.size());
    std::vector<T> x = x0, x_new(dim_);
    T t = t0;
    T h = s_.initial_step > T(0) ? s_.initial_step : initial_step(x);
    for (const T& target : times) {
      while (t < target) {
        if (stats_.steps + stats_.rejected >= s_.max_steps)
          throw std::runtime_error("ExtrapolationSolver: more than " + std::to_string(s_.max_steps) +
                                   " steps; the tolerance cannot be met");
        T step = h;
        bool last = false;
        if (t + step >= target) {
          step = target - t;
          last = true;
        }
        const T err = try_step(x, step, x_new);
        if (!finite(err))
          throw std::runtime_error("ExtrapolationSolver: the solution is not finite at t = " + to_text(t));
        if (err <= T(1)) {
          x.swap(x_new);
          t = last ? target : T(t + step);
          ++stats_.steps;
          if (s_.max_norm > T(0) && !(norm_inf(x) <= s_.max_norm))
            throw std::runtime_error("ExtrapolationSolver: the solution grows beyond " + to_text(s_.max_norm) +
                                     " at t = " + to_text(t) + " (it leaves every bound: a blow-up?)");
        } else {
          ++stats_.rejected;
        }
        // Step-size control; a step shortened to hit a sample does not shrink the next one.
        T factor = err > T(0) ? T(T(0.9) * pow_real(err, T(-1) / T(2 * s_.columns - 1))) : T(4);
        if (factor > T(4)) factor = T(4);
        if (factor < T(0.2)) factor = T(0.2);
        if (err > T(1) || !last) h = step * factor;
        if (!(h > T(0))) throw std::runtime_error("ExtrapolationSolver: step size underflow");
      }
      out.push_back(x);
    }
    return out;
  }

 private:
  static bool finite(const T& v) {
    using boost::multiprecision::isfinite;
    using std::isfinite;
    return isfinite(v);
  }
  static T abs_real(const T& v) { return v < T(0) ? T(-v) : v; }
  static T pow_real(const T& a, const T& b) {
    using boost::multiprecision::pow;
    using std::pow;
    return pow(a, b);
  }
  static std::string to_text(const T& v) {
    if constexpr (std::is_same_v<T, double>)
      return std::to_string(v);
    else
      return v.str(12);
  }

  T norm_inf(const std::vector<T>& v) const {
    T m(0);
    for (const auto& a : v)
      if (abs_real(a) > m) m = abs_real(a);
    return m;
  }

  T initial_step(const std::vector<T>& x) {
    std::vector<T> dx(dim_);
    f_(x, dx);
    ++stats_.evaluations;
    const T nx = norm_inf(x), nd = norm_inf(dx);
    T h = nd > T(0) ? T(T(0.25) * (nx > T(1) ? nx : T(1)) / nd) : T(1);
    if (h > T(1)) h = T(1);
    return h;
  }

  // One step of size H from x; writes T_{K,K} to out and returns the scaled error estimate.
  T try_step(const std::vector<T>& x, const T& H, std::vector<T>& out) {
    const int K = s_.columns;
    table_.resize(K, std::vector<T>(dim_));
    f0_.resize(dim_);
    zp_.resize(dim_);
    zc_.resize(dim_);
    fz_.resize(dim_);
    f_(x, f0_);
    ++stats_.evaluations;
    for (int j = 0; j < K; ++j) {
      const int n = 2 * (j + 1);
      const T hs = H / T(n);
      const T two_hs = hs * T(2);
      for (int i = 0; i < dim_; ++i) {
        zp_[i] = x[i];
        zc_[i] = x[i] + hs * f0_[i];
      }
      for (int m = 1; m < n; ++m) {
        f_(zc_, fz_);
        ++stats_.evaluations;
        for (int i = 0; i < dim_; ++i) {
          T next = zp_[i] + two_hs * fz_[i];
          zp_[i] = zc_[i];
          zc_[i] = next;
        }
      }
      // Aitken-Neville in place: row j of the tableau overwrites table_ from column 1 up.
      // table_[k] holds T_{j-1,k} on entry (k < j) and T_{j,k} on exit.
      std::vector<T>& cur = zc_;                             // T_{j,0}
      prev_row_.assign(table_.begin(), table_.begin() + j);  // T_{j-1,0..j-1}
      table_[0] = cur;
      for (int k = 1; k <= j; ++k) {
        const T c = coeff_[j][k];
        for (int i = 0; i < dim_; ++i) table_[k][i] = table_[k - 1][i] + (table_[k - 1][i] - prev_row_[k - 1][i]) * c;
      }
    }
    out = table_[K - 1];
    T scale = norm_inf(x);
    if (scale < T(1)) scale = T(1);
    T diff(0);
    for (int i = 0; i < dim_; ++i) {
      const T d = abs_real(T(table_[K - 1][i] - table_[K - 2][i]));
      if (d > diff) diff = d;
    }
    return diff / (s_.tolerance * scale);
  }

  Field f_;
  int dim_;
  ExtrapolationSettings<T> s_;
  ExtrapolationStats stats_;
  std::vector<std::vector<T>> coeff_;
  std::vector<std::vector<T>> table_, prev_row_;
  std::vector<T> f0_, zp_, zc_, fz_;
};

}  // namespace gm::golden
