// The property runner's own bookkeeping (properties/runner.cpp). a discarded case is not
// a check, so a verdict counts its discarded cases and keeps the first reason (the verdict's JSON
// carries them: tests/harness/reports/report_tests.cpp).
#include "impl/reference_subject.hpp"
#include "properties/registry.hpp"
#include "properties/runner.hpp"
#include "properties/support/tolerance.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <ctime>

namespace gm {
namespace {

// The case and shrink budgets count the code's CPU time (a loaded machine does not spend
// them), so a slow case here computes for its time rather than sleeps.
void burn_cpu(double seconds) {
  const double start = code_cpu_seconds();
  volatile double x = 0;
  while (code_cpu_seconds() - start < seconds) x = x + 1;
}

// A property that discards about half of its draws and checks 1 = 1 on the others.
Property half_discarding() {
  Property p{PropertyDef{.id = "half_discarding",
                         .spec = "s2.hat-map",
                         .title = "a test property that discards every other case",
                         .tolerance = ToleranceClass::Exact,
                         .needs = {},
                         .negative_controls = {},
                         .cases = {.d = 40, .mp = 0, .q = 0}}};
  p.d = [](const Subject<double>&) {
    static int calls = 0;  // every other case (a size-independent rule: RapidCheck's first draws are small)
    if (calls++ % 2 == 0) RC_DISCARD("the draw was 0");
    require_close("1 = 1", 1.0, 1.0, 1.0, 1);
  };
  return p;
}

// The one verdict of `p` in double on the reference subject, RC_PARAMS ignored.
Verdict run_in_double(const Property& p, bool shrink = true) {
  RunOptions o;
  o.honour_rc_params = false;
  o.shrink = shrink;
  const auto vs = run_property(p, reference_subject(), ScalarKind::Double, o);
  EXPECT_EQ(vs.size(), 1u);
  return vs.empty() ? Verdict{} : vs[0];
}

TEST(Runner, DiscardedCasesAreCountedInTheVerdict) {
  const Verdict v = run_in_double(half_discarding());
  EXPECT_EQ(v.outcome, Outcome::Pass) << format_verdict(v);
  EXPECT_EQ(v.cases, 40);
  EXPECT_GT(v.discarded, 0) << "half of the draws are discarded";
  EXPECT_EQ(v.discard_reason, "the draw was 0");
  EXPECT_NE(format_verdict(v).find(std::to_string(v.discarded) + " discarded"), std::string::npos) << format_verdict(v);
}

// RC_PRE's discards are reported by the condition that did not hold (RapidCheck's own text for
// them is the macro and the values it expanded to).
TEST(Runner, APreconditionDiscardNamesItsCondition) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    static int calls = 0;
    const int parity = calls++ % 2;
    RC_PRE(parity == 1);
    require_close("1 = 1", 1.0, 1.0, 1.0, 1);
  };
  const Verdict v = run_in_double(p);
  EXPECT_EQ(v.outcome, Outcome::Pass) << format_verdict(v);
  EXPECT_GT(v.discarded, 0);
  EXPECT_EQ(v.discard_reason, "the precondition parity == 1 does not hold");
}

// The negative control: a property that discards nothing reports 0.
TEST(Runner, APropertyThatDiscardsNothingReportsNone) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) { require_close("1 = 1", 1.0, 1.0, 1.0, 1); };
  const Verdict v = run_in_double(p);
  EXPECT_EQ(v.discarded, 0);
  EXPECT_EQ(format_verdict(v).find("discarded"), std::string::npos);
}

// Negative controls run without shrinking (tests/property_tests.cpp): the failure is still a
// failure, found on the same first failing case, and only the shrinking is left out. The control: with
// shrinking, the same failure ends on the smallest failing value.
TEST(Runner, WithoutShrinkingAFailureStaysAFailure) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    const int k = *rc::gen::inRange(0, 1000);
    require("k < 10", k < 10, "k = " + std::to_string(k));
  };
  const Verdict unshrunk = run_in_double(p, false);
  const Verdict shrunk = run_in_double(p, true);
  ASSERT_EQ(unshrunk.outcome, Outcome::Fail) << format_verdict(unshrunk);
  ASSERT_EQ(shrunk.outcome, Outcome::Fail) << format_verdict(shrunk);
  EXPECT_EQ(unshrunk.cases, shrunk.cases) << "the same first failing case";
  EXPECT_NE(shrunk.message.find("k = 10"), std::string::npos) << shrunk.message;
  EXPECT_NE(unshrunk.message, shrunk.message) << "the first failing draw of 0..999 is not the smallest one";
}

