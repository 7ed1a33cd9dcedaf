// harness/checking/: checking trajectory files (check_trajectories): refusals, the examples' verdicts,
// the order.
#include "harness/checking/check.hpp"
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/thorough_only.hpp"
#include "harness/checking/trajectory.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/program/build.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/svg.hpp"
#include "harness/trajectories/reference_flow.hpp"
#include "impl/reference_subject.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/loglog_fit.hpp"
#include "properties/support/tolerance.hpp"
#include "tests/support/ctest_script.hpp"

#include <gtest/gtest.h>

#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include "tests/harness/harness_support.hpp"

namespace gm::harness {
namespace {

namespace fs = std::filesystem;
using namespace harness_testing;

TEST(TrajectoryFiles, ARunTooLongForTheReferenceIsRefusedAtOnce) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "long.txt") << "# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 1.5 1\n# step: 1\n"
                                  << "0 1000 2000 3000\n1e9 1000 2000 3000\n";
  try {
    check_trajectories({(dir / "long.txt").string()}, {});
    ADD_FAILURE() << "accepted";
  } catch (const TrajectoryError& e) {
    // Refused by the estimate made before any step (harness/trajectories/reference_flow.cpp), not
    // by the solver's own limit once it has run out: no timing is asserted, the words say which.
    EXPECT_NE(std::string(e.what()).find("the reference solution would need about"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Taylor steps"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(TrajectoryFiles, NothingIsWrittenForBadInput) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "bad.txt") << "# geomech-trajectory 1\n# system: rigid_body\n";
  TrajectoryCheckOptions o;
  EXPECT_THROW(check_trajectories({(dir / "bad.txt").string()}, o), TrajectoryError);
  EXPECT_THROW(check_trajectories({(dir / "missing.txt").string()}, o), TrajectoryError);
  const auto entries = std::distance(fs::directory_iterator(dir), fs::directory_iterator{});
  EXPECT_EQ(entries, 1);
  fs::remove_all(dir);
}

std::string example(const std::string& name) { return std::string(GM_SOURCE_DIR) + "/examples/trajectories/" + name; }

TEST(TrajectoryFiles, TheExamplesAreJudgedAsTheirAuthorsShouldExpect) {
  TrajectoryCheckOptions o;
  o.order = 2;
  o.preserves = {"casimir", "energy", "orthogonality", "spatial_momentum"};
  const CheckResult good = check_trajectories({example("midpoint_h0.1.txt"), example("midpoint_h0.05.txt"),
                                               example("midpoint_h0.025.txt"), example("midpoint_h0.0125.txt")},
                                              o);
  EXPECT_TRUE(good.ok()) << console_report(good, nullptr);
  const Verdict* order = nullptr;
  for (const auto& v : good.verdicts)
    if (v.property == "trajectory_order") order = &v;
  ASSERT_NE(order, nullptr);
  EXPECT_NE(order->message.find("measured slope 2"), std::string::npos) << order->message;

  o.order = 4;  // a false order claim
  const CheckResult wrong_order = check_trajectories({example("midpoint_h0.1.txt"), example("midpoint_h0.05.txt")}, o);
  EXPECT_EQ(wrong_order.count(Outcome::Fail), 1) << console_report(wrong_order, nullptr);

  TrajectoryCheckOptions euler;
  euler.preserves = {"casimir"};
  const CheckResult e = check_trajectories({example("explicit_euler_h0.01.txt")}, euler);
  EXPECT_EQ(e.count(Outcome::Fail), 1) << console_report(e, nullptr);
  for (const auto& v : e.verdicts)
    if (v.outcome == Outcome::Fail) {
      EXPECT_EQ(v.property, "trajectory_casimir");
    }

  const CheckResult sign = check_trajectories({example("sign_error_h0.01.txt")}, {});
  EXPECT_EQ(sign.count(Outcome::Fail), 1);
  for (const auto& v : sign.verdicts)
    if (v.outcome == Outcome::Fail) {
      EXPECT_EQ(v.property, "trajectory_reference");
    }
}

// Lie-Euler on a spherical body is exact (its Omega never changes), so every error is at
// round-off. Its order-1 claim holds as "exact for this problem", not "not measurable"; the same
// files claimed at order 2 also pass (an exact step satisfies any order). Control: the midpoint
// files at a false order 4 still fail (above).
TEST(TrajectoryFiles, AnExactStepPassesAnyOrderClaim) {
  const std::vector<std::string> files{example("spherical_lie_euler_h0.1.txt"),
                                       example("spherical_lie_euler_h0.05.txt"),
                                       example("spherical_lie_euler_h0.025.txt")};
  for (int order : {1, 2}) {
    TrajectoryCheckOptions o;
    o.order = order;
    const CheckResult r = check_trajectories(files, o);
    EXPECT_TRUE(r.ok()) << console_report(r, nullptr);
    const Verdict* v = nullptr;
    for (const auto& x : r.verdicts)
      if (x.property == "trajectory_order") v = &x;
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->outcome, Outcome::Pass) << v->message;
    EXPECT_NE(v->message.find("exact for this problem (error at round-off for every step size)"), std::string::npos)
        << v->message;
    ASSERT_EQ(v->claims.size(), 1u);
    EXPECT_TRUE(v->claims[0].holds) << v->claims[0].evidence;
  }
}

TEST(TrajectoryFiles, ConvergenceSlopeLeavesOutTheRoundoffPlateau) {
  // The suite's one log-log fit (properties/support/loglog_fit.hpp), which check-trajectory uses.
  std::vector<double> hs, errs;
  for (double h = 0.1; h > 1e-6; h /= 2) hs.push_back(h), errs.push_back(std::max(3 * h * h, 1e-9));
  const std::vector<double> floors(hs.size(), 1e-8);
  const conv::SlopeFit fit = conv::loglog_slope(hs, errs, floors);
  ASSERT_TRUE(fit.measured());
  EXPECT_NEAR(fit.slope, 2.0, 1e-9);
  EXPECT_FALSE(fit.point.back());
  EXPECT_FALSE(conv::loglog_slope({0.1}, {1e-12}, {1e-8}).measured());
  // One plateau rule: round-off noise that rises above the floor again at a smaller step is still
  // the plateau. The control: fitted point by point, that noise would drag the slope far from 2.
  errs.back() = 1e-3;
  const conv::SlopeFit noisy = conv::loglog_slope(hs, errs, floors);
  EXPECT_NEAR(noisy.slope, 2.0, 1e-9);
  EXPECT_FALSE(noisy.point.back());
  std::vector<double> kept_h, kept_e;
  for (std::size_t i = 0; i < hs.size(); ++i)
    if (errs[i] > floors[i]) kept_h.push_back(hs[i]), kept_e.push_back(errs[i]);
  const conv::SlopeFit pointwise = conv::loglog_slope(kept_h, kept_e, std::vector<double>(kept_h.size(), 0.0));
  EXPECT_GT(std::abs(pointwise.slope - 2.0), 0.5) << "the control: a fit that keeps every point above the floor";
}

}  // namespace
}  // namespace gm::harness
