// `geomech mutants` (mutation/): the operators make the expected mutants, a plainly wrong mutant is
// killed, and a mutant listed as equivalent is left out of the score.
#include "impl/reference_subject.hpp"
#include "mutation/catalogue.hpp"
#include "mutation/kill_matrix.hpp"
#include "mutation/runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

const gm::mutation::MutantDef* find(const std::vector<gm::mutation::MutantDef>& all, const std::string& name) {
  auto it = std::find_if(all.begin(), all.end(), [&](const auto& m) { return m.name == name; });
  return it == all.end() ? nullptr : &*it;
}

TEST(Mutation, OperatorsMakeTheExpectedMutants) {
  const auto all = gm::mutation::all_mutants(gm::reference_subject());
  const auto* swap = find(all, "momentum_map:swap_args");
  ASSERT_NE(swap, nullptr);
  EXPECT_EQ(swap->slot, "momentum_map");
  EXPECT_EQ(swap->op_class, "swap_args");
  for (const char* n : {"momentum_map:negate_result", "momentum_map:double_result", "momentum_map:halve_result",
                        "momentum_map:permute_result", "momentum_map:permute_arg_0", "momentum_map:tiny_guard",
                        "momentum_map:axis_branch_arg_1", "momentum_map:precision_lowered", "hat:transpose_result",
                        "canonical_bracket:swap_args_0_3", "rk4:rigid_body_step:drop_attitude",
                        "implicit_midpoint:manakov_step:h_perturbed"})
    EXPECT_NE(find(all, n), nullptr) << n;
  EXPECT_EQ(find(all, "momentum_map:transpose_result"), nullptr);  // a Vec3 result has no transpose
  EXPECT_EQ(find(all, "pairing:permute_result"), nullptr);         // nor a scalar a permutation
  // Every hand-written negative control is a mutant of class handwritten.
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [](const auto& m) { return m.op_class == "handwritten"; }));

  // The reference is J = p x q; the mutant returns q x p, in the full subject and alone.
  const gm::Vec3<double> q(1, 2, 3), p(-2, 0.5, 4);
  const gm::SubjectSet full = swap->full(gm::reference_subject());
  EXPECT_EQ(full.d->momentum_map(q, p), q.cross(p));
  EXPECT_EQ(gm::reference_subject().d->momentum_map(q, p), p.cross(q));
  const gm::SubjectSet alone = swap->alone(gm::reference_subject());
  EXPECT_EQ(alone.d->momentum_map(q, p), q.cross(p));
  EXPECT_FALSE(alone.d->provides("hat"));
  EXPECT_TRUE(alone.d->provides("momentum_map"));
  EXPECT_TRUE(full.d->provides("hat"));
  const gm::Vec3<gm::Rational> qq(1, 2, 3), pp(-2, 5, 4);
  EXPECT_EQ(alone.q->momentum_map(qq, pp), gm::Vec3<gm::Rational>(qq.cross(pp)));
}

TEST(Mutation, NegatedHatIsKilledInBothModes) {
  gm::mutation::MutantsOptions o;
  o.mutant = "hat:negate_result";
  o.case_factor = 0.1;
  const auto run = gm::mutation::run_mutants(o);
  ASSERT_EQ(run.results.size(), 1u);
  EXPECT_TRUE(run.results[0].full.killed) << run.results[0].full.killed_by;
  EXPECT_TRUE(run.results[0].alone.killed) << run.results[0].alone.killed_by;
  EXPECT_EQ(gm::mutation::tally(run, false).killed, 1);
}

TEST(Mutation, EquivalentMutantIsNotCounted) {
  gm::mutation::MutantsOptions o;
  o.mutant = "pairing:swap_args";
  o.case_factor = 0.1;
  const auto run = gm::mutation::run_mutants(o);
  ASSERT_EQ(run.results.size(), 1u);
  EXPECT_TRUE(run.results[0].equivalent);
  EXPECT_FALSE(run.results[0].equivalence_argument.empty());
  const auto t = gm::mutation::tally(run, false);
  EXPECT_EQ(t.equivalent, 1);
  EXPECT_EQ(t.killed + t.survived, 0);
  EXPECT_EQ(t.score(), 1.0);                     // nothing left in the denominator
  EXPECT_TRUE(run.unknown_equivalents.empty());  // every listed name is a real mutant
}

}  // namespace

// The 50-digit runs left to --thorough never lose a kill. Of two costly 50-digit checks
// killing the same mutant, the costlier waits and the cheaper is kept; one killing a mutant no
// other check kills is kept; a cheap one is never a candidate.
TEST(Mutation, RunsLeftToThoroughKeepEveryKill) {
  using namespace gm::mutation;
  MutantsRun run;
  run.options.matrix = true;
  auto mutant = [&](const std::string& name, std::map<std::string, std::pair<bool, double>> cells) {
    MutantResult r;
    r.name = name;
    r.full.ran = true;
    r.full.killed = true;
    r.full.cells = std::move(cells);
    run.results.push_back(r);
  };
  mutant("m1", {{"a/mp50", {true, 2.0}}, {"b/double", {true, 0.01}}, {"e/mp50", {false, 1.0}}});
  mutant("m2", {{"c/mp50", {true, 1.0}}, {"b/double", {false, 0.01}}});
  mutant("m3", {{"d/mp50", {true, 0.01}}});
  mutant("m4", {{"x/mp50", {true, 3.0}}, {"y/mp50", {true, 0.5}}});
  const ThoroughOnly t = choose_thorough_only(run, 0.05);
  std::vector<std::string> left;
  for (const auto& c : t.checks) left.push_back(c.check);
  EXPECT_EQ(left, (std::vector<std::string>{"x/mp50", "a/mp50", "e/mp50"}));
  EXPECT_EQ(t.candidates, 5);  // a, c, e, x, y
  EXPECT_EQ(t.killable, 4);
  EXPECT_EQ(t.killed_by_kept, 4);
  const auto j = thorough_only_json(t, run);
  EXPECT_EQ(j.at("checks").size(), 3u);
  EXPECT_EQ(j.at("format"), "geomech-thorough-only 1");
}

// The protocol, measured too: a mutant killed in-process but not through the protocol (or the reverse) is
// named as a difference, and the score through the protocol counts what the protocol run killed.
TEST(Mutation, AVerdictThatDiffersThroughTheProtocolIsNamed) {
  using namespace gm::mutation;
  MutantsRun run;
  auto mutant = [&](const std::string& name, bool in_process, bool through) {
    MutantResult r;
    r.name = name;
    r.full.ran = r.protocol.ran = true;
    r.full.killed = in_process;
    r.protocol.killed = through;
    run.results.push_back(r);
  };
  mutant("same", true, true);
  mutant("lost", true, false);
  const Tally t = tally_protocol(run);
  EXPECT_EQ(t.mutants, 2);
  EXPECT_EQ(t.killed, 1);
  const auto d = protocol_differences(run);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "lost: killed in-process, not through the protocol");
}