// A value drawn with a name (gen.as("k")) is shown by that name, and the heading says
// the inputs are by the notes' names; the control: the same draw without a name is shown by its
// type, and the heading does not say so (tests/property_tests.cpp requires every negative control's
// failure to be of the first kind).
TEST(Runner, ACounterexampleDrawnWithNamesIsShownByThem) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    const int k = *rc::gen::inRange(0, 1000).as("k (the notes' symbol)");
    const double x = *rc::gen::just(0.5).as("x");
    require("k < 10", k < 10 || x != 0.5, "k = " + std::to_string(k));
  };
  const Verdict named = run_in_double(p);
  ASSERT_EQ(named.outcome, Outcome::Fail) << format_verdict(named);
  EXPECT_TRUE(counterexample_by_name(named)) << format_verdict(named);
  EXPECT_NE(format_verdict(named).find("by the notes' names:\n    k (the notes' symbol) = 10\n    x = 0.5"),
            std::string::npos)
      << format_verdict(named);

  p.d = [](const Subject<double>&) {
    const int k = *rc::gen::inRange(0, 1000);
    const double x = *rc::gen::just(0.5).as("x");
    require("k < 10", k < 10 || x != 0.5, "k = " + std::to_string(k));
  };
  const Verdict typed = run_in_double(p);
  ASSERT_EQ(typed.outcome, Outcome::Fail) << format_verdict(typed);
  EXPECT_FALSE(counterexample_by_name(typed)) << "one value has no name: " << format_verdict(typed);
  EXPECT_NE(format_verdict(typed).find("counterexample (shrunk):\n    int = 10"), std::string::npos)
      << format_verdict(typed);
}

// The case budget. A property whose cases take 20 ms of CPU each, with 40 planned and a budget of
// 0.1 s, passes on the cases it had time for (at least one), and says how many of how many. The
// control: without a budget all 40 run.
TEST(Runner, TheCaseBudgetStopsStartingCasesAndSaysHowMany) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    burn_cpu(0.020);
    require_close("1 = 1", 1.0, 1.0, 1.0, 1);
  };
  RunOptions o;
  o.honour_rc_params = false;
  o.case_budget_seconds = 0.1;
  const Verdict v = run_property(p, reference_subject(), ScalarKind::Double, o).at(0);
  EXPECT_EQ(v.outcome, Outcome::Pass) << format_verdict(v);
  EXPECT_GE(v.cases, 1);
  EXPECT_LT(v.cases, 40);
  EXPECT_EQ(v.cases_planned, 40);
  EXPECT_NE(format_verdict(v).find(std::to_string(v.cases) + " cases of 40 planned"), std::string::npos)
      << format_verdict(v);
  const Verdict all = run_in_double(p);
  EXPECT_EQ(all.cases, 40);
  EXPECT_EQ(all.cases_planned, 40);
  EXPECT_EQ(format_verdict(all).find("planned"), std::string::npos) << format_verdict(all);
}

// A case that fails is a failure even when the budget was spent while it ran: the budget only stops
// starting new cases after a pass, and the failure is shrunk as usual.
TEST(Runner, TheCaseBudgetDoesNotHideAFailure) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    burn_cpu(0.002);
    const int k = *rc::gen::inRange(5, 1000);
    require("k < 5", k < 5, "k = " + std::to_string(k));
  };
  RunOptions o;
  o.honour_rc_params = false;
  o.case_budget_seconds = 1e-6;  // spent before the first case ends: that case still counts
  const Verdict v = run_property(p, reference_subject(), ScalarKind::Double, o).at(0);
  EXPECT_EQ(v.outcome, Outcome::Fail) << format_verdict(v);
  EXPECT_NE(v.message.find("k = 5"), std::string::npos) << "shrunk as usual: " << v.message;
  EXPECT_FALSE(v.shrink_stopped);
}

