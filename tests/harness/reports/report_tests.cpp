// harness/reports/: the report writers say the same, a machine's fault names no slot, verdicts
// survive JSON, SVG says what it leaves out.
#include "harness/checking/check.hpp"
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/thorough_only.hpp"
#include "harness/checking/trajectory.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/program/build.hpp"
#include "harness/reports/console_stream.hpp"
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

// ---- reports --------------------------------------------------------------------------------

TEST(Reports, JUnitMarkdownAndJsonSayTheSame) {
  SubjectSet s = mutate(reference_subject(), "transposed", "", [](auto& sub) {
    using T = typename std::decay_t<decltype(sub)>::Scalar;
    const auto ref = sub.hat;
    sub.hat = [ref](const Vec3<T>& v) -> Mat3<T> { return ref(v).transpose(); };
  });
  SubjectInfo info;
  info.reproduce_prefix = "geomech check student.cpp";
  const CheckResult r = run_check(s, info, quick({"hat_is_cross_product", "vee_inverts_hat", "euler_form_2_1"}));
  const std::string junit = junit_report(r);
  // The transposed hat fails its own two checks... and vee(hat(a)) = a with the untouched vee.
  EXPECT_NE(junit.find("tests=\"9\" failures=\"6\" errors=\"0\" skipped=\"0\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<failure type=\"FAIL\""), std::string::npos);
  EXPECT_EQ(junit.find("<error"), std::string::npos);
  const std::string md = markdown_report(r, nullptr);
  EXPECT_NE(md.find("**Result: FAIL**"), std::string::npos);
  EXPECT_NE(md.find("Counterexample (shrunk, full precision)"), std::string::npos);
  EXPECT_NE(md.find("geomech check student.cpp --property hat_is_cross_product --scalar exact --reproduce '"),
            std::string::npos);
  const auto j = json_report(r, nullptr);
  EXPECT_EQ(j.at("counts").at("FAIL").get<int>(), 6);
  EXPECT_EQ(j.at("exit_code").get<int>(), 1);

  // Written atomically: a second report replaces the first, and nothing temporary is left.
  const fs::path dir = temp_dir();
  write_report_dir(r, (dir / "report").string(), nullptr);
  std::ofstream(dir / "report" / "stale.txt") << "from before";
  write_report_dir(r, (dir / "report").string(), nullptr);
  EXPECT_TRUE(fs::exists(dir / "report" / "report.md"));
  EXPECT_TRUE(fs::exists(dir / "report" / "junit.xml"));
  EXPECT_TRUE(fs::exists(dir / "report" / "verdicts.json"));
  EXPECT_FALSE(fs::exists(dir / "report" / "stale.txt"));
  // Someone's own directory is never replaced.
  fs::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "thesis.tex") << "precious";
  EXPECT_THROW(write_report_dir(r, (dir / "mine").string(), nullptr), std::runtime_error);
  EXPECT_TRUE(fs::exists(dir / "mine" / "thesis.tex"));
  EXPECT_THROW(write_report_dir(r, (dir / "mine" / "thesis.tex").string(), nullptr), std::runtime_error);
  EXPECT_THROW(write_report_dir(r, "/", nullptr), std::runtime_error);
  fs::remove_all(dir / "mine");
  const auto entries = std::distance(fs::directory_iterator(dir), fs::directory_iterator{});
  EXPECT_EQ(entries, 1);
  fs::remove_all(dir);
}

// A machine's fault is charged to the machine in every view, and names no slot: a slot's own check
// that the machine starved is an ERROR (the machine's) with its fix, not the slot's first fix. The
// control: the same failure without the machine's fault names the slot.
TEST(Reports, AMachineFaultNamesNoSlotInAnyView) {
  CheckResult r;
  r.subject = "reference";
  gm::Verdict v;
  v.subject = "reference";
  v.property = "definition_euler_3_8";
  v.scalar = "double";
  v.outcome = gm::Outcome::Error;
  v.message = "the check could not do its work: the machine starved it";
  v.machine_fault =
      "the machine's fault, not the code's: the check could not do its work. Fix: run it again on a "
      "less busy machine, or with fewer checks at once (--jobs).";
  r.verdicts.push_back(v);
  decide_first_fixes(r);  // as the check does, once the verdicts are complete
  EXPECT_TRUE(r.first_fixes.broken.empty());
  const auto j = json_report(r, nullptr);
  EXPECT_TRUE(j.at("first_fix").empty()) << j.at("first_fix").dump();
  EXPECT_EQ(j.at("verdicts").at(0).at("owner"), "machine");
  EXPECT_EQ(j.at("verdicts").at(0).at("machine_fault"), v.machine_fault);
  const std::string junit = junit_report(r);
  EXPECT_NE(junit.find("type=\"ERROR (the machine's)\""), std::string::npos) << junit;
  const std::string md = markdown_report(r, nullptr);
  EXPECT_EQ(md.find("slot `euler_3_8` is wrong"), std::string::npos) << md;
  // The same verdict read back keeps its owner.
  EXPECT_EQ(verdict_from_json(to_json(v)).machine_fault, v.machine_fault);

  r.verdicts[0].machine_fault.clear();  // the control: the code's ERROR names its slot
  decide_first_fixes(r);
  EXPECT_EQ(r.first_fixes.broken.count("euler_3_8"), 1u);
  EXPECT_EQ(json_report(r, nullptr).at("verdicts").at(0).at("owner"), "code");
  EXPECT_NE(markdown_report(r, nullptr).find("slot `euler_3_8` is wrong"), std::string::npos);
}

