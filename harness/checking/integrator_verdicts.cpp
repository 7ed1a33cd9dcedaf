#include "harness/checking/integrator_verdicts.hpp"

#include "properties/registry.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace gm::harness {

namespace {

const ClaimFinding* finding_of(const Verdict& v, const std::string& claim) {
  for (const auto& f : v.claims)
    if (f.claim == claim) return &f;
  return nullptr;
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

std::string claimed_text(const IntegratorClaims& c, const std::string& claim) {
  if (claim == "order") return c.order > 0 ? std::to_string(c.order) : "no";
  for (const auto& b : kBooleanClaims)
    if (claim == b.name) return c.*b.member ? "yes" : "no";
  return "no";
}

const std::vector<std::string>& claim_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"order"};
    for (const auto& b : kBooleanClaims) n.push_back(b.name);
    return n;
  }();
  return names;
}

// Why a verdict does not decide the claim it judges (empty: it does).
std::string incomplete_because(const Verdict& v, const std::string& claim) {
  const std::string where = v.property + " [" + v.scalar + "]";
  switch (v.outcome) {
    case Outcome::Pass:
      break;
    case Outcome::NotCharacterised:
    case Outcome::Fail:
      if (!v.step_raised.empty())
        return where + ": your step raised at " + v.step_raised_where + ": " + first_line(v.step_raised);
      return where + " " + outcome_name(v.outcome) + "S: " + first_line(v.message);
    default:
      return where + " " + outcome_name(v.outcome) + ": " + first_line(v.message);
  }
  if (v.cases < v.cases_planned)
    return where + " ran " + std::to_string(v.cases) + " of its " + std::to_string(v.cases_planned) + " planned cases";
  const ClaimFinding* f = finding_of(v, claim);
  if (!f) return where + " reported nothing on '" + claim + "'";
  if (!f->complete) return where + ": " + (f->measured.empty() ? first_line(f->evidence) : f->measured);
  return {};
}

// Whether checks of step kind k run on this integrator (has_step_kind, from what the report knows).
bool applies_to(StepKind k, const IntegratorInfo& integ) {
  auto has = [&](const char* step) {
    return std::find(integ.steps.begin(), integ.steps.end(), step) != integ.steps.end();
  };
  switch (k) {
    case StepKind::RigidBody:
      return has("rigid_body_step");
    case StepKind::RigidBodyMatrix:
      return has("rigid_body_step") && !integ.form.has_quaternion();
    case StepKind::RigidBodyQuaternion:
      return has("rigid_body_step") && integ.form.has_quaternion();
    case StepKind::Manakov:
      return has("manakov_step");
    case StepKind::Clebsch:
      return has("clebsch_step");
    case StepKind::ManakovClebsch:
      return has("manakov_clebsch_step");
    case StepKind::None:
      break;
  }
  return true;
}

// The checks that judge `claim` for an integrator with these steps, in scalar s.
std::vector<const Property*> judging(const std::string& claim, const IntegratorInfo& integ, const std::string& scalar) {
  std::vector<const Property*> out;
  const auto kind = scalar == "double" ? ScalarKind::Double : ScalarKind::MP50;
  for (const auto& p : properties()) {
    if (p.scope != Scope::Integrator || !p.runs_in(kind)) continue;
    if (std::find(p.judges.begin(), p.judges.end(), claim) == p.judges.end()) continue;
    if (!applies_to(p.step, integ)) continue;
    out.push_back(&p);
  }
  return out;
}

// One scalar's state for one claim.
struct ScalarState {
  enum Kind { NotApplicable, NotRun, Partial, Incomplete, False, Complete } kind = NotApplicable;
  std::string why;            // NotRun, Partial, Incomplete: which checks and why; False: the check that contradicts
  bool holds = true;          // Complete: every finding holds
  std::string contradicting;  // False: what the contradicting check measured ("order 0.24 in the regime ...")
  const Verdict* contradicted_by = nullptr;  // False: the verdict of that check
};

