// The harness: every registered property against one subject (the reference, a negative
// control, or someone else's implementation), each (property, scalar, integrator) isolated in
// its own child process, gathered into a CheckResult that the report writers turn into
// Markdown, JUnit XML, JSON and the console summary.
//
// Nothing is silently skipped: a property whose slots the subject does not fill, or which runs
// in a scalar the subject has no instantiation for, gets a NOT PROVIDED verdict with the reason.
#pragma once

#include "harness/checking/check_events.hpp"
#include "harness/checking/first_fix.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/languages/language.hpp"
#include "harness/languages/notebook.hpp"
#include "properties/runner.hpp"

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gm::harness {

// What is known about a subject beyond its slots: where it comes from and why parts of it are
// missing (a scalar it could not be compiled for, a slot that did not compile in a scalar, ...).
struct SubjectInfo {
  std::string source;            // the student's file, when there is one
  std::string reproduce_prefix;  // the command that re-runs this check, e.g. "./geomech check my.cpp"
  std::map<std::string, std::string> scalar_unavailable;                 // scalar -> reason
  std::map<std::string, std::map<std::string, std::string>> slot_notes;  // scalar -> slot -> reason
  std::vector<std::string> warnings;                                     // shown at the top of the report
  // What the implementation wrote but the suite could not check (an integrator whose step has
  // the wrong signature, a slot function that cannot be called as the slot expects). Each one
  // fails the check: a claim that could not be checked is not a pass.
  std::vector<std::string> unchecked;
  bool randomised = true;  // verdicts come from random cases (seeds, replay by --property); false for trajectory files
  // An implementation running out of process (harness/remote/remote_subject.hpp) keeps one server per
  // worker slot of the isolation (harness/isolation/isolate.hpp) and is told when each slot starts and ends a
  // check; empty for subjects linked in.
  std::function<void(int)> prepare_worker;
  std::function<void(int, bool)> worker_done;
  // The CPU and run-queue delay the implementation's server for worker slot w has had so far (its
  // process tree): a check's limit counts the code's CPU, wherever it runs, and tells a starved
  // server from a sleeping one. Empty in process.
  std::function<harness::TreeTimes(int)> worker_times;
  // The language of the implementation (harness/languages/language.hpp): the report names the
  // function to fix in it ("Python function `casimir` in mine.py", or the slot in the suite's own),
  // writes values as it writes them, and its checks get longer by default (timeout_factor).
  const Language* language = &suite_language();
  // A notebook (harness/languages/notebook.hpp): its code cells as they run, which the source readers
  // read and the first fix names ("cell 4, In [3], line 2"), and what of it runs and what does not,
  // in words, for the report. Empty for any other implementation.
  std::vector<CodeCell> cells;
  std::string notebook;
  // Behind the protocol (harness/remote/remote_subject.hpp): every slot call is a round trip to another
  // process, so the costly 50-digit runs of spec/thorough_only.json wait for --thorough.
  bool out_of_process = false;
  // The interpreter that ran a Python or Octave implementation, and its version ("/usr/bin/python3,
  // Python 3.11.2"), for the report.
  std::string interpreter;
};

// When --timeout is not given, the checks of an implementation in an interpreted language get its
// row's multiple of the default timeout (Language::timeout_factor, and why). The case budget is not
// scaled, so a check still starts no new case after it.
inline double timeout_factor(const SubjectInfo& info) { return info.language->timeout_factor; }

struct CheckConfig {
  std::vector<std::string> properties;  // only these (empty: all)
  std::string spec_prefix;              // only properties whose spec entry starts with this
  std::vector<ScalarKind> scalars{ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact};
  std::string integrator;             // only this integrator (empty: all)
  std::set<std::string> only_checks;  // only these "property/scalar" (empty: all): --quick
  std::string selection_note;         // said with the selection (the quick profile's provenance)
  // Left out and listed as such ("property/scalar"): the costly 50-digit runs an implementation
  // behind the protocol leaves to --thorough (harness/checking/thorough_only.hpp), and why.
  std::set<std::string> thorough_only;
  std::string thorough_only_note;
  // Why run.case_factor is below 1 when the user did not choose it (the matrix's factor, for an
  // implementation behind the protocol); empty otherwise.
  std::string case_factor_note;
  RunOptions run;               // seed, case counts, reproduce string
  double timeout_seconds = 60;  // per (property, scalar, integrator)
  bool timeout_given = false;   // --timeout was given: timeout_factor() does not apply
  int jobs = 1;                 // children at once
  bool isolate = true;          // fork per property (false: in-process, for a debugger)
  long memory_limit_mb = 4096;
  bool portraits = true;  // integrator pictures (convergence, invariants) besides the verdicts
  // Non-empty: the work-precision diagram is not drawn, and this says why (behind the protocol its
  // cost axis would time the round trips; --thorough draws it).
  std::string work_precision_left_out;
  // Told as each check starts and ends (check_events.hpp); not owned.
  std::vector<CheckListener*> listeners;
  // The checks that failed in the previous run of the same report ("property/scalar" or
  // "property/scalar/integrator", check_key): they run first, so that a re-run says within about
  // a second whether each is fixed (like Hypothesis's example database).
  std::set<std::string> failed_before;
};

// "property/scalar[/integrator]": a check's name across runs (CheckConfig::failed_before).
std::string check_key(const Verdict& v);

// The checks of the report in `dir` (its verdicts.json) that failed, crashed, timed out or could not
// run; empty when there is no readable report there.
std::set<std::string> failed_checks_in_report(const std::string& dir);

// What a claim of an integrator is found to be, decided once from the verdicts of the checks that
// judge it (harness/checking/integrator_verdicts.hpp); every view (the console's claims block,
// report.md, verdicts.json, the class summary, the gradebook) shows this record.
enum class ClaimStatus {
  Verified,         // claimed: every check that judges it ran all its cases and passed
  FalseClaim,       // claimed: a complete measurement contradicts it
  NotVerified,      // claimed: a check it rests on could not decide (the step raised, a crash, cut cases)
  NotRun,           // claimed: no check that judges it ran in this run (a selection, --thorough)
  NotChecked,       // claimed: no property judges it for this integrator's steps
  Holds,            // not claimed: the evidence that would verify it if claimed
  DoesNotHold,      // not claimed: a complete measurement shows it does not hold
  NotEstablished,   // not claimed: the evidence is incomplete
  Measured,         // the order, not claimed: measured, and the step converges
  DoesNotConverge,  // the order, not claimed: the step does not converge (its checks FAIL)
  None,             // not claimed, and nothing judges it for this integrator
};

struct ClaimDecision {
  std::string claim;
  std::string claimed;  // "2" for an order, "yes" / "no"
  ClaimStatus status = ClaimStatus::None;
  std::string word;                   // what every view shows: "verified", "FALSE CLAIM", "holds (not claimed)", ...
  std::string measured;               // in a few words: "order 1.00 (double), 1.00 (mp50)"; may be empty
  std::string why;                    // what kept it from being decided (NotVerified, NotEstablished, NotRun)
  std::vector<std::string> evidence;  // "double, integrator_order: ...", one per finding
};

struct IntegratorInfo {
  std::string name;
  bool has_claims = false;
  IntegratorClaims claims;
  std::vector<std::string> steps;        // "rigid_body_step", "manakov_step"
  std::vector<std::string> scalars;      // the scalars it is instantiated in
  StateForm form;                        // the form it keeps the rigid body's state in (core/state_form.hpp)
  std::vector<ClaimDecision> decisions;  // decided at the end of the check (harness/checking/integrator_verdicts.hpp)
  // The precision its checks judged it at (properties/support/step_precision.hpp), from its verdicts:
  // "float" with how it is known ("stated: ...", "detected: ..."); empty when it computes in its scalar.
  std::string judged_precision, judged_precision_how;
};

struct CheckResult {
  std::string subject;
  std::string description;
  SubjectInfo info;
  std::uint64_t seed = 0;
  std::string selection;          // the property selection, in words ("all properties", "--property x")
  std::vector<Verdict> verdicts;  // sorted by property, then scalar (double, mp50, exact), then integrator
  std::map<std::string, std::vector<std::string>> provided;  // scalar -> slots it fills
  std::vector<IntegratorInfo> integrators;
  std::vector<Verdict> portraits;  // integrator pictures: verdict-shaped carriers of figure series
  double seconds = 0;
  bool narrowed = false;  // a selection of properties, scalars or integrators, not the whole suite
  // Checks this run left to --thorough ("property [mp50]"), and why (CheckConfig::thorough_only).
  std::vector<std::string> left_to_thorough;
  std::string thorough_only_note;
  // The share of each property's cases this run made when it is below 1 because of
  // CheckConfig::case_factor_note (0: every case), and why.
  double case_factor = 0;
  std::string case_factor_note;
  std::string work_precision_left_out;  // CheckConfig::work_precision_left_out, when it applied

  // Which properties exercised each provided slot ("integrator NAME" for an integrator's step):
  // the properties that ran (not NOT PROVIDED) and need it.
  std::map<std::string, std::vector<std::string>> exercised;
  // Provided slots and integrators that no property exercised (warnings, never silence).
  std::vector<std::string> unexercised;
  // Everything that could not be checked: SubjectInfo::unchecked, plus claims no property checked
  // in a full run. Non-empty means the check fails.
  std::vector<std::string> unchecked;
  // The slots to fix first, decided once when the verdicts are complete (decide_first_fixes,
  // harness/checking/first_fix.hpp); every view renders them.
  RootCauses first_fixes;

  int count(Outcome o) const;
  int ran() const;  // verdicts that are not NOT PROVIDED
  // No FAIL, CRASH, TIMEOUT or ERROR, at least one check ran, and nothing was left unchecked:
  // a run that checked nothing is not a pass.
  bool ok() const;
  // PASS, FAIL, NOTHING CHECKED or UNCHECKED (what the console, report and class table say).
  std::string verdict_word() const;
  // 0 when ok(), 1 when not; 3 (kExitMachine, harness/isolation/sandbox.hpp) when a check ended in
  // the machine's ERROR (a verdict's machine_fault), whatever else it found: the run is incomplete
  // because of the grader's machine, as every command says with that status.
  int exit_code() const;
};

CheckResult run_check(const SubjectSet& subject, const SubjectInfo& info, const CheckConfig& config);

// The command that replays one verdict (`prefix --property p --scalar s [--integrator i] ...`).
std::string reproduce_command(const CheckResult& r, const Verdict& v);

// Scalars in a stable order, and back from names.
int scalar_rank(const std::string& scalar);
std::optional<ScalarKind> scalar_from_name(const std::string& name);

}  // namespace gm::harness
