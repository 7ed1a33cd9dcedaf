// The verdict on a claim an integrator makes about a quantity it keeps to round-off (the Casimir,
// the energy, orthogonality, Noether, equivariance, symplecticity, ...): the worst residual over the
// states tried against k eps * scale, eps the unit round-off of the precision the step computes in
// (properties/support/step_precision.hpp: float's 2^-23 for a step computed in float, whatever
// scalar drives it). The finding goes to the report's claims table (support/claims.hpp): claimed and
// holding, a verified claim; claimed and not holding, a FAIL with the residual as evidence; not
// claimed, a note saying whether it holds anyway.
#pragma once

#include "properties/support/claims.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"

#include <cstdio>
#include <string>

namespace gm {

// Whether `residual` is within k step-eps * scale.
template <class T>
bool within_roundoff(const T& residual, const T& scale, double k) {
  return is_finite(residual) && residual <= T(k) * step_eps<T>() * scale;
}

// The residual of a claimed quantity in the run's log (ResidualLog: the table's "2.1 eps"), in units
// of the step's eps.
template <class T>
void log_roundoff_residual(const std::string& what, const T& residual, const T& scale) {
  auto& log = residual_log();
  ++log.checks;
  const T unit = step_eps<T>() * scale;
  const double units = !is_finite(residual) ? std::numeric_limits<double>::infinity()
                       : residual == T(0)   ? 0.0
                       : unit == T(0)       ? std::numeric_limits<double>::infinity()
                                            : to_double(T(residual / unit));
  if (units >= log.worst_eps_units) {
    log.worst_eps_units = units;
    log.worst_absolute = to_double(residual);
    log.worst_check = what;
  }
}

// `cause`, when given, is what an experiment found and is said after the residual; `defect`: that
// experiment shows the quantity is not kept whatever the residual of this run (a systematic
// round-off, support/roundoff_drift.hpp, moves it by the same amount at every step: within the
// allowance over 64 steps, percent-level over 10^5).
template <class T>
void judge_roundoff_claim(const char* claim, bool claimed, const std::string& integrator, const std::string& what,
                          const T& residual, const T& scale, double k, const std::string& cause = {},
                          bool defect = false, const std::string& defect_measured = {}) {
  const std::string tag = judged_tag<T>();
  const bool holds = within_roundoff(residual, scale, k) && !defect;
  const std::string units = step_eps_units(residual, scale);
  const std::string evidence = integrator + ": " + what + ": residual " + units + ", allowed " + fmt("%g ", k) +
                               eps_word<T>() + " * scale, scale " + to_string_full(scale) +
                               (cause.empty() ? std::string() : "; " + cause) + tag;
  if (claimed) log_roundoff_residual(integrator + ": " + what + " (claimed)", residual, scale);
  judge_claim(claim, claimed, holds, evidence,
              defect && !defect_measured.empty() ? defect_measured : "residual " + units);
  if (!claimed && holds) record_note(integrator + ": " + what + " holds although not claimed (residual " + units + ")");
  if (!claimed && !holds)
    record_note(integrator + ": " + what + " does not hold (not claimed): residual " + units +
                (cause.empty() ? std::string() : "; " + cause) + tag);
}

}  // namespace gm