ScalarState scalar_state(const CheckResult& r, const IntegratorInfo& integ, const std::string& claim,
                         const std::string& scalar, std::vector<std::string>& evidence,
                         std::vector<std::string>& measured) {
  ScalarState st;
  // The verdicts of this integrator in this scalar that judge the claim.
  std::vector<const Verdict*> vs;
  for (const auto& v : r.verdicts) {
    if (v.integrator != integ.name || v.scalar != scalar) continue;
    const auto judged = judged_claims(v);
    if (std::find(judged.begin(), judged.end(), claim) != judged.end()) vs.push_back(&v);
  }
  // The registered checks that should have: those that did not run are said.
  std::vector<std::string> not_run;
  for (const Property* p : judging(claim, integ, scalar)) {
    const bool ran = std::any_of(vs.begin(), vs.end(), [&](const Verdict* v) { return v->property == p->id; });
    if (ran) continue;
    const std::string key = p->id + " [" + scalar + "]";
    const bool thorough =
        std::find(r.left_to_thorough.begin(), r.left_to_thorough.end(), key) != r.left_to_thorough.end();
    not_run.push_back(key + (thorough     ? " left to --thorough"
                             : r.narrowed ? " not selected in this run"
                                          : " did not run"));
  }
  if (vs.empty()) {
    if (not_run.empty()) return st;  // nothing judges it here
    st.kind = ScalarState::NotRun;
    for (const auto& n : not_run) st.why += (st.why.empty() ? "" : "; ") + n;
    return st;
  }
  std::string incomplete, contradicted;
  bool all_hold = true;
  for (const Verdict* v : vs) {
    if (const ClaimFinding* f = finding_of(*v, claim)) {
      evidence.push_back(scalar + ", " + v->property + ": " + f->evidence);
      if (!f->measured.empty() && v->property.find("order") != std::string::npos &&
          v->property.find("local") == std::string::npos)
        measured.push_back(f->measured + " (" + scalar + ")");
      else if (!f->measured.empty() && claim != "order")
        measured.push_back(f->measured + " (" + scalar + ")");
      // A measurement that does not hold decides, complete or shortened (a loss of energy seen in a
      // short run is a loss), even when the step raised in a later case: a finding is recorded only
      // by a case that ran to its end.
      if (!f->holds && contradicted.empty()) {
        contradicted = v->property + " [" + scalar + "]";
        st.contradicted_by = v;
        st.contradicting = (f->measured.empty() ? first_line(f->evidence) : f->measured) + " (" + scalar + ")";
      }
      all_hold = all_hold && f->holds;
    }
    // A check that ran and failed (not for a raise, not for the machine) contradicts the claims it
    // judges, unless its findings name another claim as the one that failed: a failed check is not
    // "not verified".
    if (v->outcome == Outcome::Fail && v->step_raised.empty() && v->machine_fault.empty() && contradicted.empty()) {
      const ClaimFinding* mine = finding_of(*v, claim);
      const bool another = std::any_of(v->claims.begin(), v->claims.end(),
                                       [&](const ClaimFinding& f) { return f.claim != claim && !f.holds; });
      if (!another && (!mine || !mine->holds)) {
        contradicted = v->property + " [" + scalar + "]";
        st.contradicted_by = v;
        all_hold = false;
        if (!mine) evidence.push_back(scalar + ", " + v->property + ": FAILS: " + first_line(v->message));
      }
    }
    const std::string why = incomplete_because(*v, claim);
    if (!why.empty() && incomplete.empty()) incomplete = why;
  }
  if (!contradicted.empty()) {
    st.kind = ScalarState::False;
    st.why = contradicted;
    st.holds = false;
    return st;
  }
  if (!incomplete.empty()) {
    st.kind = ScalarState::Incomplete;
    st.why = incomplete;
    return st;
  }
  st.holds = all_hold;
  if (!not_run.empty()) {
    st.kind = ScalarState::Partial;
    for (const auto& n : not_run) st.why += (st.why.empty() ? "" : "; ") + n;
    return st;
  }
  st.kind = ScalarState::Complete;
  return st;
}

std::string join(const std::vector<std::string>& xs, const char* sep) {
  std::string out;
  for (const auto& x : xs) out += (out.empty() ? "" : sep) + x;
  return out;
}

}  // namespace

std::vector<std::string> judged_claims(const Verdict& v) {
  if (v.integrator.empty()) return {};
  if (const Property* p = find_property(v.property); p && p->scope == Scope::Integrator) return p->judges;
  std::vector<std::string> out;
  for (const auto& f : v.claims) out.push_back(f.claim);
  return out;
}

std::string verdict_word(const Verdict& v, const IntegratorClaims* claims) {
  if (!v.machine_fault.empty()) return kMachineErrorWord;
  if (v.outcome != Outcome::Pass || v.integrator.empty()) return outcome_name(v.outcome);
  const auto judged = judged_claims(v);
  if (judged.empty()) return "PASS";
  IntegratorClaims none;
  if (claims_any(claims ? *claims : none, judged)) return "PASS";
  // The order is asked of every integrator (it must converge): its rows pass or fail as checks.
  if (judged == std::vector<std::string>{"order"}) return "PASS";
  bool any = false, holds = true, complete = v.cases >= v.cases_planned;
  for (const auto& claim : judged)
    if (const ClaimFinding* f = finding_of(v, claim)) {
      any = true;
      holds = holds && f->holds;
      complete = complete && f->complete;
    }
  if (any && !holds) return "does not hold (not claimed)";
  if (!any || !complete) return "not established (not claimed)";
  return "holds (not claimed)";
}

