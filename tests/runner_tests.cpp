// The property runner's own bookkeeping (properties/runner.cpp). Issue 18: a discarded case is not
// a check, so a verdict counts its discarded cases and keeps the first reason (the verdict's JSON
// carries them: tests/harness_tests.cpp).
#include "impl/reference_subject.hpp"
#include "properties/registry.hpp"
#include "properties/runner.hpp"
#include "properties/support/tolerance.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

namespace gm {
namespace {

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

}  // namespace
}  // namespace gm
