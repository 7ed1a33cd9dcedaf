// harness/program/: reading compiler output, the precompiled student header.
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

// ---- reading compiler output ------------------------------------------------------------------

TEST(Build, CompilerMessagesNameTheSlotsThatDoNotCompile) {
  const std::string gcc =
      "student.cpp: In instantiation of 'static T S::hamiltonian_3_4(const Vec3<T>&, const Vec3<T>&) [with T = "
      "Rational]':\n"
      "student/geomech/student.hpp:110:5:   required from 'static decltype (...) "
      "gm::student::detail::slot_hamiltonian_3_4::call_template(A&& ...)'\n"
      "student.cpp:12:20: error: no matching function for call to 'sqrt(Rational&)'\n"
      "student.cpp: In instantiation of ... gm::student::detail::slot_omega_3_5::call_template ...\n"
      "student.cpp:20:3: error: ambiguous overload for 'operator*'\n";
  const auto failing = slots_failing_in(gcc);
  ASSERT_EQ(failing.size(), 2u);
  EXPECT_NE(failing.at("hamiltonian_3_4").find("sqrt"), std::string::npos);
  EXPECT_NE(failing.at("omega_3_5").find("ambiguous"), std::string::npos);
  EXPECT_NE(hint_for(failing.at("hamiltonian_3_4"), "exact").find("no exact rational value"), std::string::npos);
  EXPECT_NE(hint_for("error: no matching function for call to 'sqrt(Real50&)' std::sqrt", "mp50").find("unqualified"),
            std::string::npos);
  EXPECT_FALSE(integrators_failing_in(gcc));
  EXPECT_EQ(first_error(gcc).find("student.cpp:12:20: error"), 0u);
}

// The hat slot as a student writes it, for the test files below.
const char* const kHatSlot =
    "  template <class T> static Mat3<T> hat(const Vec3<T>& v) {\n"
    "    Mat3<T> m; m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0); return m; }\n";

// A build of the double instantiation alone, cached in dir/cache.
BuildOptions double_only(const fs::path& dir) {
  BuildOptions o;
  o.cache_dir = (dir / "cache").string();
  o.mp50 = o.exact = false;
  return o;
}