const char* status_word(ClaimStatus s) {
  switch (s) {
    case ClaimStatus::Verified:
      return "verified";
    case ClaimStatus::FalseClaim:
      return "FALSE CLAIM";
    case ClaimStatus::NotVerified:
      return "NOT VERIFIED";
    case ClaimStatus::NotRun:
      return "claimed, not run";
    case ClaimStatus::NotChecked:
      return "claimed, NOT CHECKED by any property";
    case ClaimStatus::Holds:
      return "holds (not claimed)";
    case ClaimStatus::DoesNotHold:
      return "does not hold (not claimed)";
    case ClaimStatus::NotEstablished:
      return "not established (not claimed)";
    case ClaimStatus::Measured:
      return "measured (not claimed)";
    case ClaimStatus::DoesNotConverge:
      return "DOES NOT CONVERGE";
    case ClaimStatus::None:
      break;
  }
  return "-";
}

bool fails_check(const ClaimDecision& d) {
  return d.status == ClaimStatus::FalseClaim || d.status == ClaimStatus::NotVerified ||
         d.status == ClaimStatus::NotChecked || d.status == ClaimStatus::DoesNotConverge;
}

namespace {

using ScalarStates = std::vector<std::pair<std::string, ScalarState>>;

// For a claim that does not hold: the contradicting figure leads the measured ones, and an
// unclaimed property's counterexample and reproducing command join its why.
void explain_contradiction(ClaimDecision& d, const CheckResult& r, const std::string& claim,
                           const ScalarStates& states) {
  // The figure that contradicts it leads, not a passing check's (a generic order beside a
  // failing regime's).
  for (const auto& [s, st] : states)
    if (st.kind == ScalarState::False && !st.contradicting.empty()) {
      if (d.measured.find(st.contradicting) == std::string::npos)
        d.measured = st.contradicting + (d.measured.empty() ? "" : "; elsewhere " + d.measured);
      else
        d.measured = st.contradicting;
      break;
    }
  // A property nobody claimed that does not hold carries its counterexample: the check's finding
  // at its input (support/named_inputs.hpp puts the input in it) and the command that shows it
  // again.
  if (d.status == ClaimStatus::DoesNotHold)
    for (const auto& [s, st] : states)
      if (st.kind == ScalarState::False && st.contradicted_by) {
        const Verdict& v = *st.contradicted_by;
        std::string finding;
        if (const ClaimFinding* f = finding_of(v, claim)) finding = first_line(f->evidence);
        d.why = d.why + (finding.empty() ? "" : ": " + finding) + "; reproduce: " + reproduce_command(r, v);
        break;
      }
}

// An unclaimed order's checks that fail (the step does not converge) are FAIL rows: said so.
void mark_unclaimed_order_failure(ClaimDecision& d, const CheckResult& r, const IntegratorInfo& integ) {
  for (const auto& v : r.verdicts)
    if (v.integrator == integ.name && v.outcome == Outcome::Fail && v.step_raised.empty()) {
      const auto judged = judged_claims(v);
      if (std::find(judged.begin(), judged.end(), "order") != judged.end()) {
        d.status = ClaimStatus::DoesNotConverge;
        d.why = v.property + " [" + v.scalar + "]: " + first_line(v.message);
        break;
      }
    }
}

// One claim of an integrator decided from its checks' states in every scalar: status, word, why.
ClaimDecision decide_claim(const CheckResult& r, const IntegratorInfo& integ, const std::string& claim,
                           const std::vector<std::string>& scalars) {
  ClaimDecision d;
  d.claim = claim;
  d.claimed = claimed_text(integ.claims, claim);
  bool claimed = d.claimed != "no";
  // A claim a check reported as made (a trajectory's --order) counts as made.
  for (const auto& v : r.verdicts)
    if (v.integrator == integ.name)
      if (const ClaimFinding* f = finding_of(v, claim); f && f->claimed) claimed = true;
  if (claimed && d.claimed == "no") d.claimed = "yes";
  std::vector<std::string> measured;
  ScalarStates states;
  for (const auto& s : scalars) {
    ScalarState st = scalar_state(r, integ, claim, s, d.evidence, measured);
    if (st.kind != ScalarState::NotApplicable) states.emplace_back(s, st);
  }
  d.measured = join(measured, ", ");
  auto any = [&](ScalarState::Kind k) {
    return std::any_of(states.begin(), states.end(), [&](const auto& x) { return x.second.kind == k; });
  };
  auto first = [&](ScalarState::Kind k) {
    for (const auto& [s, st] : states)
      if (st.kind == k) return st.why;
    return std::string();
  };
  // Where not every check of the claim ran (a selection, --thorough): the word says by which it was
  // decided, and `why` which did not run.
  std::vector<std::string> partly;
  for (const auto& [s, st] : states)
    if (st.kind == ScalarState::NotRun || st.kind == ScalarState::Partial) partly.push_back(st.why);
  std::vector<std::string> decided;
  for (const auto& [s, st] : states)
    if (st.kind == ScalarState::Complete || st.kind == ScalarState::Partial) decided.push_back(s);
  const std::string qualified = partly.empty() ? "" : " by the checks that ran (" + join(decided, ", ") + ")";
  const bool order = claim == "order";
  if (states.empty()) {
    d.status = claimed ? ClaimStatus::NotChecked : ClaimStatus::None;
  } else if (any(ScalarState::False)) {
    d.status = claimed ? ClaimStatus::FalseClaim : order ? ClaimStatus::DoesNotConverge : ClaimStatus::DoesNotHold;
    d.why = first(ScalarState::False);
    explain_contradiction(d, r, claim, states);
  } else if (any(ScalarState::Incomplete)) {
    d.status = claimed ? ClaimStatus::NotVerified : ClaimStatus::NotEstablished;
    d.why = first(ScalarState::Incomplete);
  } else if (decided.empty()) {
    d.status = claimed ? ClaimStatus::NotRun : ClaimStatus::None;
    d.why = join(partly, "; ");
  } else {
    bool holds = true;
    for (const auto& [s, st] : states) holds = holds && st.holds;
    if (claimed)
      d.status = holds ? ClaimStatus::Verified : ClaimStatus::FalseClaim;
    else if (order)
      d.status = holds ? ClaimStatus::Measured : ClaimStatus::DoesNotConverge;
    else
      d.status = holds ? ClaimStatus::Holds : ClaimStatus::DoesNotHold;
  }
  if (order && !claimed && d.status != ClaimStatus::DoesNotConverge) mark_unclaimed_order_failure(d, r, integ);
  d.word = status_word(d.status);
  if (d.status == ClaimStatus::Verified || d.status == ClaimStatus::Holds || d.status == ClaimStatus::Measured) {
    d.word += qualified;
    if (!partly.empty()) d.why = "not run: " + join(partly, "; ");
  }
  if (d.status == ClaimStatus::NotRun) d.word = "claimed, " + d.why;
  return d;
}

}  // namespace

