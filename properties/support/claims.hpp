// What integrator-scoped properties report about an integrator's claims.
//
// An integrator declares claims (IntegratorClaims: order, symmetric, casimir, energy,
// orthogonality, spectrum, poisson). A property that verifies one of them measures it whether or
// not it was claimed, and reports the finding with judge_claim():
//
//   judge_claim("casimir", claims.casimir, residual_is_roundoff, "max ||Pi|^2 - |Pi0|^2| = ...");
//
//   claimed and holds        -> the case passes: the claim is verified;
//   claimed and not holds    -> the case fails: a false claim (with the evidence as the message);
//   not claimed, holds       -> the case passes; the report says "holds, not claimed";
//   not claimed, not holds   -> the case passes: nothing was claimed.
//
// The runner gathers the findings of every case of a run into the verdict (Verdict::claims):
// a finding holds only if it held in every case.
#pragma once

#include <string>
#include <vector>

namespace gm {

struct ClaimFinding {
  std::string claim;     // name of the IntegratorClaims field ("order", "casimir", ...)
  bool claimed = false;  // whether the integrator claims it
  bool holds = true;     // whether it held in every case run
  std::string evidence;  // what was measured (from the first case where it did not hold, else the last)
};

// Findings of the property run in progress (the runner clears them before each property run).
std::vector<ClaimFinding>& recorded_claims();

// Records the finding and fails the current case when a claim that was made does not hold.
void judge_claim(const std::string& claim, bool claimed, bool holds, const std::string& evidence);

}  // namespace gm
