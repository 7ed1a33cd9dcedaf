// The first fixes of a check, decided once by the check (run_check, check_trajectories) and kept on
// the CheckResult; the console, report.md, verdicts.json's `first_fix` and the class views render
// them and decide nothing.
//
// A slot is wrong when its own direct property (one that needs that slot alone) has a problem; the
// other failing properties that need it are its downstream. A wrong slot whose source calls another
// wrong slot (harness/checking/source_calls.hpp) most likely fails through it: the callee is the fix.
// Order: callees before their callers, then the slot most other failures call.
#pragma once

#include "harness/languages/language.hpp"
#include "harness/languages/notebook.hpp"
#include "properties/verdict.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gm::harness {

struct CheckResult;
struct SubjectInfo;

bool is_problem(Outcome o);  // FAIL, CRASH, TIMEOUT or ERROR

// A verdict's row: "property" or "property [integrator]".
std::string row_name(const Verdict& v);

struct RootCauses {
  std::map<std::string, Verdict> broken;                       // slot -> its clearest failing direct verdict
  std::map<std::string, std::vector<std::string>> downstream;  // slot -> failing rows that need it
  std::set<std::string> caused;                                // those properties
  std::set<std::string> explained;                             // direct + caused
  std::vector<std::string> order;  // broken slots: callees before their callers, then the one most other failures call
  // A broken slot whose source calls another broken slot -> that slot: fix the callee first.
  std::map<std::string, std::string> calls_broken;
};

// The rule, from the verdicts and the source the result names. A machine's fault names no slot.
RootCauses root_causes(const CheckResult& r);

// r.first_fixes = root_causes(r): once, when the verdicts are complete.
void decide_first_fixes(CheckResult& r);

// The slot whose own direct check this verdict is (a property of the subject needing that slot
// alone); "" for any other.
std::string slot_of_direct_check(const Verdict& v);

// The first fixes as the verdicts arrive, for a console that prints them live (the same rule,
// decided on what has arrived so far): a slot whose own direct check fails is named once; one whose
// source calls a slot already named most likely fails through it, and that callee is named.
class FirstFixesSoFar {
 public:
  struct Named {
    std::string slot;
    std::string callee;  // empty: the slot itself is wrong; else the slot it calls, named before
  };
  explicit FirstFixesSoFar(const SubjectInfo& info);
  // A problem verdict's first fix, if it names a slot not named yet (a machine's fault names none).
  std::optional<Named> on_problem(const Verdict& v);

 private:
  std::string source_;
  const Language* language_;
  std::vector<CodeCell> cells_;  // a notebook's
  std::set<std::string> named_;
  // Which slots each slot of the source calls (harness/checking/source_calls.hpp), read at the first one.
  std::optional<std::map<std::string, std::set<std::string>>> calls_;
};

}  // namespace gm::harness
