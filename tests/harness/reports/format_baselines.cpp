// Every report format (harness/reports/report_formats.hpp) rendered from one fixed check result and
// compared byte for byte with its approved baseline in tests/harness/reports/baselines/, one file per
// format, named as in a report folder. A change of a format's text shows here as the first line that
// differs; when the change is meant, approve it by running the test with GEOMECH_APPROVE_BASELINES=1
// (it rewrites the baselines, and the diff is reviewed in the commit like any other).
#include "harness/checking/first_fix.hpp"
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/reports/report_formats.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace gm::harness {
namespace {

namespace fs = std::filesystem;

const fs::path kBaselines = fs::path(GM_SOURCE_DIR) / "tests/harness/reports/baselines";

// The statement and the spec entry are the fixture's own words, not the registry's: a property's
// title edited elsewhere does not change these baselines.
Verdict fixed_verdict(const std::string& property, const std::string& scalar, Outcome outcome) {
  Verdict v;
  v.subject = "fixed_student";
  v.property = property;
  v.spec = "s3.euler-flow";
  v.title = "the statement of " + property;
  v.scalar = scalar;
  v.outcome = outcome;
  v.seed = 20261202;
  v.cases = outcome == Outcome::Pass ? 100 : 7;
  v.cases_planned = 100;
  v.checks = 300;
  v.seconds = 0.25;
  v.worst_eps_units = outcome == Outcome::Pass ? 1.5 : 0;
  return v;
}

// One check of each kind a report tells apart: a slot that passes, a slot that fails with its shrunk
// counterexample and its replay, a slot not provided, a check the machine starved (its fault, not the
// code's), an integrator whose claimed order holds and whose claimed Casimir does not, and a claim
// nothing could check. Every number is fixed, the seconds included.
CheckResult fixed_check_result() {
  CheckResult r;
  r.subject = "fixed_student";
  r.description = "a fixed check result for the format baselines";
  r.info.source = "student.cpp";
  r.info.reproduce_prefix = "geomech check student.cpp";
  r.seed = 20261202;
  r.selection = "all properties";
  r.seconds = 12.5;
  r.provided["double"] = {"hat", "vee", "euler_3_8"};
  r.verdicts.push_back(fixed_verdict("hat_is_cross_product", "double", Outcome::Pass));
  Verdict fail = fixed_verdict("definition_euler_3_8", "double", Outcome::Fail);
  fail.message = "dPi/dt differs from Pi x Omega (3.8) by 2.0 at the shrunk input";
  fail.counterexample = {{"Vec3<double>", "(1, 2, 3)"}, {"Vec3<double>", "(0.5, -1, 0.25)"}};
  fail.reproduce = "BAhEAAAAAAAAAAAA";
  r.verdicts.push_back(fail);
  Verdict missing = fixed_verdict("definition_vee_n", "double", Outcome::NotProvided);
  missing.message = "needs vee_n, which this implementation does not provide";
  r.verdicts.push_back(missing);
  Verdict starved = fixed_verdict("vee_inverts_hat", "mp50", Outcome::Error);
  starved.message = "the check could not do its work: the machine starved it";
  starved.machine_fault =
      "the machine's fault, not the code's: the check could not do its work. Fix: run it again on a less busy "
      "machine, or with fewer checks at once (--jobs).";
  r.verdicts.push_back(starved);
  IntegratorInfo midpoint;
  midpoint.name = "midpoint";
  midpoint.has_claims = true;
  midpoint.claims.integrator = "midpoint";
  midpoint.claims.order = 2;
  midpoint.claims.casimir = true;
  midpoint.steps = {"rigid_body_step"};
  midpoint.scalars = {"double"};
  r.integrators.push_back(midpoint);
  Verdict order = fixed_verdict("integrator_order", "double", Outcome::Pass);
  order.integrator = "midpoint";
  order.claims.push_back({"order", true, true, "slope 2.00 over h = 1/8 ... 1/128", true, "order 2.00"});
  r.verdicts.push_back(order);
  Verdict casimir = fixed_verdict("integrator_casimir", "double", Outcome::Fail);
  casimir.integrator = "midpoint";
  casimir.message = "the Casimir |Pi|^2 is kept to round-off over 64 steps: residual 3.1e+04 eps * scale";
  casimir.claims.push_back({"casimir", true, false, "residual 3.1e+04 eps * scale", true, "residual 3.1e+04 eps"});
  r.verdicts.push_back(casimir);
  r.unchecked = {"integrator 'midpoint' claims 'simplectic', which is not a claim the suite knows"};
  decide_integrator_verdicts(r);  // as the check does, once the verdicts are complete
  decide_first_fixes(r);
  return r;
}

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Empty when `received` is `approved`; else the first line that differs, both ways, by number.
std::string first_difference(const std::string& approved, const std::string& received) {
  if (approved == received) return {};
  std::istringstream a(approved), b(received);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) return "they differ in their last line's end";
    if (la != lb || more_a != more_b)
      return "line " + std::to_string(line) + ":\n  approved: " + (more_a ? la : "(the end)") +
             "\n  received: " + (more_b ? lb : "(the end)");
  }
}