std::vector<ClaimDecision> decide_claims(const CheckResult& r, const IntegratorInfo& integ) {
  std::vector<std::string> names = claim_names();
  for (const auto& v : r.verdicts)
    if (v.integrator == integ.name)
      for (const auto& c : judged_claims(v))
        if (std::find(names.begin(), names.end(), c) == names.end()) names.push_back(c);
  std::vector<std::string> scalars = integ.scalars;
  // A step detected to compute in float is checked in double only, as one stated to (the runner
  // leaves its 50-digit checks NOT PROVIDED): its claims are decided there.
  if (integ.judged_precision_how.rfind("detected", 0) == 0) std::erase(scalars, std::string("mp50"));
  if (scalars.empty()) {  // trajectory checks: the scalars their verdicts ran in
    for (const auto& v : r.verdicts)
      if (v.integrator == integ.name && std::find(scalars.begin(), scalars.end(), v.scalar) == scalars.end())
        scalars.push_back(v.scalar);
  }
  std::vector<ClaimDecision> out;
  for (const auto& claim : names) out.push_back(decide_claim(r, integ, claim, scalars));
  return out;
}

void decide_integrator_verdicts(CheckResult& r) {
  std::map<std::string, const IntegratorClaims*> claims;
  for (const auto& i : r.integrators) claims[i.name] = i.has_claims ? &i.claims : nullptr;
  for (auto& v : r.verdicts) {
    auto it = claims.find(v.integrator);
    v.word = verdict_word(v, it == claims.end() ? nullptr : it->second);
  }
  for (auto& i : r.integrators) {
    for (const auto& v : r.verdicts)
      if (v.integrator == i.name && !v.judged_precision.empty()) {
        i.judged_precision = v.judged_precision;
        i.judged_precision_how = v.judged_precision_how;
        break;
      }
    i.decisions = decide_claims(r, i);
  }
}

}  // namespace gm::harness
