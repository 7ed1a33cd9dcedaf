// The example implementations (examples/students) as tests: each example's check program runs,
// and its report must say exactly what the table below says: which checks fail (and with what
// words), crash or time out; every other check passes or is not provided. The correct example
// passes everything. Plus the real `geomech check FILE.cpp` path end to end, and class mode.
//
//   example_tests --ctest-script OUT --examples TSV --geomech EXE --source-dir DIR
//       writes the ctest declarations (run after each build);
//   example_tests --example NAME --program EXE --source FILE      one example;
//   example_tests --end-to-end NAME --geomech EXE --source FILE    `geomech check FILE` from scratch;
//   example_tests --class DIR --geomech EXE                        `geomech check-class DIR`;
//   example_tests --cmake-package CMAKE --config DIR --source FILE  a student's own CMake project.
//
// The end-to-end tests compile (three compilers each) and take the RESOURCE_LOCK "compilers", so
// they run one at a time and the time they print is that of one check alone.
//
// Examples whose bug is a false integrator claim are judged by their claims table; an
// integrator-scoped property may FAIL for them only because of such a claim.
#include "harness/isolation/process.hpp"
#include "properties/registry.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Expected {
  std::string property;
  std::vector<std::string> scalars;
  std::string outcome;  // FAIL, CRASH, TIMEOUT, NOT PROVIDED
  std::string says;     // text the verdict's message must contain
};

struct ClaimExpected {
  std::string integrator, claim, status;
};

struct Example {
  std::string name;
  std::string bug;  // what is wrong, for the test log
  std::vector<Expected> verdicts;
  std::vector<ClaimExpected> claims;
  bool false_claims = false;  // the bug is a false claim: integrator properties may FAIL
  std::vector<std::string> args;
  // The first item of "What to fix" in report.md must contain this (the slot that is
  // wrong comes first); empty: not asserted.
  std::string first_fix = {};
  std::vector<std::string> report_says = {};  // lines report.md must contain
  int exit_code = -1;                         // expected exit status when not 0/1 by the verdicts
};

const std::vector<std::string> all3 = {"double", "mp50", "exact"};

