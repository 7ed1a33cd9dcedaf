// The verdict on a claim an integrator makes about a quantity it keeps to round-off (Noether,
// equivariance, symplecticity, ...): the worst residual over the states tried against
// k eps(T) * scale. The finding goes to the report's claims table (support/claims.hpp): claimed and
// holding, a verified claim; claimed and not holding, a FAIL with the residual as evidence; not
// claimed, a note saying whether it holds anyway.
#pragma once

#include "properties/support/claims.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/tolerance.hpp"

#include <cstdio>
#include <string>

namespace gm {

template <class T>
void judge_roundoff_claim(const char* claim, bool claimed, const std::string& integrator, const std::string& what,
                          const T& residual, const T& scale, double k) {
  const std::string scalar = scalar_tag<T>();
  const bool holds = is_finite(residual) && residual <= T(k) * eps<T>() * scale;
  const std::string units =
      is_finite(residual) ? fmt("%.3g eps * scale", to_double(T(residual / (eps<T>() * scale)))) : "not finite";
  const std::string evidence = integrator + ": " + what + ": residual " + units + ", allowed " +
                               fmt("%g eps * scale", k) + ", scale " + to_string_full(scale) + scalar;
  judge_claim(claim, claimed, holds, evidence, "residual " + units);
  if (!claimed && holds) record_note(integrator + ": " + what + " holds although not claimed (residual " + units + ")");
  if (!claimed && !holds)
    record_note(integrator + ": " + what + " does not hold (not claimed): residual " + units + scalar);
}

}  // namespace gm
