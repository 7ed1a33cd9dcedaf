// Systematic round-off (DESIGN.md, "Judged at the precision the code computes in"): round-off can
// be a defect of its own. A biased rounding (a normalisation that leans one way) moves an invariant
// by the same amount at every step, whatever h; over 10^5 steps that is a percent-level drift in
// float, where round-off without a bias wanders by a few eps like a random walk (Higham, "Accuracy
// and Stability of Numerical Algorithms", ch. 2-3). Told apart by experiment, at a fixed state:
//   1. the step at a tiny h (h |Omega| = 2^-8 of the step's eps: 2^-31 in float, 2^-60 in double): the
//      motion moves the state by far less than its last place, so a step without a bias returns the state, or one rounding both ways; a drift
//      of the invariant there is the step's own arithmetic;
//   2. the trend at two step sizes, the check's own h and h/4: a truncation drift scales with a
//      power of h, a bias per step does not.
// Systematic: at the tiny step the mean change per step is at least 1/16 of the step's eps
// (relative to the invariant) and stands at least 6 standard errors from 0 over 256 steps (a
// random walk without bias does so with a chance below 1e-8). The rate per step is the finding, and
// its size over 10^5 steps.
#pragma once

#include "properties/support/scalar_text.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/truth.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gm::roundoffdrift {

struct Drift {
  bool systematic = false;
  double per_step = 0;         // mean relative change per step at the tiny h
  double gaining = 0;          // the share of the tiny steps that raised it
  double at_h = 0, at_h4 = 0;  // mean relative change per step at the check's h and at h/4
  double h = 0, tiny_h = 0;
  std::string words;  // "systematic round-off, by experiment: ..." (systematic only)
  std::string rate;   // "systematic round-off: |Pi|^2 gains 2.4e-07 per step whatever h, 2.4% over 10^5 steps"
};

struct Moments {
  double mean = 0, standard_error = 0, rising = 0;
};

// The mean change per step of e_k = (invariant_k - invariant_0) / |invariant_0| (e_0 = 0), its
// standard error and the share of steps that raise it.
inline Moments moments_of(const std::vector<double>& e) {
  Moments m;
  const std::size_t n = e.size() > 0 ? e.size() - 1 : 0;
  if (n == 0) return m;
  double sum = 0, sum2 = 0;
  int rising = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double d = e[k] - e[k - 1];
    if (!std::isfinite(d)) return Moments{};
    sum += d, sum2 += d * d;
    rising += d > 0;
  }
  m.mean = sum / static_cast<double>(n);
  const double var = std::max(0.0, sum2 / static_cast<double>(n) - m.mean * m.mean);
  m.standard_error = std::sqrt(var / static_cast<double>(n));
  m.rising = static_cast<double>(rising) / static_cast<double>(n);
  return m;
}