const std::vector<Example>& examples() {
  static const std::vector<Example> list = {
      {"correct", "nothing: every check it can be given passes, every claim holds", {}, {}, false, {}},
      {"double_only",
       "nothing, but written for double only",
       {{"euler_form_3_8", {"mp50", "exact"}, "NOT PROVIDED", "provided for double only"},
        {"hamiltonian_gradient_3_5", {"mp50", "exact"}, "NOT PROVIDED", "provided for double only"},
        {"hat_is_cross_product", {"mp50", "exact"}, "NOT PROVIDED", "provided for double only"}},
       {},
       false,
       {}},
      {"bug_euler_sign",
       "Euler's equations with the cross product reversed",
       {{"definition_euler_3_8", all3, "FAIL", "slot euler_3_8: dPi/dt = Pi x I^-1 Pi, (3.8) does not hold"},
        {"euler_form_3_8", all3, "FAIL", "euler_3_8(I, I Omega) = componentwise (2.1) does not hold"},
        {"euler_flow_is_elliptic_solution", {"double", "mp50"}, "FAIL", "= elliptic solution"}},
       {},
       false,
       {},
       "slot `euler_3_8` is wrong"},
      {"bug_hat_transposed",
       "the transposed hat convention",
       {{"definition_hat", all3, "FAIL", "slot hat: hat(v) = (-v_i eps_ijk), (2.11) does not hold"},
        {"definition_vee", all3, "FAIL", "slot vee: vee(S) = (S_32, S_13, S_21) for skew S, (2.11) does not hold"},
        {"hat_is_cross_product", all3, "FAIL", "does not hold"},
        {"hat_is_lie_algebra_isomorphism", all3, "FAIL", "[hat(a), hat(b)] = hat(a x b) does not hold"},
        {"restricted_variation_2_8", all3, "FAIL", "dOmega/ds - dXi/dt = Omega x Xi does not hold"}},
       {},
       false,
       {},
       "slot `hat` is wrong"},
      {"bug_reconstruction",
       "reconstruction as dO/dt = hat(Omega) O",
       {{"definition_reconstruction_2_10", all3, "FAIL",
         "slot reconstruction_2_10: dO/dt = O Omega_hat, (2.10) does not hold"},
        {"reconstruction_is_left_invariant", all3, "FAIL", "(left-invariant) does not hold"}},
       {},
       false,
       {},
       "slot `reconstruction_2_10` is wrong"},
      {"bug_pairing_half",
       "the factor 1/2 of the trace pairing lost",
       {{"definition_pairing", all3, "FAIL", "slot pairing: <A, B> = tr(A^T B)/2, (2.15) does not hold"},
        {"definition_lagrangian_2_13", all3, "FAIL", "slot lagrangian_2_13"},
        {"trace_pairing_is_dot_product", all3, "FAIL", "<hat(a), hat(b)> = a . b does not hold"},
        {"lagrangian_2_13_is_kinetic_energy", all3, "FAIL", "does not hold"},
        {"symmetric_part_does_not_pair", all3, "FAIL", "<Pi_skew, Omega_hat> = vee(Pi_skew) . Omega does not hold"}},
       {},
       false,
       {},
       "slot `pairing` is wrong"},
      {"bug_manakov_omega",
       "Manakov's Omega recovered as A^-1 M / 2",
       {{"definition_manakov_Omega", all3, "FAIL", "slot manakov_Omega: A Omega + Omega A = M, (2.34)"},
        {"manakov_omega_solves_2_34", all3, "FAIL",
         "A Omega + Omega A = M for Omega = manakov_Omega(A, M) does not hold"}},
       {},
       false,
       {},
       "slot `manakov_Omega` is wrong"},
      {"bug_hamiltonian_inertia",
       "the Hamiltonian with I instead of I^-1",
       {{"definition_hamiltonian_3_4", all3, "FAIL", "slot hamiltonian_3_4: h = Pi . I^-1 Pi / 2, (3.4) does not hold"},
        {"hamiltonian_3_3_is_3_4", all3, "FAIL", "does not hold"},
        {"hamiltonian_gradient_3_5", all3, "FAIL", "does not hold"}},
       {},
       false,
       {},
       "slot `hamiltonian_3_4` is wrong"},
      {"bug_euler_no_division",
       "(2.1) without the division by I",
       {{"definition_euler_2_1", all3, "FAIL",
         "slot euler_2_1: dOmega/dt = I^-1 (I Omega x Omega), (2.1) does not hold"},
        {"euler_form_2_1", all3, "FAIL", "I * euler_2_1(I, Omega) = componentwise (2.1) does not hold"}},
       {},
       false,
       {},
       "slot `euler_2_1` is wrong"},
      {"bug_crash",
       "an out-of-range index (the process aborts)",
       {{"definition_vee", all3, "CRASH", "Assertion `index >= 0 && index < size()' failed"},
        {"vee_inverts_hat", all3, "CRASH", "Assertion `index >= 0 && index < size()' failed"},
        {"restricted_variation_2_8", all3, "CRASH", "Assertion `index >= 0 && index < size()' failed"}},
       {},
       false,
       {},
       "slot `vee` is wrong"},
      {"bug_hang",
       "an iteration that never ends",
       {{"definition_manakov_Omega", all3, "TIMEOUT", "did not finish within 2 s"},
        {"manakov_omega_solves_2_34", all3, "TIMEOUT", "did not finish within 2 s"}},
       {},
       false,
       {"--timeout", "2"},
       "slot `manakov_Omega` is wrong"},
      {"bug_throws",
       "a stub that throws",
       {{"definition_lagrangian_2_13", all3, "FAIL", "lagrangian_2_13: not written yet"},
        {"lagrangian_2_13_is_kinetic_energy", all3, "FAIL", "lagrangian_2_13: not written yet"}},
       {},
       false,
       {},
       "slot `lagrangian_2_13` is wrong"},
      {"bug_claims_casimir",
       "explicit Euler claiming to preserve |Pi|^2 and O^T O = Id",
       {},
       {{"explicit_euler", "casimir", "FALSE CLAIM"},
        {"explicit_euler", "orthogonality", "FALSE CLAIM"},
        {"explicit_euler", "order", "verified"}},
       true,
       {}},
      {"bug_order_claim",
       "a first-order Lie-Trotter splitting claiming order 2 and symmetry",
       // Its field is right at every state drawn, fast (scaled) motions included, and the
       // false claim says so first; its inputs are by the notes' names.
       {{"integrator_converges_in_every_regime",
         {"double", "mp50"},
         "FAIL",
         "the step's own equation: your step's vector field is right"},
        {"integrator_local_order", {"double", "mp50"}, "FAIL", "inputs, by the notes' names:\n    I = "}},
       {{"lie_trotter", "order", "FALSE CLAIM"},
        {"lie_trotter", "symmetric", "FALSE CLAIM"},
        {"lie_trotter", "casimir", "verified"},
        {"lie_trotter", "orthogonality", "verified"}},
       true,
       {}},
      // Structural claims that do not hold.
      {"bug_claims_structure",
       "RK4 with the rows of O normalised claiming equivariance and Noether; explicit Verlet on the "
       "non-separable Clebsch Hamiltonian claiming symplecticity; explicit Euler claiming bounded energy",
       {},
       {{"rk4_rows_normalised", "equivariant", "FALSE CLAIM"},
        {"rk4_rows_normalised", "noether", "FALSE CLAIM"},
        {"rk4_rows_normalised", "order", "verified"},
        {"explicit_verlet", "symplectic", "FALSE CLAIM"},
        {"explicit_euler", "bounded_energy", "FALSE CLAIM"},
        {"explicit_euler", "order", "verified"}},
       true,
       {}},
      // A slot provided alone, wrongly, fails its own direct property.
      {"bug_energy_alone",
       "only the energy (3.4), without its 1/2",
       {{"definition_hamiltonian_3_4", all3, "FAIL",
         "slot hamiltonian_3_4: h = Pi . I^-1 Pi / 2, (3.4) does not hold"}},
       {},
       false,
       {},
       "slot `hamiltonian_3_4` is wrong"},
      {"bug_momentum_map_alone",
       "only the momentum map, written J = q x p",
       {{"definition_momentum_map", all3, "FAIL", "slot momentum_map: J(q, p) = p x q"}},
       {},
       false,
       {},
       "slot `momentum_map` is wrong"},
      {"bug_bracket_sign_alone",
       "only the Lie-Poisson bracket (3.6), with the wrong sign (its axioms still hold)",
       {{"definition_lie_poisson_3_6", all3, "FAIL",
         "slot lie_poisson_3_6: {f, h} = -Pi . (df x dh), (3.6) does not hold"}},
       {},
       false,
       {},
       "slot `lie_poisson_3_6` is wrong"},
      {"bug_noether_as_printed",
       "the spatial momentum exactly as printed in (2.30), a recorded erratum",
       {{"definition_spatial_momentum", all3, "FAIL",
         "your result is the formula as printed in the notes, (2.30) pi = O^-1 Pi O, i.e. O^T Pi, which is an erratum: "
         "see spec/CATALOGUE.md, entry s2.noether"},
        {"noether_spatial_momentum_conserved", {"double", "mp50"}, "FAIL", ""},
        {"noether_endpoint_term_2_28", all3, "NOT PROVIDED", "pairing"}},
       {},
       false,
       {},
       "slot `spatial_momentum` is wrong"},
      // In double only: its slots are correct.hpp's, which student.end_to_end.correct checks in every scalar
      // with the same seed; what this example is about (UNCHECKED, exit status 1) does not depend on
      // the scalar, and the two other scalars cost 25 of its 35 s.
      {"bug_integrator_signature",
       "an integrator whose step cannot be called as the slot expects: its claims cannot be checked",
       {},
       {},
       false,
       {"--scalar", "double"},
       "",
       {"**Result: UNCHECKED**", "integrator 'explicit_euler_pi_only' has none of rigid_body_step("},
       1},
      {"bug_slot_names",
       "right formulas under names that are not slot names: nothing is checked",
       {},
       {},
       false,
       {},
       "",
       {"**Result: NOTHING CHECKED**", "`energy` is not a slot name", "did you mean `hamiltonian_3_4`",
        "`euler` is not a slot name", "did you mean `euler_3_8`", "`omega35` is not a slot name"},
       1},
  };
  return list;
}

