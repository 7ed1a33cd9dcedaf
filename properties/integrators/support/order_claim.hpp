// The verdict on an integrator's order claim from its errors at a fixed time as the step shrinks
// (integrator_claims.cpp, integrator_canonical.cpp): one rule for every kind of step.
//   - an error that is not finite at some step fails a claimed order (a blow-up is not a plateau);
//   - an error at round-off at every step size is an exact step for this problem: any claimed
//     order holds, and the note says so;
//   - the log-log slope over the points above the round-off floors (conv::loglog_slope) must be
//     within 0.1 of the claim; with fewer than 3 such points the order is not measurable (noted);
//   - the measured order is always a finding, claimed or not, and without a claim the
//     slope must still be at least 1 - 0.1: a step that does not converge integrates nothing.
#pragma once

#include "properties/integrators/support/convergence.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm {

// `where` says on what the errors were measured ("" or " on Manakov, n = 4"), `scalar` is the
// scalar's tag (" (double)").
// Each part's measured order, as "Pi: order 3.99, O: order 2.00" (`names` and their errors at hs);
// a part at round-off at every step is said so.
inline std::string parts_order(const std::vector<std::string>& names, const std::vector<std::vector<double>>& errs,
                               const std::vector<double>& hs, const std::vector<double>& floors) {
  std::string out;
  char buf[96];
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto fit = conv::loglog_slope(hs, errs[i], floors);
    if (conv::at_roundoff_everywhere(errs[i], floors))
      std::snprintf(buf, sizeof buf, "%s: at round-off", names[i].c_str());
    else if (fit.used < 3)
      std::snprintf(buf, sizeof buf, "%s: not measurable", names[i].c_str());
    else
      std::snprintf(buf, sizeof buf, "%s: order %.2f", names[i].c_str(), fit.slope);
    out += (out.empty() ? "" : ", ") + std::string(buf);
  }
  return out;
}

// `parts`, when given, is each part of the state with its own measured order ("Pi: order 3.99, O:
// order 2.00", parts_order below): an order that fails names the part that is off.
// `undecided_within`, when positive: the steps reached where the error is not yet its leading term
// alone (h |Omega| = `largest_turn`, 1/4 or more: the only steps whose error stands above a float
// step's round-off for a method of order 4); a slope off the claim by more than 0.1 and at most this much is NOT VERIFIED
// there, not FALSE: the reference RK4 computed in float measures 3.89 to 4.11 over such windows
// (tests/float_verdicts.py).
inline void judge_order_claim(const std::string& integrator, int claimed, const std::string& where,
                              const std::string& scalar, const std::vector<double>& hs, const std::vector<double>& errs,
                              const std::vector<double>& floors, const std::string& parts = {},
                              double undecided_within = 0, double largest_turn = 0) {
  char buf[160];
  if (const double bad = conv::first_non_finite(hs, errs); bad > 0) {
    std::snprintf(buf, sizeof buf, ": the error at the fixed time is not finite at h = %g", bad);
    const std::string what = integrator + buf + where + scalar;
    judge_claim("order", claimed > 0, false, what, "does not converge: the error is not finite");
    record_note(what);
    require(integrator + ": the error at the fixed time" + where + " is finite for every step size", false, what);
    return;
  }
  const auto fit = conv::loglog_slope(hs, errs, floors);
  if (conv::at_roundoff_everywhere(errs, floors)) {
    // Exact for this problem: an error at round-off at every step size contradicts no
    // order; a claimed one holds, and the note says why no slope was measured.
    const std::string exact = integrator + ": exact for this problem (error at round-off for every step size" + where +
                              "); any claimed order holds" + scalar;
    judge_claim("order", claimed > 0, true, exact, "exact for this problem (error at round-off)");
    record_note(exact);
    return;
  }
  if (fit.used < 3) {
    // Not measurable: the finding is incomplete, a claim is not verified by it.
    const std::string why =
        integrator + ": fewer than three step sizes above round-off" + where + "; order not measurable" + scalar;
    judge_claim("order", claimed > 0, true, why, "not measurable (fewer than three step sizes above round-off)", false);
    record_note(why);
    return;
  }
  std::snprintf(buf, sizeof buf, ": measured order %.3f", fit.slope);
  const std::string measured = integrator + buf + where + (parts.empty() ? "" : " (" + parts + ")");
  char order[64];
  std::snprintf(order, sizeof order, "order %.2f", fit.slope);
  std::snprintf(buf, sizeof buf, " (claimed %d)", claimed);
  record_note(measured + (claimed > 0 ? std::string(buf) : std::string(" (no order claimed)")) + scalar);
  if (claimed <= 0) {
    // Measured and shown whether or not it was claimed; and whatever is claimed, a step
    // whose error does not shrink with h integrates nothing: order at least 1 - 0.1.
    const bool converges = fit.slope >= 0.9;
    judge_claim("order", false, converges, measured + " (no order claimed)" + scalar,
                converges ? std::string(order) : "does not converge (" + std::string(order) + ")");
    std::snprintf(buf, sizeof buf, "measured slope %.4f\n", fit.slope);
    require(integrator + ": the error at the fixed time" + where +
                " shrinks as h does (order at least 1 - 0.1, any convergent method; no order claimed)",
            converges, buf + fit.table);
    return;
  }
  const bool holds = std::abs(fit.slope - claimed) <= 0.1;
  std::snprintf(buf, sizeof buf, ", claimed %d", claimed);
  if (!holds && std::abs(fit.slope - claimed) <= undecided_within) {
    char turn[64];
    std::snprintf(turn, sizeof turn, "steps up to h |Omega| = %.2g", largest_turn);
    judge_claim("order", true, true,
                measured + buf + ", over " + turn +
                    ", where the error is not yet its leading term alone: "
                    "not decided within 0.1" +
                    scalar,
                std::string(order) + " (" + turn + ": not decided within 0.1)", false);
    return;
  }
  judge_claim("order", true, holds, measured + buf + scalar, order);
  std::snprintf(buf, sizeof buf, "measured slope %.4f\n", fit.slope);
  require(integrator + ": the measured order (log-log slope of the error against h)" + where +
              " is within 0.1 of the claimed " + std::to_string(claimed),
          holds, buf + fit.table);
}

}  // namespace gm