TEST(Reports, VerdictsSurviveJsonWithNonFiniteNumbersAndBadBytes) {
  Verdict v;
  v.property = "p";
  v.outcome = Outcome::Timeout;
  v.message = std::string("bad bytes \xff\xfe here");
  v.worst_eps_units = HUGE_VAL;
  Series s;
  s.points = {{1, std::nan("")}, {2, -HUGE_VAL}};
  v.series.push_back(s);
  v.claims.push_back(ClaimFinding{"order", true, false, "slope 1"});
  const auto back = verdicts_from_string(verdicts_to_string({v}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].outcome, Outcome::Timeout);
  EXPECT_TRUE(std::isinf(back[0].worst_eps_units));
  EXPECT_TRUE(std::isnan(back[0].series[0].points[0].second));
  EXPECT_FALSE(back[0].claims[0].holds);
}

// The count of discarded cases crosses the JSON, and a verdict written before it was
// counted (no "discarded" field) still reads, as 0.
TEST(Reports, DiscardedCasesSurviveJson) {
  Verdict v;
  v.property = "p";
  v.outcome = Outcome::Pass;
  v.discarded = 7;
  v.discard_reason = "a degenerate draw";
  const auto back = verdicts_from_string(verdicts_to_string({v}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].discarded, 7);
  EXPECT_EQ(back[0].discard_reason, "a degenerate draw");
  auto j = nlohmann::json::parse(verdicts_to_string({v}));
  j[0].erase("discarded");
  j[0].erase("discard_reason");
  const auto old = verdicts_from_string(j.dump());
  EXPECT_EQ(old[0].discarded, 0);
  CheckResult r;
  r.verdicts = {v};
  const std::string md = markdown_report(r, nullptr);
  EXPECT_NE(md.find("| 7 | a degenerate draw |"), std::string::npos) << md;
}

TEST(Reports, SvgLeavesOutWhatCannotBeDrawnAndSaysSo) {
  Series s;
  s.figure = "f";
  s.name = "errors <&>";
  s.log_x = s.log_y = true;
  s.reference_slope = 2;
  s.points = {{0.1, 1e-2}, {0.05, 2.5e-3}, {0.025, 0}, {0.0125, std::nan("")}};
  const std::string svg = svg_plot("title", {s});
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find("slope 2 (claimed)"), std::string::npos);
  EXPECT_NE(svg.find("2 point(s) not drawn"), std::string::npos);
  EXPECT_NE(svg.find("errors &lt;&amp;&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("clip-path"), std::string::npos);
  EXPECT_NE(svg_plot("empty", {}).find("no drawable points"), std::string::npos);
}

// The streamed console renders the live first fixes the check decides (harness/checking/first_fix.hpp):
// a FIRST FIX line for the callee, a THEN line for the caller that calls it. The control: a
// verdict that is no slot's own check gets no such line.
TEST(Reports, TheConsoleStreamNamesTheFirstFixAsItArrives) {
  const fs::path dir = temp_dir();
  write_omega_and_its_caller(dir);
  SubjectInfo info;
  info.source = dir.string();
  info.language = language_named("octave");
  std::ostringstream out, err;
  ConsoleStream console("dave", info, 0, false, out, err, false);
  auto failing = [](const char* property) {
    gm::Verdict v;
    v.subject = "dave";
    v.property = property;
    v.scalar = "double";
    v.outcome = gm::Outcome::Fail;
    v.message = "does not hold";
    return v;
  };
  console.finished({failing("definition_manakov_Omega")}, false, CheckProgress{});
  console.finished({failing("definition_manakov_2_34")}, false, CheckProgress{});
  console.finished({failing("hat_is_cross_product_of_nothing")}, false, CheckProgress{});
  const std::string text = out.str();
  EXPECT_NE(text.find("FIRST FIX: "), std::string::npos) << text;
  EXPECT_NE(text.find("manakov_Omega' in " + dir.filename().string() +
                      " is wrong: its own check definition_manakov_Omega fails in double"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("THEN:      "), std::string::npos) << text;
  EXPECT_NE(text.find("and it calls 'manakov_Omega', which is wrong: fix that first"), std::string::npos) << text;
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("FIRST FIX: "), 1u) << text;  // the third verdict, no slot's own check, named nothing
  EXPECT_EQ(count("THEN:      "), 1u) << text;
  EXPECT_NE(text.find("hat_is_cross_product_of_nothing"), std::string::npos) << text;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gm::harness