const Example* find_example(const std::string& name) {
  for (const auto& e : examples())
    if (e.name == name) return &e;
  return nullptr;
}

std::string temp_dir(const std::string& tag) {
  std::string t = (fs::temp_directory_path() / ("geomech-test-" + tag + "-XXXXXX")).string();
  if (!::mkdtemp(t.data())) throw std::runtime_error("cannot create a temporary directory");
  return t;
}

json read_json(const fs::path& p) {
  std::ifstream f(p);
  if (!f) throw std::runtime_error("no " + p.string());
  return json::parse(f);
}

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    ++failures;
    std::cout << "  FAILED: " << what << "\n";
  }
}

// The report of one example against its expectations.
void check_report(const Example& e, const json& report, int exit_code) {
  bool expect_problem = false;
  for (const auto& x : e.verdicts)
    if (x.outcome != "NOT PROVIDED") expect_problem = true;
  for (const auto& c : e.claims)
    if (c.status == "FALSE CLAIM") expect_problem = true;
  const int expected_exit = e.exit_code >= 0 ? e.exit_code : expect_problem ? 1 : 0;
  check(exit_code == expected_exit,
        "exit status " + std::to_string(exit_code) + ", expected " + std::to_string(expected_exit));

  std::map<std::pair<std::string, std::string>, const Expected*> expected;
  for (const auto& x : e.verdicts)
    for (const auto& s : x.scalars) expected[{x.property, s}] = &x;
  std::map<std::pair<std::string, std::string>, bool> seen;
  for (const auto& v : report.at("verdicts")) {
    const std::string prop = v.at("property"), scalar = v.at("scalar"), outcome = v.at("outcome");
    const std::string message = v.at("message");
    auto it = expected.find({prop, scalar});
    if (it != expected.end()) {
      seen[{prop, scalar}] = true;
      check(outcome == it->second->outcome, prop + " in " + scalar + " is " + outcome + ", expected " +
                                                it->second->outcome + "\n    message: " + message);
      check(
          message.find(it->second->says) != std::string::npos,
          prop + " in " + scalar + ": the message does not say \"" + it->second->says + "\"\n    message: " + message);
      if (outcome == "FAIL" || outcome == "CRASH" || outcome == "TIMEOUT")
        check(v.contains("reproduce_command") && !v.at("reproduce_command").get<std::string>().empty(),
              prop + " in " + scalar + " has no reproduce command");
      if (outcome == "FAIL" && message.find("Exception") == std::string::npos)
        check(!v.at("counterexample").empty(), prop + " in " + scalar + " has no counterexample");
    } else if (!(e.false_claims && outcome == "FAIL" && message.find("false claim") != std::string::npos)) {
      check(
          outcome == "PASS" || outcome == "NOT PROVIDED",
          prop + " in " + scalar + " is " + outcome + "; only PASS or NOT PROVIDED expected\n    message: " + message);
    }
    if (outcome == "NOT PROVIDED")
      check(!message.empty(), prop + " in " + scalar + " is NOT PROVIDED without a reason");
  }
  for (const auto& [key, x] : expected)
    check(seen.count(key) > 0, key.first + " in " + key.second + " is missing from the report");

  for (const auto& c : e.claims) {
    std::string status = "(no such integrator)";
    for (const auto& i : report.at("integrators"))
      if (i.at("name") == c.integrator)
        for (const auto& row : i.at("claims"))
          if (row.at("claim") == c.claim) status = row.at("status");
    check(status == c.status,
          "claim '" + c.claim + "' of " + c.integrator + " is '" + status + "', expected '" + c.status + "'");
  }
  // No claim of any integrator may be false unless expected.
  for (const auto& i : report.at("integrators"))
    for (const auto& row : i.at("claims")) {
      bool listed = false;
      for (const auto& c : e.claims) listed = listed || (c.integrator == i.at("name") && c.claim == row.at("claim"));
      if (!listed)
        check(row.at("status") != "FALSE CLAIM",
              "claim '" + row.at("claim").get<std::string>() + "' of " + i.at("name").get<std::string>() + " is false");
    }
}

