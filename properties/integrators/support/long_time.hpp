// Long-time behaviour of an energy error (DESIGN.md "A verdict is decided once"): the
// trend and sign of H(t) - H0 tell apart
//   conserved    max |e| within the round-off budget of the run;
//   losing       the energy falls: at (nearly) every step that changes it beyond round-off, or by a
//                trend larger than the oscillation it hides in (dissipative, like backward Euler;
//                however early the loss saturates, it is a loss);
//   gaining      the same, rising (secular growth, like explicit Euler), or not finite;
//   oscillating  otherwise: bounded, no trend (a symplectic or Poisson method, by backward error
//                analysis: Hairer, Lubich, Wanner, "Geometric Numerical Integration", ch. IX).
// Used by the `bounded_energy` claim (properties/integrators/integrator_structure.cpp): it holds for conserved
// and oscillating energy only.
//
// Input: the signed relative error e_k = (H_k - H0) / |H0| at the times t_k of a long run. The
// trend is the change of the mean of e from the first quarter of the run to the last, D; the
// oscillation is R, the widest range of e within one quarter. A drift c t on top of an oscillation
// of amplitude a gives D = 3 c T / 4 and R = c T / 4 + 2 a: called a trend once c T > 4 a, when
// the drift over the run outgrows the oscillation. A bounded oscillation whose period is below a
// quarter of the run gives quarter means that differ by far less than R. A monotone loss that
// saturates in the first quarter has D near 0 and is caught by the steps themselves: it falls at
// every step that changes it. Everything is in double: the errors are relative, and double's range
// holds the 50-digit run's 1e-48 as well.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::longtime {

enum class EnergyKind { Conserved, Oscillating, Losing, Gaining };

inline const char* kind_name(EnergyKind k) {
  switch (k) {
    case EnergyKind::Conserved:
      return "conserved to round-off";
    case EnergyKind::Oscillating:
      return "bounded: oscillates with no trend";
    case EnergyKind::Losing:
      return "loses energy (dissipative)";
    case EnergyKind::Gaining:
      return "gains energy (secular growth)";
  }
  return "?";
}

struct EnergyClassification {
  EnergyKind kind = EnergyKind::Conserved;
  double max_error = 0;    // max |e|
  double final_error = 0;  // e at the end of the run (signed)
  double trend = 0;        // D: mean of the last quarter minus mean of the first
  double oscillation = 0;  // R: the widest range of e within a quarter
  double budget = 0;
  long steps = 0;
  long changed = 0;                 // steps that changed H beyond round-off
  long fell = 0, rose = 0;          // of those, how many lowered it and how many raised it
  double fell_by = 0, rose_by = 0;  // the total variation of e downwards and upwards
  bool not_finite = false;          // e is not finite at step `steps` (a NaN or infinite H)
  double last_finite = 0;           // |e| at the step before, the last finite one
  bool holds() const { return kind == EnergyKind::Conserved || kind == EnergyKind::Oscillating; }

  // "loses energy at 100% of the steps that change it: 51.3% after 10^4 steps (dissipative)"
  std::string words() const {
    char buf[300];
    const auto pct = [](double x) { return 100.0 * std::abs(x); };
    switch (kind) {
      case EnergyKind::Conserved:
        std::snprintf(buf, sizeof buf, "conserved to round-off: max |H - H0| / |H0| = %.3g over %ld steps", max_error,
                      steps);
        break;
      case EnergyKind::Oscillating:
        std::snprintf(buf, sizeof buf, "oscillates within %.3g of H0 (relative) with no trend over %ld steps (bounded)",
                      max_error, steps);
        break;
      case EnergyKind::Losing:
      case EnergyKind::Gaining: {
        const bool losing = kind == EnergyKind::Losing;
        const long way = losing ? fell : rose;
        if (not_finite && (std::isinf(max_error) || last_finite > 1)) {
          std::snprintf(buf, sizeof buf,
                        "gains energy without bound: H is not finite within %ld steps, after |H - H0| / |H0| reached "
                        "%.3g (secular growth)",
                        steps, last_finite);
        } else if (not_finite) {
          // A NaN from a state whose energy had not grown: what the step returned, not a growth.
          std::snprintf(buf, sizeof buf,
                        "the step returns a state that is not finite at step %ld, from a state whose |H - H0| / |H0| "
                        "was %.3g",
                        steps, last_finite);
        } else if (changed > 0 && way == changed) {
          std::snprintf(buf, sizeof buf, "%s energy at every step that changes it: %.3g%% %s after %ld steps (%s)",
                        losing ? "loses" : "gains", pct(final_error), losing ? "lost" : "gained", steps,
                        losing ? "dissipative" : "secular growth");
        } else if (changed > 0 && way >= 0.99 * static_cast<double>(changed)) {
          std::snprintf(buf, sizeof buf,
                        "%s energy at %.1f%% of the steps that change it: %.3g%% %s after %ld steps (%s)",
                        losing ? "loses" : "gains", 100.0 * static_cast<double>(way) / static_cast<double>(changed),
                        pct(final_error), losing ? "lost" : "gained", steps, losing ? "dissipative" : "secular growth");
        } else if (std::abs(trend) > oscillation) {
          std::snprintf(buf, sizeof buf,
                        "%s energy over the run: %.3g%% %s after %ld steps, a trend larger than its oscillation (%s)",
                        losing ? "loses" : "gains", pct(final_error), losing ? "lost" : "gained", steps,
                        losing ? "dissipative" : "secular growth");
        } else {
          const double share = (losing ? fell_by : rose_by) / std::max(fell_by + rose_by, 1e-300);
          std::snprintf(buf, sizeof buf,
                        "%s energy over the run: %.3g%% %s after %ld steps, %.1f%% of its motion %s (the rest is "
                        "round-off noise) (%s)",
                        losing ? "loses" : "gains", pct(final_error), losing ? "lost" : "gained", steps, 100.0 * share,
                        losing ? "downwards" : "upwards", losing ? "dissipative" : "secular growth");
        }
        break;
      }
    }
    return buf;
  }
  std::string evidence() const {
    char buf[300];
    if (not_finite) return words();  // the statistics of a run cut short by a NaN say nothing more
    std::snprintf(buf, sizeof buf,
                  "%s; max |e| = %.3g, e at the end %.3g, trend (last quarter's mean - first's) %.3g against an "
                  "oscillation of %.3g within a quarter, round-off budget %.3g",
                  words().c_str(), max_error, final_error, trend, oscillation, budget);
    return buf;
  }
};

