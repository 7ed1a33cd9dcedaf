#include "harness/checking/first_fix.hpp"

#include "harness/checking/check.hpp"
#include "harness/checking/source_calls.hpp"

#include "properties/registry.hpp"

#include <algorithm>

namespace gm::harness {

bool is_problem(Outcome o) {
  return o == Outcome::Fail || o == Outcome::Crash || o == Outcome::Timeout || o == Outcome::Error;
}

std::string row_name(const Verdict& v) { return v.property + (v.integrator.empty() ? "" : " [" + v.integrator + "]"); }

namespace {

const Property* property_of(const Verdict& v) { return find_property(v.property); }

// Which of two failures of a slot's own check shows it more clearly: an exact
// counterexample (it fails in rationals, no tolerance involved) before a float one, and among float
// ones the residual farthest above its allowance; a marginal case (a few eps over) comes last.
bool clearer(const Verdict& a, const Verdict& b) {
  const bool ea = a.scalar == "exact" && a.outcome == Outcome::Fail,
             eb = b.scalar == "exact" && b.outcome == Outcome::Fail;
  if (ea != eb) return ea;
  return a.worst_eps_units > b.worst_eps_units;
}

}  // namespace

std::string slot_of_direct_check(const Verdict& v) {
  const Property* p = property_of(v);
  if (p && p->scope == Scope::Subject && p->needs.size() == 1) return p->needs.front();
  return {};
}

FirstFixesSoFar::FirstFixesSoFar(const SubjectInfo& info)
    : source_(info.source), language_(info.language), cells_(info.cells) {}

std::optional<FirstFixesSoFar::Named> FirstFixesSoFar::on_problem(const Verdict& v) {
  if (!is_problem(v.outcome) || !v.machine_fault.empty()) return std::nullopt;
  const std::string slot = slot_of_direct_check(v);
  if (slot.empty() || !named_.insert(slot).second) return std::nullopt;
  if (!calls_)
    calls_ = source_.empty() ? std::map<std::string, std::set<std::string>>{} : slot_calls(source_, *language_, cells_);
  Named n{slot, ""};
  if (auto it = calls_->find(slot); it != calls_->end())
    for (const auto& c : it->second)
      if (named_.count(c) && c != slot) n.callee = c;
  return n;
}

RootCauses root_causes(const CheckResult& r) {
  RootCauses rc;
  for (const auto& v : r.verdicts) {
    if (!is_problem(v.outcome) || !v.machine_fault.empty()) continue;  // the machine's: names no slot
    const Property* p = property_of(v);
    if (!p || p->needs.size() != 1 || p->scope != Scope::Subject) continue;
    auto it = rc.broken.find(p->needs.front());
    if (it == rc.broken.end() || clearer(v, it->second)) rc.broken[p->needs.front()] = v;
  }
  for (const auto& [slot, direct] : rc.broken) rc.explained.insert(direct.property);
  std::set<std::string> listed;
  for (const auto& v : r.verdicts) {
    if (!is_problem(v.outcome) || !v.machine_fault.empty() || rc.explained.count(v.property)) continue;
    const Property* p = property_of(v);
    if (!p) continue;
    for (const auto& need : p->needs)
      if (rc.broken.count(need)) {
        if (listed.insert(need + "/" + v.property).second) rc.downstream[need].push_back(row_name(v));
        rc.caused.insert(v.property);
      }
  }
  rc.explained.insert(rc.caused.begin(), rc.caused.end());
  // A wrong slot that calls another wrong slot (read from the student's source, across the
  // files of a folder too) most likely fails through it: the callee is the first fix.
  if (rc.broken.size() > 1 && !r.info.source.empty()) {
    const auto calls = slot_calls(r.info.source, *r.info.language, r.info.cells);
    for (const auto& [slot, direct] : rc.broken)
      if (auto it = calls.find(slot); it != calls.end())
        for (const auto& callee : it->second)
          if (rc.broken.count(callee)) {
            rc.calls_broken[slot] = callee;
            break;
          }
  }
  auto depth = [&](std::string s) {  // how many wrong callees stand before it (a cycle stops)
    int d = 0;
    for (auto it = rc.calls_broken.find(s); it != rc.calls_broken.end() && d < 64; it = rc.calls_broken.find(s))
      s = it->second, ++d;
    return d;
  };
  for (const auto& [slot, direct] : rc.broken) rc.order.push_back(slot);
  std::stable_sort(rc.order.begin(), rc.order.end(), [&](const std::string& a, const std::string& b) {
    auto n = [&](const std::string& s) {
      auto it = rc.downstream.find(s);
      return it == rc.downstream.end() ? 0 : it->second.size();
    };
    if (depth(a) != depth(b)) return depth(a) < depth(b);
    return n(a) > n(b);
  });
  return rc;
}

void decide_first_fixes(CheckResult& r) { r.first_fixes = root_causes(r); }

}  // namespace gm::harness