// What an example's report folder must say: its verdicts and claims (check_report), report.md's
// lines and first fix, junit.xml, and the work-precision diagram of its integrators.
void check_example_outputs(const Example& e, const fs::path& report_dir, int exit_code) {
  const json report = read_json(report_dir / "verdicts.json");
  check_report(e, report, exit_code);
  check(fs::exists(report_dir / "report.md"), "no report.md");
  std::ifstream md_in(report_dir / "report.md");
  std::ostringstream md_text;
  md_text << md_in.rdbuf();
  const std::string md = md_text.str();
  for (const auto& says : e.report_says)
    check(md.find(says) != std::string::npos, "report.md does not say \"" + says + "\"");
  if (!e.first_fix.empty()) {
    const auto at = md.find("## What to fix\n\n");
    const std::string first =
        at == std::string::npos ? "(no What to fix section)" : md.substr(at + 16, md.find('\n', at + 16) - at - 16);
    check(first.find(e.first_fix) != std::string::npos,
          "the first item of What to fix is \"" + first + "\", expected it to say \"" + e.first_fix + "\"");
  }
  check(fs::exists(report_dir / "junit.xml"), "no junit.xml");
  // An implementation with integrators gets the work-precision diagram, with rows for
  // each of its integrators (in double) and for the suite's methods, Boost.Odeint's among them.
  std::vector<std::string> stepping;
  for (const auto& i : report.at("integrators"))
    for (const auto& sc : i.at("scalars"))
      if (sc == "double") stepping.push_back(i.at("name"));
  if (!stepping.empty()) {
    std::ifstream csv_in(report_dir / "figures" / "work-precision.csv");
    std::ostringstream csv_text;
    csv_text << csv_in.rdbuf();
    const std::string csv = csv_text.str();
    check(csv.rfind("problem,method,source,steps,vector_field_evaluations,seconds,error_at_t4\n", 0) == 0,
          "figures/work-precision.csv is missing or has no header");
    for (const auto& name : stepping)
      check(csv.find(",\"" + name + "\",subject,") != std::string::npos, "work-precision.csv has no row for " + name);
    check(csv.find(",\"odeint runge_kutta_dopri5 (adaptive)\",suite,") != std::string::npos,
          "work-precision.csv has no row for Boost.Odeint");
    check(md.find("## Work-precision diagram and long-time energy") != std::string::npos,
          "report.md has no work-precision section");
  }
}

