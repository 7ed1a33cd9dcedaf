// Long-time behaviour of an energy error: conserved to round-off, bounded (oscillating, no secular
// drift), or drifting. Used by the `bounded_energy` claim (properties/integrator_structure.cpp).
//
// Input: the relative energy error e_k = (H_k - H_0) / |H_0| at the times t_k of a long run.
// The run is cut into W windows of equal length; m_w = max |e| over window w.
//   conserved  max_k |e_k| <= budget (the caller's round-off allowance for the whole run);
//   drifting   the least-squares line through (t_w, m_w) rises over the run by more than the
//              median window maximum (the typical size of the error). Pure linear drift c t gives
//              a rise c T against a median c T / 2 (ratio 2); drift c t on top of an oscillation
//              of amplitude A is called drifting once c T > 2 A, i.e. once the drift over the run
//              exceeds the oscillation it hides in. A bounded oscillation gives window maxima ~A
//              each, a fitted rise far below A even when a window is shorter than a period (the
//              first windows, where the error starts from 0, are the only systematic trend, and a
//              few of W windows move the median little);
//   bounded    otherwise.
// A non-finite error is drifting. Everything is done in double: the errors are relative, and
// double's range holds the 50-digit run's 1e-48 as well.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::longtime {

enum class EnergyKind { Conserved, Bounded, Drifting };

inline const char* kind_name(EnergyKind k) {
  switch (k) {
    case EnergyKind::Conserved: return "conserved to round-off";
    case EnergyKind::Bounded: return "bounded, oscillating without secular drift";
    case EnergyKind::Drifting: return "drifting (secular growth)";
  }
  return "?";
}

struct EnergyClassification {
  EnergyKind kind = EnergyKind::Conserved;
  double max_error = 0;     // max |e| over the run
  double typical = 0;       // median of the window maxima
  double slope = 0;         // fitted growth of the window maxima per unit time
  double rise = 0;          // slope * (run length): the fitted drift over the run
  double budget = 0;
  int windows = 0;
  std::string evidence() const {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%s: max |H-H0|/|H0| = %.3g, fitted drift of the window maxima %.3g per unit time (%.3g over the "
                  "run), median window maximum %.3g, round-off budget %.3g, %d windows",
                  kind_name(kind), max_error, slope, rise, typical, budget, windows);
    return buf;
  }
};

inline EnergyClassification classify_energy_error(const std::vector<double>& t, const std::vector<double>& e,
                                                  double budget, int windows = 20) {
  EnergyClassification c;
  c.budget = budget;
  c.windows = windows;
  const std::size_t n = std::min(t.size(), e.size());
  for (std::size_t k = 0; k < n; ++k) {
    const double a = std::abs(e[k]);
    if (!std::isfinite(a)) {
      c.kind = EnergyKind::Drifting;
      c.max_error = a;
      return c;
    }
    c.max_error = std::max(c.max_error, a);
  }
  if (n < static_cast<std::size_t>(2 * windows)) windows = std::max(1, static_cast<int>(n / 2));
  c.windows = windows;
  std::vector<double> tw, mw;
  for (int w = 0; w < windows; ++w) {
    const std::size_t lo = n * w / windows, hi = n * (w + 1) / windows;
    double m = 0;
    for (std::size_t k = lo; k < hi; ++k) m = std::max(m, std::abs(e[k]));
    tw.push_back((t[lo] + t[hi - 1]) / 2);
    mw.push_back(m);
  }
  {
    std::vector<double> sorted = mw;
    std::sort(sorted.begin(), sorted.end());
    c.typical = sorted[sorted.size() / 2];
  }
  double st = 0, sm = 0;
  for (int w = 0; w < windows; ++w) st += tw[w], sm += mw[w];
  st /= windows, sm /= windows;
  double stt = 0, stm = 0;
  for (int w = 0; w < windows; ++w) stt += (tw[w] - st) * (tw[w] - st), stm += (tw[w] - st) * (mw[w] - sm);
  c.slope = stt > 0 ? stm / stt : 0;
  c.rise = c.slope * (t[n - 1] - t[0]);
  if (c.max_error <= budget)
    c.kind = EnergyKind::Conserved;
  else if (c.rise > c.typical)
    c.kind = EnergyKind::Drifting;
  else
    c.kind = EnergyKind::Bounded;
  return c;
}

}  // namespace gm::longtime