// The precompiled geomech/student.hpp only saves time, and GCC drops an unusable one without a
// word, so this asks the compiler: the cached compile command of a one-slot file, run again with
// -Winvalid-pch, must not say the .gch was rejected (nor for a piece that leaves slots or the
// integrators out: the header tests none of the macros of geomech/detail/scalar_selection.hpp).
// Control: the same command with a macro the header does test must say so.
TEST(Build, ThePrecompiledStudentHeaderIsUsed) {
  const Toolchain tc = load_toolchain(default_toolchain_path());
  ASSERT_FALSE(tc.precompiled_header.empty()) << tc.path << " names no precompiled header with a .gch beside it";
  const fs::path dir = temp_dir();
  const fs::path src = dir / "one_slot.cpp";
  std::ofstream(src) << "#include <geomech/student.hpp>\nusing namespace gm;\nstruct OneSlot {\n"
                     << kHatSlot << "};\nGEOMECH_STUDENT(OneSlot);\n";
  const BuildOptions o = double_only(dir);
  const BuildResult r = build_student(src.string(), tc, o);
  ASSERT_TRUE(r.ok) << r.message;
  fs::path cmd_file;
  for (const auto& e : fs::recursive_directory_iterator(dir / "cache"))
    if (e.path().filename() == "double.cmd") cmd_file = e.path();
  ASSERT_FALSE(cmd_file.empty());
  std::ifstream in(cmd_file);
  const std::string cmd((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(cmd.find("-include " + tc.precompiled_header), std::string::npos) << cmd;
  auto compiler_says = [&](const std::string& extra) {
    const fs::path log = dir / "pch.log";
    const std::string line = cmd + " -Winvalid-pch" + extra + " > " + log.string() + " 2>&1";
    EXPECT_EQ(std::system(line.c_str()), 0) << line;
    std::ifstream l(log);
    return std::string((std::istreambuf_iterator<char>(l)), std::istreambuf_iterator<char>());
  };
  const std::string used = compiler_says("");
  EXPECT_EQ(used.find("not used"), std::string::npos) << used;
  const std::string retry = compiler_says(" -DGEOMECH_SKIP_SLOTS='\"hat\"' -DGEOMECH_SKIP_INTEGRATORS=1");
  EXPECT_EQ(retry.find("not used"), std::string::npos) << retry;
  const std::string control = compiler_says(" -DGEOMECH_STUDENT_SELECTION=::gm::student::detail::WholeFile");
  EXPECT_NE(control.find("not used"), std::string::npos) << control;
  fs::remove_all(dir);
}

// After a first look the double instantiation is three pieces (the Manakov slots, the other slots,
// then the integrators) and the program registers one subject from them: a file with a slot in each
// piece and an integrator shows both slots and the integrator. Control: the program linked with the
// first piece twice instead of both registers it once, says so, and lacks manakov_M.
TEST(Build, ThePiecesOfTheDoubleCompileMakeOneSubject) {
  const Toolchain tc = load_toolchain(default_toolchain_path());
  const fs::path dir = temp_dir();
  const fs::path src = dir / "two_pieces.cpp";
  std::ofstream(src) << "#include <geomech/student.hpp>\nusing namespace gm;\nstruct TwoPieces {\n"
                     << kHatSlot
                     << "  template <class T> static MatX<T> manakov_M(const MatX<T>& A, const MatX<T>& W) {\n"
                        "    return A * W + W * A; }\n};\n"
                        "struct Still {\n  static constexpr const char* name = \"still\";\n"
                        "  template <class T> static RigidBodyState<T> rigid_body_step(const Vec3<T>&, "
                        "const RigidBodyState<T>& x, const T&) { return x; }\n};\n"
                        "GEOMECH_STUDENT(TwoPieces, Still);\n";
  const BuildOptions o = double_only(dir);
  BuildOptions first_look = o;  // its slots in two pieces, then the full build adds the integrators
  first_look.integrators = false;
  first_look.program_name = "check-double";
  ASSERT_TRUE(build_student(src.string(), tc, first_look).ok);
  const BuildResult r = build_student(src.string(), tc, o);
  ASSERT_TRUE(r.ok) << r.message;
  auto run = [&](const std::string& program) {
    const fs::path log = dir / "run.log";
    const std::string line = program +
                             " --scalar double --jobs 1 --property definition_hat --property definition_manakov_M > " +
                             log.string() + " 2>&1";
    std::system(line.c_str());
    std::ifstream l(log);
    return std::string((std::istreambuf_iterator<char>(l)), std::istreambuf_iterator<char>());
  };
  const std::string whole = run(r.program);
  EXPECT_NE(whole.find("summary: 2 PASS, 0 FAIL"), std::string::npos) << whole;
  EXPECT_NE(whole.find("(1 provided slots and integrators were not exercised"), std::string::npos) << whole;  // still
  EXPECT_EQ(whole.find("second registration"), std::string::npos) << whole;

  std::ifstream link_file(fs::path(r.program).parent_path() / "link-check.cmd");
  std::string link((std::istreambuf_iterator<char>(link_file)), std::istreambuf_iterator<char>());
  const std::string first = (fs::path(r.program).parent_path() / "double-slots-1.o").string();
  const std::string second = (fs::path(r.program).parent_path() / "double-slots-2.o").string();
  ASSERT_NE(link.find(second), std::string::npos) << link;
  link.replace(link.find(second), second.size(), first);
  link.replace(link.rfind(r.program), r.program.size(), (dir / "one_piece_twice").string());
  ASSERT_EQ(std::system(link.c_str()), 0) << link;
  const std::string control = run((dir / "one_piece_twice").string());
  EXPECT_NE(control.find("summary: 1 PASS, 0 FAIL, 1 NOT PROVIDED"), std::string::npos) << control;
  EXPECT_NE(control.find("second registration"), std::string::npos) << control;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gm::harness
