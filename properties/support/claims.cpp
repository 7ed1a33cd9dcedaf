#include "properties/support/claims.hpp"

#include "properties/support/tolerance.hpp"

namespace gm {

std::vector<ClaimFinding>& recorded_claims() {
  thread_local std::vector<ClaimFinding> findings;
  return findings;
}

void judge_claim(const std::string& claim, bool claimed, bool holds, const std::string& evidence,
                 const std::string& measured, bool complete) {
  record_claim_finding(claim, claimed, holds, evidence, measured, complete);
  if (claimed && !holds) fail("false claim '" + claim + "': " + evidence);
}

void record_claim_finding(const std::string& claim, bool claimed, bool holds, const std::string& evidence,
                          const std::string& measured, bool complete) {
  auto& all = recorded_claims();
  ClaimFinding* f = nullptr;
  for (auto& x : all)
    if (x.claim == claim) f = &x;
  if (!f) {
    all.push_back(ClaimFinding{claim, claimed, true, {}, true, {}});
    f = &all.back();
  }
  f->claimed = claimed;
  // Once it did not hold, only a later case where it did not hold replaces the evidence: the last
  // failing case is the one shrinking ends with (RapidCheck accepts each failing shrink at once).
  // Likewise a case that could not decide keeps its evidence against later ones that could: it is
  // what the verdict's "not verified" rests on.
  if (!holds || (f->holds && (!complete || f->complete))) {
    f->evidence = evidence;
    f->measured = measured;
  }
  f->holds = f->holds && holds;
  f->complete = f->complete && complete;
  ++residual_log().checks;
}

}  // namespace gm
