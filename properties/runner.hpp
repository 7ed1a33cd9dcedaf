// Runs one property against one subject in one scalar and turns RapidCheck's result into a
// verdict: outcome, message, shrunk counterexample at full precision, the seed, RapidCheck's
// reproduce string, and the worst residual seen (in units of eps * scale).
#pragma once

#include "properties/registry.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/figures.hpp"
#include "properties/verdict.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gm {

struct RunOptions {
  std::uint64_t seed = 0;        // base seed; each (property, scalar) derives its own from it
  int cases = 0;                 // 0: the property's default for the scalar
  double case_factor = 1.0;      // multiplies the default case counts
  std::string reproduce;         // RapidCheck reproduce string (the value after "reproduce=")
  bool honour_rc_params = true;  // read seed / max_success / reproduce from $RC_PARAMS
  bool shrink = true;            // shrink a failure to a small case (a negative control only needs the failure)
  // Time budgets, so that a correct but slow implementation (Python in 50 digits, a solve redone
  // at every call) is checked on fewer cases instead of being stopped as a TIMEOUT:
  //  - case_budget_seconds: once this much time has passed, no new case is started (at least one
  //    case runs); the verdict says how many of the planned cases ran;
  //  - shrink_budget_seconds: once this much time has passed since a failure was found, shrinking
  //    stops; the counterexample is the smallest failing case found by then, and the verdict says so.
  // 0: no budget (ctest's reference runs and negative controls).
  double case_budget_seconds = 0;
  double shrink_budget_seconds = 0;
  // The subject runs out of process (behind the protocol): every step is a round trip, so a long
  // run of a claim nobody made is characterised over a shorter run, and its finding says it is not
  // the evidence that would verify the claim. In process, it is run in full.
  bool out_of_process = false;
};

// The CPU seconds of the code under test so far: the clock of the case and shrink budgets (issue
// 47: a busy machine does not cut a check's cases; the work done does). By default this process's
// CPU; an implementation behind the protocol adds its server's (harness/remote/remote_subject.cpp).
void set_code_cpu_clock(std::function<double()> clock);
double code_cpu_seconds();

// The options of the property run in progress on this thread (set by run_property): what a
// property may adapt to, such as RunOptions::out_of_process.
const RunOptions& current_run_options();

// Runs `p` on `subject` in scalar `k`: one verdict, or one per integrator for
// integrator-scoped properties (a subject with no integrator gets one NOT PROVIDED verdict).
std::vector<Verdict> run_property(const Property& p, const SubjectSet& subject, ScalarKind k,
                                  const RunOptions& options = {});

// Seed used for a given property key and base seed (deterministic, independent of the subject so
// every subject of a class sees the same inputs).
std::uint64_t derive_seed(std::uint64_t base, const std::string& property_key);

// Whether the integrator claims any of `judged` (claim names: "order", "casimir", ...).
bool claims_any(const IntegratorClaims& c, const std::vector<std::string>& judged);

// Human-readable verdict, several lines for anything but a pass.
std::string format_verdict(const Verdict& v);

// Whether `text` is a RapidCheck reproduce string (the value printed after "reproduce="); when it
// is not, `why` says what is wrong with it.
bool is_reproduce_string(const std::string& text, std::string* why = nullptr);

// The command line that replays a failing verdict through the `geomech` tool.
std::string reproduce_command(const Verdict& v);

// A counterexample's values are named by the notes' symbols where the property drew them with a
// name (gen(...).as("Pi"): "Pi = [...]"), by their type otherwise ("Vec3<double> = [...]").
// True when every value has a name; the heading then says so.
bool counterexample_by_name(const Verdict& v);
// True when the failure message already shows the inputs by the notes' names (showing_inputs):
// the reports then leave RapidCheck's list of drawn values out, as it says the same less clearly.
bool inputs_in_message(const Verdict& v);
// "counterexample (shrunk), by the notes' names:" and its variants, for the text reports.
std::string counterexample_heading(const Verdict& v);

}  // namespace gm
