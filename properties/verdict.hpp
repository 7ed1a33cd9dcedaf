// A verdict: what one property found of one subject in one scalar (and one integrator), decided once
// by the runner (properties/runner.hpp) and rendered by every report: its outcome, its message, the
// shrunk counterexample at full precision, the seed and reproduce string, the worst residual seen
// (in units of eps * scale), the claims it judged and where its time went.
#pragma once

#include "properties/support/claims.hpp"
#include "properties/support/figures.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gm {

// NotCharacterised: an integrator property that judges only claims nobody made could
// measure nothing (the step raised); it neither passes nor fails the check.
enum class Outcome { Pass, Fail, NotProvided, Crash, Timeout, Error, NotCharacterised };
const char* outcome_name(Outcome o);

// Where a check's time goes through the protocol (docs/PERFORMANCE.md): the calls a property made
// of an implementation behind it, the round trips they took (a call answered from memory takes
// none; a run of steps takes one), and the wall seconds spent waiting for the replies. Counted by
// the protocol's connection in this process; a property's share is the difference over its run.
struct ProtocolCounts {
  long calls = 0, round_trips = 0, memo_hits = 0;
  double waiting_seconds = 0;
};
ProtocolCounts& protocol_counts();

struct Verdict {
  std::string subject;
  std::string property;
  std::string spec;
  std::string title;
  std::string scalar;
  std::string integrator;  // for integrator-scoped properties
  Outcome outcome = Outcome::Error;
  std::string message;
  std::vector<std::pair<std::string, std::string>> counterexample;  // (type, value)
  std::string reproduce;                                            // value for RC_PARAMS="reproduce=..."
  std::uint64_t seed = 0;
  int cases = 0;          // cases that passed before the verdict
  int cases_planned = 0;  // the cases the run asked for; more than `cases` on a PASS when the case budget was spent
  bool shrink_stopped = false;  // FAIL: shrinking was stopped by its time budget (the counterexample is not minimal)
  int discarded = 0;            // cases RapidCheck discarded (RC_DISCARD, RC_PRE): they checked nothing
  std::string discard_reason;   // the first discarded case's reason
  double worst_eps_units = 0;   // worst residual / (eps * scale)
  double worst_absolute = 0;
  std::string worst_check;
  long checks = 0;
  double seconds = 0;
  // Where the time went (docs/PERFORMANCE.md): this property's protocol counts, the CPU seconds of
  // the code under test (an implementation behind the protocol: its server's) and of the suite.
  ProtocolCounts protocol;
  double code_cpu_seconds = 0, suite_cpu_seconds = 0;
  std::vector<Series> series;        // data for pictures, from the last case run
  std::vector<std::string> notes;    // remarks from the last case run (e.g. an unclaimed invariant that holds)
  std::vector<ClaimFinding> claims;  // integrator properties: what they found about each claim
  // Integrator properties: the step raised in the case this verdict reports: its message
  // and where it was called; empty otherwise.
  std::string step_raised;
  std::string step_raised_where;
  double step_raised_rate = 0, step_raised_size = 0;  // |Omega| and |Pi| where it raised (not written out)
  // What every view shows for this verdict, decided once (harness/checking/integrator_verdicts.hpp): for an
  // integrator property, "PASS", "FALSE CLAIM", "holds (not claimed)", "does not hold (not claimed)",
  // "not established (not claimed): ...", "NOT CHARACTERISED"; empty for the others (the outcome).
  std::string word;
  // Who owns a not-pass: empty, the code under test (FAIL, CRASH, TIMEOUT, ...); otherwise the machine
  // or the set-up, and this says what went wrong and its fix ("the machine starved the check: ...").
  // Such an ERROR is never graded, never names a slot, and the check is run again once the
  // condition changes (DESIGN.md, "A cause is an experiment").
  std::string machine_fault;
  // Integrator properties: the precision the step was judged at when it is coarser than the scalar's
  // own ("float"), and how it is known ("stated: ...", "detected: ..."); empty otherwise
  // (properties/support/step_precision.hpp).
  std::string judged_precision, judged_precision_how;

  std::string key() const;  // subject/property/scalar[/integrator]: RapidCheck's test id
};

}  // namespace gm