TEST(ReportFormats, EachFormatMatchesItsApprovedBaseline) {
  const CheckResult r = fixed_check_result();
  const bool approve = std::getenv("GEOMECH_APPROVE_BASELINES") != nullptr;
  for (const ReportFormat& f : report_formats()) {
    const fs::path baseline = kBaselines / f.file;
    const std::string received = f.render(r, nullptr);
    if (approve) {
      std::ofstream(baseline, std::ios::binary | std::ios::trunc) << received;
      continue;
    }
    ASSERT_TRUE(fs::exists(baseline)) << f.name << " has no baseline " << baseline
                                      << "; write it with GEOMECH_APPROVE_BASELINES=1 and review it";
    EXPECT_EQ(first_difference(read_file(baseline), received), "")
        << f.name << " (" << f.file << ") is not its approved baseline " << baseline
        << ". If the change is meant: GEOMECH_APPROVE_BASELINES=1 build/tests/geomech_harness_tests "
           "--gtest_filter=ReportFormats.EachFormatMatchesItsApprovedBaseline, and review the diff";
  }
}

// The negative control: one verdict changed (the failing slot passes) changes every format, and the
// comparison names the first line that differs; a file cut short is told from a changed one.
TEST(ReportFormats, ABaselineRefusesAChangedResult) {
  CheckResult changed = fixed_check_result();
  for (Verdict& v : changed.verdicts)
    if (v.property == "definition_euler_3_8") v.outcome = Outcome::Pass, v.message.clear(), v.counterexample.clear();
  decide_first_fixes(changed);
  for (const ReportFormat& f : report_formats()) {
    const std::string approved = read_file(kBaselines / f.file);
    ASSERT_FALSE(approved.empty()) << f.file;
    EXPECT_NE(first_difference(approved, f.render(changed, nullptr)), "") << f.name << " did not change";
  }
  EXPECT_EQ(first_difference("a\nb\nc\n", "a\nX\nc\n"), "line 2:\n  approved: b\n  received: X");
  EXPECT_EQ(first_difference("a\nb\n", "a\n"), "line 2:\n  approved: b\n  received: (the end)");
  EXPECT_EQ(first_difference("a\n", "a\n"), "");
}

// The registry is the one list: a report folder's files and the formats' options, none twice.
TEST(ReportFormats, EachFormatHasOneFileAndOneOption) {
  std::set<std::string> files, options;
  for (const ReportFormat& f : report_formats()) {
    EXPECT_TRUE(files.insert(f.file).second) << f.file;
    EXPECT_TRUE(options.insert(f.option).second) << f.option;
    EXPECT_EQ(f.option.rfind("--", 0), 0u) << f.option;
  }
  EXPECT_EQ(report_folder_files(), "report.md, report.html, junit.xml, verdicts.json and figures/");
}

}  // namespace
}  // namespace gm::harness