// e[0] is the start (0); `step_roundoff` is the round-off of one step's relative change (a change
// of H no larger is not counted as a fall or a rise).
inline EnergyClassification classify_energy_error(const std::vector<double>& t, const std::vector<double>& e,
                                                  double budget, double step_roundoff) {
  (void)t;
  EnergyClassification c;
  c.budget = budget;
  const std::size_t n = e.size();
  c.steps = n > 0 ? static_cast<long>(n - 1) : 0;
  double rose_by = 0, fell_by = 0;  // the total variation of e upwards and downwards
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(e[k])) {
      c.not_finite = true;
      c.kind = EnergyKind::Gaining;
      c.last_finite = k > 0 ? std::abs(e[k - 1]) : 0;
      c.max_error = std::abs(e[k]);
      c.steps = static_cast<long>(k);
      return c;
    }
    c.max_error = std::max(c.max_error, std::abs(e[k]));
    if (k > 0) {
      const double d = e[k] - e[k - 1];
      (d < 0 ? fell_by : rose_by) += std::abs(d);
      if (std::abs(d) > step_roundoff) {
        ++c.changed;
        (d < 0 ? c.fell : c.rose) += 1;
      }
    }
  }
  c.final_error = n > 0 ? e[n - 1] : 0;
  if (c.max_error <= budget) {
    c.kind = EnergyKind::Conserved;
    return c;
  }
  // Quarters: their means and ranges.
  double mean[4] = {0, 0, 0, 0};
  for (int q = 0; q < 4; ++q) {
    const std::size_t lo = n * q / 4, hi = std::max(lo + 1, n * (q + 1) / 4);
    double lo_e = e[lo], hi_e = e[lo], sum = 0;
    for (std::size_t k = lo; k < hi && k < n; ++k)
      lo_e = std::min(lo_e, e[k]), hi_e = std::max(hi_e, e[k]), sum += e[k];
    mean[q] = sum / static_cast<double>(hi - lo);
    c.oscillation = std::max(c.oscillation, hi_e - lo_e);
  }
  c.trend = mean[3] - mean[0];
  // Monotone: (nearly) every step that changes H beyond round-off changes it one way, or, weighed
  // by size, the motion of e one way is at least three times the other (round-off noise on a
  // plateau, as in single precision, moves e both ways by about as much, and cannot hide a loss of
  // the state's size); and the run ends beyond the budget that way.
  c.fell_by = fell_by;
  c.rose_by = rose_by;
  const bool down_by_size = fell_by > 3 * rose_by, up_by_size = rose_by > 3 * fell_by;
  const bool monotone_down =
      c.changed > 0 && (c.fell >= 0.99 * static_cast<double>(c.changed) || down_by_size) && c.final_error < -budget;
  const bool monotone_up =
      c.changed > 0 && (c.rose >= 0.99 * static_cast<double>(c.changed) || up_by_size) && c.final_error > budget;
  if (monotone_down || (std::abs(c.trend) > c.oscillation && c.trend < 0))
    c.kind = EnergyKind::Losing;
  else if (monotone_up || (std::abs(c.trend) > c.oscillation && c.trend > 0))
    c.kind = EnergyKind::Gaining;
  else
    c.kind = EnergyKind::Oscillating;
  return c;
}

}  // namespace gm::longtime
