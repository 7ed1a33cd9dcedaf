// The verdict on an integrator's order claim from its errors at a fixed time as the step shrinks
// (integrator_claims.cpp, integrator_canonical.cpp): one rule for every kind of step.
//   - an error that is not finite at some step fails a claimed order (a blow-up is not a plateau);
//   - an error at round-off at every step size is an exact step for this problem: any claimed
//     order holds (issue 36), and the note says so;
//   - the log-log slope over the points above the round-off floors (conv::loglog_slope) must be
//     within 0.1 of the claim; with fewer than 3 such points the order is not measurable (noted);
//   - the measured order is always noted, claimed or not.
#pragma once

#include "properties/support/claims.hpp"
#include "properties/support/convergence.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm {

// `where` says on what the errors were measured ("" or " on Manakov, n = 4"), `scalar` is the
// scalar's tag (" (double)").
inline void judge_order_claim(const std::string& integrator, int claimed, const std::string& where,
                              const std::string& scalar, const std::vector<double>& hs, const std::vector<double>& errs,
                              const std::vector<double>& floors) {
  char buf[160];
  if (const double bad = conv::first_non_finite(hs, errs); bad > 0) {
    std::snprintf(buf, sizeof buf, ": the error at the fixed time is not finite at h = %g", bad);
    const std::string what = integrator + buf + where + scalar;
    if (claimed > 0) judge_claim("order", true, false, what);
    record_note(what);
    return;
  }
  const auto fit = conv::loglog_slope(hs, errs, floors);
  if (conv::at_roundoff_everywhere(errs, floors)) {
    // Exact for this problem (issue 36): an error at round-off at every step size contradicts no
    // order; a claimed one holds, and the note says why no slope was measured.
    const std::string exact = integrator + ": exact for this problem (error at round-off for every step size" +
                              where + "); any claimed order holds" + scalar;
    if (claimed > 0) judge_claim("order", true, true, exact);
    record_note(exact);
    return;
  }
  if (fit.used < 3) {
    record_note(integrator + ": fewer than three step sizes above round-off" + where + "; order not measurable" + scalar);
    return;
  }
  std::snprintf(buf, sizeof buf, ": measured order %.3f", fit.slope);
  const std::string measured = integrator + buf + where;
  std::snprintf(buf, sizeof buf, " (claimed %d)", claimed);
  record_note(measured + (claimed > 0 ? std::string(buf) : std::string(" (no order claimed)")) + scalar);
  if (claimed <= 0) return;
  const bool holds = std::abs(fit.slope - claimed) <= 0.1;
  std::snprintf(buf, sizeof buf, ", claimed %d", claimed);
  judge_claim("order", true, holds, measured + buf + scalar);
  std::snprintf(buf, sizeof buf, "measured slope %.4f\n", fit.slope);
  require(integrator + ": the measured order (log-log slope of the error against h)" + where +
              " is within 0.1 of the claimed " + std::to_string(claimed),
          holds, buf + fit.table);
}

}  // namespace gm