int run_example(const std::string& name, const std::string& program, const std::string& source) {
  const Example* e = find_example(name);
  if (!e) {
    std::cout << "no expectations for example '" << name << "'\n";
    return 1;
  }
  std::cout << "example " << name << ": " << e->bug << "\n";
  const std::string dir = temp_dir(name);
  std::vector<std::string> argv{program,
                                "--quiet",
                                "--jobs",
                                "2",
                                "--report",
                                dir + "/report",
                                "--source",
                                source,
                                "--reproduce-prefix",
                                "geomech check " + source};
  if (std::find(e->args.begin(), e->args.end(), "--timeout") == e->args.end())
    argv.insert(argv.end(), {"--timeout", "60"});
  argv.insert(argv.end(), e->args.begin(), e->args.end());
  const auto pr = gm::harness::run_process(gm::harness::ProcessSpec{argv, {}, false});
  std::cout << pr.output;
  try {
    check_example_outputs(*e, fs::path(dir) / "report", pr.exit_code);
  } catch (const std::exception& ex) {
    check(false, ex.what());
  }
  fs::remove_all(dir);
  std::cout << (failures ? "example report not as expected\n" : "example report as expected\n");
  return failures ? 1 : 0;
}

// `geomech check FILE.cpp` from nothing: compile (in a fresh cache), link, check, report.
// correct.cpp's report is also held to its row of the examples' table (check_example_outputs):
// this test is the one complete check of correct.cpp in the suite (it was made twice,
// here and by a CMake-built example program, 35-45 s of ctest's time for the same verdicts).
int run_end_to_end(const std::string& name, const std::string& geomech, const std::string& source) {
  const std::string dir = temp_dir("e2e-" + name);
  std::vector<std::string> argv{geomech,    "check",         source,   "--cache-dir", dir + "/cache",
                                "--report", dir + "/report", "--jobs", "2",           "--quiet"};
  // The examples' limit per check (run_example): every check of correct.cpp ends within 60 s.
  if (name == "correct") argv.insert(argv.end(), {"--timeout", "60"});
  const auto t0 = std::chrono::steady_clock::now();
  const auto pr = gm::harness::run_process(gm::harness::ProcessSpec{argv, {}, false});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << pr.output;
  std::printf("end to end: `geomech check %s` from scratch took %.1f s (compile, link, check, report)\n",
              fs::path(source).filename().c_str(), seconds);
  try {
    const json report = read_json(fs::path(dir) / "report" / "verdicts.json");
    if (name == "correct") {
      check(pr.exit_code == 0, "exit status " + std::to_string(pr.exit_code) + ", expected 0");
      check(report.at("counts").at("PASS").get<int>() > 0, "nothing passed");
      for (const char* bad : {"FAIL", "CRASH", "TIMEOUT", "ERROR"})
        check(report.at("counts").at(bad).get<int>() == 0, std::string("some checks are ") + bad);
      const Example* e = find_example("correct");
      check(e != nullptr, "no expectations for example 'correct'");
      if (e) check_example_outputs(*e, fs::path(dir) / "report", pr.exit_code);
      // The second run finds everything up to date. What it checks does not matter here (the first
      // run's check is the one asserted above, correct.cpp's complete check): the
      // build is of the whole program whatever is selected (tools/geomech.cpp), so one property in
      // every scalar is enough to show that nothing is compiled again. this saves a
      // second complete check (about 24 s alone, 40-60 s under ctest -j2).
      std::vector<std::string> again_argv = argv;
      again_argv.insert(again_argv.end(), {"--property", "hat_is_cross_product"});
      const auto t1 = std::chrono::steady_clock::now();
      const auto again = gm::harness::run_process(gm::harness::ProcessSpec{again_argv, {}, false});
      const double s2 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      std::printf("the same program again (nothing to compile), one property, took %.1f s\n", s2);
      check(again.output.find("(up to date)") != std::string::npos, "the second run compiled again");
      check(again.exit_code == 0,
            "the second run's one property did not pass: exit status " + std::to_string(again.exit_code));
    } else if (name == "bug_nan") {
      // A NaN fails; the slot that needs sqrt is left out of the exact rationals, with the reason.
      check(pr.exit_code == 1, "exit status " + std::to_string(pr.exit_code) + ", expected 1");
      bool nan_fail = false, exact_reason = false;
      for (const auto& v : report.at("verdicts")) {
        const std::string prop = v.at("property"), scalar = v.at("scalar"), outcome = v.at("outcome"),
                          message = v.at("message");
        if (prop == "hamiltonian_3_3_is_3_4" && scalar == "double" && outcome == "FAIL" &&
            message.find("NaN") != std::string::npos)
          nan_fail = true;
        if (prop == "hamiltonian_3_3_is_3_4" && scalar == "exact" && outcome == "NOT PROVIDED" &&
            message.find("does not compile for exact") != std::string::npos &&
            message.find("no exact rational value") != std::string::npos)
          exact_reason = true;
      }
      check(nan_fail, "hamiltonian_3_3_is_3_4 does not fail in double with a message about NaN");
      check(exact_reason, "hamiltonian_3_3_is_3_4 in exact is not NOT PROVIDED with the compiler's reason and hint");
    } else {
      check(false, "no end-to-end expectations for " + name);
    }
  } catch (const std::exception& ex) {
    check(false, ex.what());
  }
  fs::remove_all(dir);
  return failures ? 1 : 0;
}

