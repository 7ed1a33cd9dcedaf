// The integrator-claims machinery on the reference subject: a property that holds although it is
// not claimed passes with a note saying so; a claim that does not hold fails (the negative
// controls show that for every claim); an integrator with no claims at all is still measured.
#include "impl/reference_subject.hpp"
#include "properties/runner.hpp"

#include <gtest/gtest.h>

namespace gm {
namespace {

std::vector<Verdict> run_for(const SubjectSet& s, const char* property, ScalarKind k, const char* integrator) {
  const Property* p = find_property(property);
  EXPECT_NE(p, nullptr) << property;
  std::vector<Verdict> out;
  if (!p) return out;
  RunOptions o;
  o.honour_rc_params = false;
  for (auto& v : run_property(*p, s, k, o))
    if (v.integrator == integrator) out.push_back(v);
  return out;
}

bool has_note(const Verdict& v, const std::string& text) {
  for (const auto& n : v.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

TEST(IntegratorClaims, AnUnclaimedInvariantThatHoldsIsNoted) {
  SubjectSet s = reference_subject();
  s.name = "reference-without-claims";
  s.claims.clear();  // nothing claimed for any integrator
  for (ScalarKind k : {ScalarKind::Double, ScalarKind::MP50}) {
    const auto v = run_for(s, "integrator_casimir", k, "lie_poisson_splitting");
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].outcome, Outcome::Pass) << format_verdict(v[0]);
    EXPECT_TRUE(has_note(v[0], "holds although not claimed")) << format_verdict(v[0]);
  }
  // The energy is not kept by the splitting: no note, still a pass (nothing was promised).
  const auto e = run_for(s, "integrator_energy", ScalarKind::MP50, "lie_poisson_splitting");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].outcome, Outcome::Pass);
  EXPECT_FALSE(has_note(e[0], "holds although not claimed")) << format_verdict(e[0]);
  // The order is measured and reported even when not claimed.
  const auto o = run_for(s, "integrator_order", ScalarKind::Double, "rk4");
  ASSERT_EQ(o.size(), 1u);
  EXPECT_EQ(o[0].outcome, Outcome::Pass);
  EXPECT_TRUE(has_note(o[0], "no order claimed")) << format_verdict(o[0]);
  EXPECT_FALSE(o[0].series.empty());
}

TEST(IntegratorClaims, AFalseOrderClaimFails) {
  SubjectSet s = reference_subject();
  for (auto& c : s.claims)
    if (c.integrator == "rk4") c.order = 2;
  for (ScalarKind k : {ScalarKind::Double, ScalarKind::MP50}) {
    const auto v = run_for(s, "integrator_order", k, "rk4");
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].outcome, Outcome::Fail) << format_verdict(v[0]);
  }
}

TEST(IntegratorClaims, ConvergenceSeriesCarryTheClaimedSlope) {
  const auto v = run_for(reference_subject(), "integrator_order", ScalarKind::Double, "implicit_midpoint");
  ASSERT_EQ(v.size(), 1u);
  ASSERT_FALSE(v[0].series.empty());
  EXPECT_EQ(v[0].series[0].reference_slope, 2.0);
  EXPECT_TRUE(v[0].series[0].log_x && v[0].series[0].log_y);
  EXPECT_EQ(v[0].series[0].points.size(), 5u);
}

}  // namespace
}  // namespace gm
