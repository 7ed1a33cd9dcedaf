// harness/trajectories/: the 50-digit reference flow.
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

// ---- the reference flow -----------------------------------------------------------------------

TEST(ReferenceFlow, AgreesWithTheSymmetricTopInClosedForm) {
  // I1 = I2: Pi3 is constant and (Pi1, Pi2) turns at the rate nu = Pi3 (1/I3 - 1/I1):
  // dPi1/dt = Pi2 Pi3 (1/I3 - 1/I2) = nu Pi2, dPi2/dt = -nu Pi1.
  using R = Real50;
  const Vec3<R> I(R(2), R(2), R(1));
  const RigidBodyState<R> x0{Vec3<R>(R(3) / R(5), R(0), R(4) / R(5)), Mat3<R>::Identity()};
  std::vector<R> times;
  for (int k = 1; k <= 10; ++k) times.push_back(R(k));
  const auto xs = reference_rigid_body(I, x0, R(0), times);
  const R nu = x0.Pi(2) * (R(1) / I(2) - R(1) / I(0));
  R worst(0), orth(0);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const R t = times[k];
    const Vec3<R> exact(x0.Pi(0) * cos(nu * t), -x0.Pi(0) * sin(nu * t), x0.Pi(2));
    worst = std::max(worst, max_abs((xs[k].Pi - exact).eval()));
    orth = std::max(orth, max_abs((xs[k].O.transpose() * xs[k].O - Mat3<R>::Identity()).eval()));
  }
  EXPECT_LT(worst, R(1e-42)) << to_string_full(worst);
  EXPECT_LT(orth, R(1e-42)) << to_string_full(orth);
}

TEST(ReferenceFlow, KeepsTheInvariantsOfATriaxialBodyAndRefusesNonsense) {
  using R = Real50;
  const Vec3<R> I(R(2), R(1), R(2) / R(3));
  const RigidBodyState<R> x0{Vec3<R>(R(9) / R(20), R(1) / R(10), R(89) / R(100)), Mat3<R>::Identity()};
  const auto xs = reference_rigid_body(I, x0, R(0), {R(20)});
  const auto h = [&](const Vec3<R>& P) {
    return (P(0) * P(0) / I(0) + P(1) * P(1) / I(1) + P(2) * P(2) / I(2)) / R(2);
  };
  EXPECT_LT(abs(R(xs[0].Pi.squaredNorm() - x0.Pi.squaredNorm())), R(1e-42));
  EXPECT_LT(abs(R(h(xs[0].Pi) - h(x0.Pi))), R(1e-42));
  // Noether: pi = O Pi is constant.
  EXPECT_LT(max_abs((xs[0].O * xs[0].Pi - x0.Pi).eval()), R(1e-42));
  EXPECT_THROW(reference_rigid_body(Vec3<R>(R(1), R(0), R(1)), x0, R(0), {R(1)}), std::invalid_argument);
  EXPECT_THROW(reference_rigid_body(I, x0, R(0), {R(2), R(1)}), std::invalid_argument);
  ReferenceLimits tight;
  tight.max_steps = 3;
  EXPECT_THROW(reference_rigid_body(I, x0, R(0), {R(100)}, tight), std::length_error);
}

}  // namespace
}  // namespace gm::harness
