// harness/trajectories/: the trajectory reader and its error messages.
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

// ---- trajectory files --------------------------------------------------------------------------

const char* kGood =
    "# geomech-trajectory 1\n"
    "# system: rigid_body\n"
    "# inertia: 2 1.5 1\n"
    "# step: 0.1\n"
    "## a free comment\n"
    "0 0.6 0 0.8\n"
    "0.1 0.6 0.01 0.8\n";

std::string bad(const std::string& text, const TrajectoryParams& params = {}) {
  try {
    parse_trajectory(text, "t.txt", params);
  } catch (const TrajectoryError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(TrajectoryFiles, ReadsTheDocumentedFormat) {
  const Trajectory t = parse_trajectory(kGood, "t.txt");
  EXPECT_EQ(t.rows.size(), 2u);
  EXPECT_FALSE(t.has_O);
  EXPECT_EQ(t.inertia[1], "1.5");
  EXPECT_EQ(t.step, 0.1);
  // Headerless CSV (MATLAB's writematrix) with the parameters on the command line, CRLF endings.
  TrajectoryParams p;
  p.system = "rigid_body";
  p.inertia = std::array<std::string, 3>{"2", "1.5", "1"};
  p.step = "0.1";
  const Trajectory csv =
      parse_trajectory("0,0.6,0,0.8,1,0,0,0,1,0,0,0,1\r\n0.1,0.6,0,0.8,1,0,0,0,1,0,0,0,1\r\n", "m.csv", p);
  EXPECT_TRUE(csv.has_O);
  EXPECT_EQ(csv.rows[1].O[8], 1.0);
}

TEST(TrajectoryFiles, EveryMalformedInputIsRejectedWithFileLineAndColumn) {
  const std::string head = "# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 1.5 1\n# step: 0.1\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "t.txt: the file is empty"},
      {"\n  \n", "t.txt: the file is empty"},
      {head, "t.txt: no data rows"},
      {head + "0 1 0 0\n", "t.txt: only one data row"},
      {head + "0 1 0 0\n0.1 1 0\n", "t.txt:6: a row has 3 fields, expected 4 like the rows above"},
      {head + "0 1 0 0\n0.1 1 0 0 5\n", "t.txt:6: a row has 5 fields, expected 4"},
      {head + "0 1 0 0\n0.1 1 zero 0\n", "t.txt:6:7: Pi2 is not a number: 'zero'"},
      {head + "0 1 0 0\n0.1 1 nan 0\n", "t.txt:6:7: Pi2 is NaN"},
      {head + "0 1 0 0\n0.1 -inf 0 0\n", "t.txt:6:5: Pi1 is infinite"},
      {head + "0 1 0 0\n0.1 1e300 0 0\n", "t.txt:6:5: Pi1 = 1e300 is an absurd magnitude"},
      {head + "0 1 0 0\n0.1 1e999 0 0\n", "t.txt:6:5: Pi1 '1e999' is out of the range of a double"},
      {head + "0 1 0 0\n0 1 0 0\n", "t.txt:6:1: t = 0 does not increase"},
      {head + "0 1 0 0\n0.1 1.0.0 0 0\n", "t.txt:6:5: Pi1 is not a number: '1.0.0'"},
      {"# geomech-trajectory 2\n", "t.txt:1: unsupported format line"},
      {"# geomech-trajectory 1\n# sytem: rigid_body\n", "t.txt:2:3: unknown header field 'sytem'"},
      {"# geomech-trajectory 1\n# system: pendulum\n# inertia: 1 1 1\n# step: 1\n0 1 0 0\n1 1 0 0\n",
       "t.txt:2: unknown system 'pendulum' (known: rigid_body)"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# step: 0.1\n0 1 0 0\n1 1 0 0\n", "t.txt: no inertia"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 1.5\n", "t.txt:3:12: inertia needs 3 numbers"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 -1 1\n# step: 0.1\n0 1 0 0\n1 1 0 0\n",
       "t.txt:3: the moments of inertia must be positive, got I2 = -1"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 0 1\n# step: 0.1\n0 1 0 0\n1 1 0 0\n",
       "must be positive, got I2 = 0"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 1.5 1\n# step: 0\n0 1 0 0\n1 1 0 0\n",
       "t.txt:4: the step size must be positive"},
      {"# geomech-trajectory 1\n# step: 0.1\n# step: 0.2\n", "t.txt:3:3: header field 'step' is given twice"},
      {"# geomech-trajectory 1\n# just words\n", "t.txt:2:3: a header line must be '# key: value'"},
      {"# geomech-trajectory 1\n# columns: t x y z\n", "t.txt:2:12: columns must be"},
      {head + "# columns: t Pi1 Pi2 Pi3\n0 1 0 0 1 0 0 0 1 0 0 0 1\n",
       "t.txt:6: a row has 13 fields, expected 4 like the columns line"},
      {"0 1 0 0\n1 1 0 0\n", "t.txt: no system"},
      {std::string("0 1\0 0 0\n", 10), "not a text file"},
      {"# geomech-trajectory 1\n# system: rigid_body\n# inertia: 1 0.5 0.3333333333333333\n# step: 0.1\n0 1 0 0\n1 1 0 "
       "0\n",
       "t.txt:3: I1 is larger than the sum of the other two moments: no rigid body has this inertia (give "
       "--allow-nonphysical"},
      {head + "0 0 0 0\n0.1 0 0 0\n", "t.txt:5: Pi(0) = 0: zero angular momentum"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string got = bad(text);
    EXPECT_NE(got.find(expected), std::string::npos) << "input:\n"
                                                     << text << "\nexpected: " << expected << "\ngot: " << got;
  }
  TrajectoryParams p;
  p.step = "0.2";
  EXPECT_NE(bad(kGood, p).find("t.txt:4: step in the file differs from --step"), std::string::npos) << bad(kGood, p);
}

// The notes' example body (no mass distribution has it) is checked when asked to, with a warning.
TEST(TrajectoryFiles, NonphysicalInertiaIsCheckedWhenAllowed) {
  const std::string text =
      "# geomech-trajectory 1\n# system: rigid_body\n# inertia: 1 0.5 0.3333333333333333\n# step: 0.1\n0 1 0 0\n1 1 0 "
      "0\n";
  TrajectoryParams p;
  p.allow_nonphysical = true;
  const Trajectory t = parse_trajectory(text, "t.txt", p);
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("no rigid body has this inertia"), std::string::npos) << t.warnings[0];
}

}  // namespace
}  // namespace gm::harness
