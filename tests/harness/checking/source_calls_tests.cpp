// Who calls whom in a submission, read from its source: the first fix is the function
// whose own check fails, not one that calls it.
#include "harness/checking/first_fix.hpp"
#include "harness/checking/source_calls.hpp"
#include "harness/reports/report.hpp"

#include "tests/harness/harness_support.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace gm::harness;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return gm::testing_support::scratch_folder("calls", name); }
using gm::testing_support::write_file;

}  // namespace

TEST(SourceCalls, ACallerIsReadFromPythonOctaveAndCpp) {
  const std::string py =
      "def manakov_Omega(A, M):\n    \"\"\"not manakov_M(A, W) in a docstring\"\"\"\n    return solve(A, M)  # "
      "manakov_M( here\n\n"
      "def manakov_2_34(A, M):\n    W = manakov_Omega(A, M)\n    return madd(matmul(M, W), matmul(W, M), -1)\n";
  const auto p = slot_calls_in_text(py, *language_named("python"));
  EXPECT_EQ(p.count("manakov_Omega"), 0u);  // neither the docstring nor the comment is a call
  ASSERT_EQ(p.count("manakov_2_34"), 1u);
  EXPECT_EQ(p.at("manakov_2_34"), (std::set<std::string>{"manakov_Omega"}));
  const std::string m =
      "function W = manakov_Omega(A, M)\n  W = A';  % manakov_M(A, W)\nend\n"
      "function d = euler_3_8(I, P)\n  d = cross(P, omega_3_5(I, P));\nend\n";
  EXPECT_EQ(slot_calls_in_text(m, *language_named("octave")),
            (std::map<std::string, std::set<std::string>>{{"euler_3_8", {"omega_3_5"}}}));
  const std::string cpp =
      "struct S {\n  template <class T>\n  static Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& P) {\n"
      "    return P.cwiseQuotient(I);\n  }\n  template <class T>\n"
      "  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& P) {\n    return P.cross(omega_3_5<T>(I, P));\n  "
      "}\n};\n";
  EXPECT_EQ(slot_calls_in_text(cpp, *language_named("c++")),
            (std::map<std::string, std::set<std::string>>{{"euler_3_8", {"omega_3_5"}}}));
  // A folder of Octave function files: calls across files; a link is not read (the control: the
  // same file as a regular file is).
  const fs::path dir = scratch("calls");
  write_file(dir / "manakov_2_34.m",
             "function d = manakov_2_34(A, M)\n  W = manakov_Omega(A, M);\n  d = M * W - W * M;\nend\n");
  write_file(dir / "elsewhere" / "euler.m", "function d = euler_3_8(I, P)\n  d = cross(P, omega_3_5(I, P));\nend\n");
  fs::create_symlink(dir / "elsewhere" / "euler.m", dir / "euler_3_8.m");
  const auto f = slot_calls(dir.string(), *language_named("octave"));
  EXPECT_EQ(f, (std::map<std::string, std::set<std::string>>{{"manakov_2_34", {"manakov_Omega"}}}));
  fs::remove(dir / "euler_3_8.m");
  fs::copy_file(dir / "elsewhere" / "euler.m", dir / "euler_3_8.m");
  EXPECT_EQ(slot_calls(dir.string(), *language_named("octave")).count("euler_3_8"), 1u);
  fs::remove_all(dir);
}

// "first fix: manakov_2_34", which is right and calls the wrong manakov_Omega (a folder
// submission). Both own checks fail; the callee comes first, and the caller says why it fails.
TEST(SourceCalls, TheFirstFixIsTheCalleeNotTheCaller) {
  const fs::path dir = scratch("first-fix");
  gm::harness::harness_testing::write_omega_and_its_caller(dir);
  CheckResult r;
  r.info.source = dir.string();
  r.info.language = language_named("octave");
  for (const char* p : {"definition_manakov_2_34", "definition_manakov_Omega"}) {
    gm::Verdict v;
    v.property = p;
    v.scalar = "double";
    v.outcome = gm::Outcome::Fail;
    v.message = "does not hold";
    r.verdicts.push_back(v);
  }
  decide_first_fixes(r);  // as the engine does; the report renders it
  const RootCauses& rc = r.first_fixes;
  EXPECT_EQ(rc.order, (std::vector<std::string>{"manakov_Omega", "manakov_2_34"}));
  EXPECT_EQ(rc.calls_broken, (std::map<std::string, std::string>{{"manakov_2_34", "manakov_Omega"}}));
  const std::string md = markdown_report(r, nullptr);
  EXPECT_NE(md.find("- **Octave function `manakov_Omega` in " + dir.filename().string() + " is wrong**"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("fails too**, and it calls `manakov_Omega`, which is wrong (above): fix that first"),
            std::string::npos)
      << md;
  // The control: a manakov_2_34 that does not call it is wrong on its own, and sorts as before.
  write_file(dir / "manakov_2_34.m", "function d = manakov_2_34(A, M)\n  d = M;\nend\n");
  const RootCauses alone = root_causes(r);
  EXPECT_TRUE(alone.calls_broken.empty());
  EXPECT_EQ(alone.order, (std::vector<std::string>{"manakov_2_34", "manakov_Omega"}));
  fs::remove_all(dir);
}

// The console's live first fixes follow the same rule on what has arrived so far: the callee
// named first makes the caller a THEN; a slot is named once; a machine's fault and a check that is
// no slot's own name none. The control: arriving in the other order, the caller is named alone.
TEST(SourceCalls, TheLiveFirstFixFollowsTheSameRule) {
  const fs::path dir = scratch("live-first-fix");
  gm::harness::harness_testing::write_omega_and_its_caller(dir);
  SubjectInfo info;
  info.source = dir.string();
  info.language = language_named("octave");
  auto failing = [](const char* property, const std::string& machine_fault = "") {
    gm::Verdict v;
    v.property = property;
    v.scalar = "double";
    v.outcome = machine_fault.empty() ? gm::Outcome::Fail : gm::Outcome::Error;
    v.machine_fault = machine_fault;
    return v;
  };
  FirstFixesSoFar live(info);
  EXPECT_FALSE(live.on_problem(failing("definition_manakov_Omega", "the machine starved it")).has_value());
  const auto omega = live.on_problem(failing("definition_manakov_Omega"));
  ASSERT_TRUE(omega.has_value());
  EXPECT_EQ(omega->slot, "manakov_Omega");
  EXPECT_EQ(omega->callee, "");
  EXPECT_FALSE(live.on_problem(failing("definition_manakov_Omega")).has_value()) << "named twice";
  const auto caller = live.on_problem(failing("definition_manakov_2_34"));
  ASSERT_TRUE(caller.has_value());
  EXPECT_EQ(caller->slot, "manakov_2_34");
  EXPECT_EQ(caller->callee, "manakov_Omega");
  EXPECT_FALSE(live.on_problem(failing("no_such_property")).has_value());

  FirstFixesSoFar other_order(info);
  const auto first = other_order.on_problem(failing("definition_manakov_2_34"));
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->callee, "") << "its callee had not arrived";
  fs::remove_all(dir);
}