// `geomech check-class DIR`: one summary table, one report per implementation, the bad ones named.
int run_class(const std::string& class_dir, const std::string& geomech) {
  const std::string dir = temp_dir("class");
  const auto pr = gm::harness::run_process(
      gm::harness::ProcessSpec{{geomech, "check-class", class_dir, "--report", dir + "/reports", "--parallel", "2",
                                "--scalar", "double", "--trusted"},
                               {},
                               false});
  std::cout << pr.output;
  check(pr.exit_code == 1,
        "exit status " + std::to_string(pr.exit_code) + ", expected 1 (one fails, one does not compile)");
  std::ifstream f(fs::path(dir) / "reports" / "summary.md");
  std::stringstream summary;
  summary << f.rdbuf();
  const std::string s = summary.str();
  check(s.find("| alice | PASS |") != std::string::npos, "alice does not pass in the summary");
  check(s.find("| bob | **FAIL** |") != std::string::npos, "bob does not fail in the summary");
  check(s.find("| carol | **DOES NOT COMPILE** |") != std::string::npos, "carol is not reported as not compiling");
  check(s.find("| dave | PASS |") != std::string::npos, "dave (a folder with a header) does not pass");
  check(s.find("carol: does not compile") != std::string::npos && s.find("error") != std::string::npos,
        "the summary does not show carol's compiler error");
  for (const char* who : {"alice", "bob", "dave"})
    check(fs::exists(fs::path(dir) / "reports" / who / "report.md"), std::string("no report for ") + who);
  std::cout << s;
  fs::remove_all(dir);
  return failures ? 1 : 0;
}