// The shrink budget: a failure whose shrinking would take long (each try 30 ms of CPU) stops shrinking once
// the budget is spent and reports the smallest failing case found by then, with its inputs and its
// own message, said to be not minimal; replaying it (the reproduce string) fails again.
TEST(Runner, TheShrinkBudgetKeepsTheSmallestFailureFoundSoFar) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    burn_cpu(0.030);
    const int k = *rc::gen::inRange(0, 1000000);
    require("k < 10", k < 10, "k = " + std::to_string(k));
  };
  RunOptions o;
  o.honour_rc_params = false;
  o.shrink_budget_seconds = 0.1;
  const Verdict v = run_property(p, reference_subject(), ScalarKind::Double, o).at(0);
  ASSERT_EQ(v.outcome, Outcome::Fail) << format_verdict(v);
  EXPECT_TRUE(v.shrink_stopped);
  EXPECT_NE(v.message.find("k = "), std::string::npos) << v.message;
  EXPECT_EQ(v.message.find("RC_DISCARD"), std::string::npos)
      << "the failure's own text, not the budget's: " << v.message;
  ASSERT_FALSE(v.counterexample.empty()) << "the inputs of the failing case";
  const int k = std::stoi(v.counterexample.front().second);
  EXPECT_GE(k, 10) << "a failing input";
  EXPECT_NE(v.message.find("k = " + std::to_string(k)), std::string::npos) << "the inputs belong to the message";
  EXPECT_NE(format_verdict(v).find("not minimal"), std::string::npos) << format_verdict(v);
  // The replay runs the recorded case without shrinking: a failure with the same inputs.
  RunOptions replay;
  replay.honour_rc_params = false;
  replay.reproduce = v.reproduce;
  const Verdict again = run_property(p, reference_subject(), ScalarKind::Double, replay).at(0);
  EXPECT_EQ(again.outcome, Outcome::Fail) << format_verdict(again);
  EXPECT_EQ(again.message, v.message);
}

// A failure that depends on what the implementation kept from earlier calls (here a call
// counter: right for the first 5 calls of a process, wrong after) fails in a check, and its replay
// alone, in a fresh process (the counter reset), passes. The replay is then not an ERROR ("Reproduced
// result is not a failure") but runs the whole sequence again and fails, saying so; its replay is
// by seed (no reproduce string). Control: a failure that does not depend on state replays as usual.
int g_calls = 0;

TEST(Runner, AFailureThatNeedsEarlierCallsIsNamedAndReplaysTheSequence) {
  Property p = half_discarding();
  p.d = [](const Subject<double>&) {
    const int k = *rc::gen::inRange(0, 100);
    ++g_calls;
    require("the slot is right", g_calls <= 5, "k = " + std::to_string(k) + ", call " + std::to_string(g_calls));
  };
  RunOptions o;
  o.honour_rc_params = false;
  g_calls = 0;
  const Verdict v = run_property(p, reference_subject(), ScalarKind::Double, o).at(0);
  ASSERT_EQ(v.outcome, Outcome::Fail) << format_verdict(v);
  ASSERT_FALSE(v.reproduce.empty());
  RunOptions replay = o;
  replay.reproduce = v.reproduce;
  g_calls = 0;  // a fresh process
  const Verdict again = run_property(p, reference_subject(), ScalarKind::Double, replay).at(0);
  EXPECT_EQ(again.outcome, Outcome::Fail) << format_verdict(again);
  EXPECT_NE(again.message.find("not alone: the case replayed by itself passes, so the implementation keeps state "
                               "between calls"),
            std::string::npos)
      << again.message;
  // (the replay of the case alone was one call more, so the sequence fails a case earlier than before)
  EXPECT_NE(again.message.find("earlier cases of this check, not alone"), std::string::npos) << again.message;
  EXPECT_TRUE(again.reproduce.empty()) << "replayed by seed, the whole sequence";

  // The control: a stateless failure replays as itself, without the note.
  p.d = [](const Subject<double>&) {
    const int k = *rc::gen::inRange(0, 100);
    require("k < 50", k < 50, "k = " + std::to_string(k));
  };
  const Verdict w = run_property(p, reference_subject(), ScalarKind::Double, o).at(0);
  ASSERT_EQ(w.outcome, Outcome::Fail);
  replay.reproduce = w.reproduce;
  const Verdict w2 = run_property(p, reference_subject(), ScalarKind::Double, replay).at(0);
  EXPECT_EQ(w2.outcome, Outcome::Fail);
  EXPECT_EQ(w2.message.find("keeps state between calls"), std::string::npos) << w2.message;
}

}  // namespace
}  // namespace gm
