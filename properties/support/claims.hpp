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
//   not claimed, holds       -> the case passes; the report says "holds (not claimed)";
//   not claimed, not holds   -> the case passes: nothing was claimed; the report says "does not hold".
//
// The runner gathers the findings of every case of a run into the verdict (Verdict::claims):
// a finding holds only if it held in every case. What the claims block, the table, the JUnit XML and
// verdicts.json say is decided once from the verdicts and their findings (harness/checking/integrator_verdicts.hpp):
// a claim is verified only when every check that judges it (PropertyDef::judges) ran all its
// cases and passed with complete findings.
#pragma once

#include <string>
#include <vector>

namespace gm {

struct ClaimFinding {
  std::string claim;     // name of the IntegratorClaims field ("order", "casimir", ...)
  bool claimed = false;  // whether the integrator claims it
  bool holds = true;     // whether it held in every case run
  std::string evidence;  // what was measured (from the last case where it did not hold, else the last case)
  // The measurement is the one that would verify the claim: false when it was shortened
  // (an unclaimed long run characterised over a tenth of its length) or could not be made in full;
  // a finding that is not complete never makes "holds" or "verified", it makes "not established".
  bool complete = true;
  // What was measured, in a few words, for the claims block: "order 1.00", "loses energy: 51% after
  // 10^4 steps (dissipative)", "residual 0.3 eps * scale". Empty: the evidence says it.
  std::string measured;
};

// Findings of the property run in progress (the runner clears them before each property run).
std::vector<ClaimFinding>& recorded_claims();

// Records the finding and fails the current case when a claim that was made does not hold.
// The evidence kept is the last failing case's (the case RapidCheck reports, after shrinking), or
// the last case's when it held in every case.
void judge_claim(const std::string& claim, bool claimed, bool holds, const std::string& evidence,
                 const std::string& measured = {}, bool complete = true);

// Records the finding only: for a property whose own require() then fails the case with a fuller
// message than "false claim" would.
void record_claim_finding(const std::string& claim, bool claimed, bool holds, const std::string& evidence,
                          const std::string& measured = {}, bool complete = true);

}  // namespace gm
