#include "properties/support/claims.hpp"

#include "properties/support/tolerance.hpp"

namespace gm {

std::vector<ClaimFinding>& recorded_claims() {
  thread_local std::vector<ClaimFinding> findings;
  return findings;
}

void judge_claim(const std::string& claim, bool claimed, bool holds, const std::string& evidence) {
  auto& all = recorded_claims();
  ClaimFinding* f = nullptr;
  for (auto& x : all)
    if (x.claim == claim) f = &x;
  if (!f) {
    all.push_back(ClaimFinding{claim, claimed, true, {}});
    f = &all.back();
  }
  f->claimed = claimed;
  if (f->holds) f->evidence = evidence;  // keep the first counter-evidence once it stops holding
  f->holds = f->holds && holds;
  ++residual_log().checks;
  if (claimed && !holds) fail("false claim '" + claim + "': " + evidence);
}

}  // namespace gm