// `check-class --shard K/N` and `merge-class`: the class in two shards, merged, gives
// the same summary table and the same verdicts as one unsharded run.
int run_class_shards(const std::string& class_dir, const std::string& geomech) {
  const std::string dir = temp_dir("class-shards");
  auto run = [&](std::vector<std::string> args) {
    std::vector<std::string> argv{geomech};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto pr = gm::harness::run_process(gm::harness::ProcessSpec{argv, {}, false});
    std::cout << pr.output;
    return pr;
  };
  const std::vector<std::string> common{"--parallel", "2", "--scalar", "double", "--trusted"};
  auto with = [&](std::vector<std::string> a) {
    a.insert(a.end(), common.begin(), common.end());
    return a;
  };
  const auto whole = run(with({"check-class", class_dir, "--report", dir + "/whole"}));
  const auto s1 = run(with({"check-class", class_dir, "--report", dir + "/shard1", "--shard", "1/2"}));
  const auto s2 = run(with({"check-class", class_dir, "--report", dir + "/shard2", "--shard", "2/2"}));
  const auto merged = run({"merge-class", dir + "/merged", dir + "/shard2", dir + "/shard1"});
  check(merged.exit_code == whole.exit_code, "merge-class exits " + std::to_string(merged.exit_code) +
                                                 ", the unsharded run " + std::to_string(whole.exit_code));
  auto read = [](const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  const std::string a = read(fs::path(dir) / "whole" / "summary.md"), b = read(fs::path(dir) / "merged" / "summary.md");
  check(!a.empty() && a == b,
        "the merged summary differs from the unsharded one:\n--- unsharded\n" + a + "\n--- merged\n" + b);
  const std::string s1sum = read(fs::path(dir) / "shard1" / "summary.md");
  check(s1sum.find("| alice |") != std::string::npos && s1sum.find("| bob |") == std::string::npos,
        "shard 1/2 should hold alice and carol (every second implementation from the first)");
  for (const char* who : {"alice", "bob", "dave"}) {
    const json x = read_json(fs::path(dir) / "whole" / who / "verdicts.json");
    const json y = read_json(fs::path(dir) / "merged" / who / "verdicts.json");
    check(x.at("counts") == y.at("counts"), std::string("the counts of ") + who + " differ after the merge");
  }
  const auto missing = run({"merge-class", dir + "/bad", dir + "/shard1"});
  check(missing.exit_code == 2 && missing.output.find("shards 2 of 2 are missing") != std::string::npos,
        "merging one shard of two is not refused with a clear message");
  fs::remove_all(dir);
  return failures ? 1 : 0;
}

// A student's own CMake project using the exported GeomechStudentConfig.cmake.
int run_cmake_package(const std::string& cmake, const std::string& config_dir, const std::string& source) {
  const fs::path dir = temp_dir("cmake-package");
  fs::copy_file(source, dir / "student.cpp");
  std::ofstream(dir / "CMakeLists.txt") << "cmake_minimum_required(VERSION 3.25)\nproject(student CXX)\n"
                                        << "find_package(GeomechStudent REQUIRED PATHS \"" << config_dir
                                        << "\" NO_DEFAULT_PATH)\ngeomech_add_student(check student.cpp)\n";
  using gm::harness::ProcessSpec;
  const auto configure = gm::harness::run_process(ProcessSpec{
      {cmake, "-S", dir.string(), "-B", (dir / "build").string(), "-DCMAKE_BUILD_TYPE=Release"}, {}, false});
  check(configure.exit_code == 0, "the student's project does not configure:\n" + configure.output);
  const auto build = gm::harness::run_process(ProcessSpec{{cmake, "--build", (dir / "build").string()}, {}, false});
  check(build.exit_code == 0, "the student's project does not build:\n" + build.output);
  if (build.exit_code == 0) {
    const auto run = gm::harness::run_process(
        ProcessSpec{{(dir / "build" / "check").string(), "--quiet", "--report", (dir / "report").string()}, {}, false});
    std::cout << run.output;
    check(run.exit_code == 0, "the student's check program fails");
    check(run.output.find("PASS") != std::string::npos, "no PASS in the summary");
  }
  fs::remove_all(dir);
  return failures ? 1 : 0;
}

std::string bracket(const std::string& s) { return "[==[" + s + "]==]"; }

int write_ctest_script(const std::string& out, const std::string& tsv, const std::string& geomech,
                       const std::string& source_dir, const std::string& cmake, const std::string& config_dir) {
  std::ifstream in(tsv);
  if (!in) {
    std::cerr << "cannot read " << tsv << "\n";
    return 1;
  }
  std::string self = fs::read_symlink("/proc/self/exe").string();
  std::ostringstream script;
  script << "# Generated by " << self << " --ctest-script; do not edit.\n";
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string name, program, source;
    if (!std::getline(fields, name, '\t') || !std::getline(fields, program, '\t') ||
        !std::getline(fields, source, '\t'))
      continue;
    const Example* e = find_example(name);
    if (!e) {
      std::cerr << "example '" << name << "' has no expectations in tests/example_tests.cpp\n";
      return 1;
    }
    const std::string test = "example." + name;
    script << "add_test(" << bracket(test) << " " << bracket(self) << " --example " << bracket(name) << " --program "
           << bracket(program) << " --source " << bracket(source) << ")\n";
    std::string labels = "examples;student";
    script << "set_tests_properties(" << bracket(test) << " PROPERTIES LABELS " << bracket(labels) << " TIMEOUT 300)\n";
  }
  for (const char* e2e : {"correct", "bug_nan"}) {
    const std::string test = std::string("student.end_to_end.") + e2e;
    script << "add_test(" << bracket(test) << " " << bracket(self) << " --end-to-end " << e2e << " --geomech "
           << bracket(geomech) << " --source " << bracket(source_dir + "/examples/students/" + e2e + ".cpp") << ")\n";
    script << "set_tests_properties(" << bracket(test)
           << " PROPERTIES LABELS \"student;end-to-end\" TIMEOUT 600 RESOURCE_LOCK compilers)\n";
  }
  script << "add_test(student.cmake_package " << bracket(self) << " --cmake-package " << bracket(cmake) << " --config "
         << bracket(config_dir) << " --source " << bracket(source_dir + "/tests/class/alice.cpp") << ")\n";
  script << "set_tests_properties(student.cmake_package PROPERTIES LABELS \"student;end-to-end\" TIMEOUT 600 "
            "RESOURCE_LOCK compilers)\n";
  script << "add_test(student.class_mode " << bracket(self) << " --class " << bracket(source_dir + "/tests/class")
         << " --geomech " << bracket(geomech) << ")\n";
  script << "set_tests_properties(student.class_mode PROPERTIES LABELS \"student;end-to-end\" TIMEOUT 600 "
            "RESOURCE_LOCK compilers)\n";
  script << "add_test(student.class_shards_merge " << bracket(self) << " --class-shards "
         << bracket(source_dir + "/tests/class") << " --geomech " << bracket(geomech) << ")\n";
  script << "set_tests_properties(student.class_shards_merge PROPERTIES LABELS \"student;end-to-end\" TIMEOUT 900 "
            "RESOURCE_LOCK compilers)\n";
  const std::string tmp = out + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    f << script.str();
    if (!f) return 1;
  }
  fs::rename(tmp, out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> a;
  for (int i = 1; i + 1 < argc; i += 2) a[argv[i]] = argv[i + 1];
  try {
    if (a.count("--ctest-script"))
      return write_ctest_script(a["--ctest-script"], a["--examples"], a["--geomech"], a["--source-dir"], a["--cmake"],
                                a["--config"]);
    if (a.count("--cmake-package")) return run_cmake_package(a["--cmake-package"], a["--config"], a["--source"]);
    if (a.count("--example")) return run_example(a["--example"], a["--program"], a["--source"]);
    if (a.count("--end-to-end")) return run_end_to_end(a["--end-to-end"], a["--geomech"], a["--source"]);
    if (a.count("--class")) return run_class(a["--class"], a["--geomech"]);
    if (a.count("--class-shards")) return run_class_shards(a["--class-shards"], a["--geomech"]);
  } catch (const std::exception& e) {
    std::cout << "error: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "usage: see the comment at the top of tests/example_tests.cpp\n";
  return 2;
}