// `values(h, steps)`: e_k = (invariant_k - invariant_0) / |invariant_0| for k = 0..steps, steps of h
// from the fixed state, computed in T and then converted (a change of one unit of T's last place
// survives the conversion); `rate` is the state's |Omega|, `h` the check's step; `name` the
// invariant ("|Pi|^2").
template <class T, class Values>
Drift measure(Values&& values, const T& rate, const T& h, const std::string& name) {
  Drift d;
  d.h = to_double(h);
  // 2^-8 of the step's own eps a step, h |Omega| = 2^-31 in float, 2^-60 in double, 2^-175 in 50
  // digits: a consistent step moves the state by far less than its last place.
  T tiny = step_eps<T>() / T(256);
  tiny = at_least_min_h<T>(T(tiny / rate));
  d.tiny_h = to_double(tiny);
  const Moments at_tiny = moments_of(values(tiny, 256));
  d.per_step = at_tiny.mean;
  d.gaining = at_tiny.rising;
  const double eps = step_eps_double<T>();
  const bool biased = std::abs(at_tiny.mean) >= eps / 16 && std::abs(at_tiny.mean) >= 6 * at_tiny.standard_error;
  if (!biased) return d;
  d.systematic = true;
  d.at_h = moments_of(values(h, 64)).mean;
  d.at_h4 = moments_of(values(T(h / T(4)), 64)).mean;
  const auto same = [&](double a) {
    return a * d.per_step > 0 && std::abs(a) <= 2 * std::abs(d.per_step) && std::abs(a) >= std::abs(d.per_step) / 2;
  };
  const bool whatever_h = same(d.at_h) && same(d.at_h4);
  const bool gains = d.per_step > 0;
  const std::string over = fmt("%.2g%% over 10^5 steps", 100 * std::abs(std::expm1(1e5 * std::log1p(d.per_step))));
  d.rate = "systematic round-off: " + name + (gains ? " gains " : " loses ") + fmt("%.2g", std::abs(d.per_step)) +
           " of itself per step" + (whatever_h ? " whatever h" : "") + ", " + over;
  d.words = "systematic round-off, by experiment: " + name + (gains ? " gains " : " loses ") +
            fmt("%.2g", std::abs(d.per_step)) + " of itself per step (" + fmt("%.2g", std::abs(d.per_step) / eps) +
            " " + eps_word<T>() + ") at h = " + fmt("%.3g", d.tiny_h) + ", a step far too small to move the state, " +
            fmt("%.0f%% of 256 steps ", 100 * (gains ? d.gaining : 1 - d.gaining)) + (gains ? "raising" : "lowering") +
            " it; at the check's h = " + fmt("%.3g", d.h) + " and at h/4: " + fmt("%+.2g", d.at_h) + " and " +
            fmt("%+.2g", d.at_h4) + " per step" +
            (whatever_h ? ", the same whatever h: a biased rounding in the step (a normalisation that rounds one way), "
                        : ", on top of what the steps change: a biased rounding in the step, ") +
            fmt("%.2g%% over 10^5 steps", 100 * std::abs(std::expm1(1e5 * std::log1p(d.per_step))));
  return d;
}

// The experiment of support/roundoff_drift.hpp for `invariant`, once per integrator in this process,
// at a fixed state (a generic body, momentum and attitude): a bias per step that the 64 steps'
// allowance could hide. Nothing is found when the step raises there.
template <class T, class Invariant>
const Drift& rigid_body_drift(const Integrator<T>& in, const std::string& name, Invariant invariant) {
  static thread_local std::map<std::string, Drift> found;
  const std::string key = in.name + "\n" + name;
  if (auto it = found.find(key); it != found.end()) return it->second;
  const Vec3<T> I(T(7) / T(4), T(3) / T(2), T(5) / T(4));
  const Vec3<T> a(T(1) / T(2), T(-1) / T(3), T(1) / T(4));
  const Mat3<T> A = truth::skew_of(a), Id = Mat3<T>::Identity();
  const RigidBodyState<T> x0{Vec3<T>(T(21) / T(32), T(-19) / T(32), T(-3) / T(16)),
                             Mat3<T>((Id - A / T(2)).inverse() * (Id + A / T(2)))};
  const T v0 = invariant(I, x0);
  const auto values = [&](const T& h, int steps) {
    std::vector<double> e{0.0};
    RigidBodyState<T> x = x0;
    for (int n = 0; n < steps; ++n) {
      x = in.rigid_body_step(I, x, h);
      e.push_back(to_double(T((invariant(I, x) - v0) / abs_value(v0))));
    }
    return e;
  };
  Drift d;
  try {
    d = measure<T>(values, T(max_abs(Vec3<T>(x0.Pi.cwiseQuotient(I)))), T(1) / T(8), name);
  } catch (const StepRaised&) {
    current_step_raise().reset();
  } catch (const OutsideDomain&) {}
  return found[key] = d;
}

}  // namespace gm::roundoffdrift
