// harness/checking/: the check on deliberately broken subjects, claims and "holds (not claimed)", the
// runs left to --thorough.
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

// ---- the check engine on broken subjects ------------------------------------------------------

TEST(CheckEngine, ACrashHangNaNOrExceptionFailsThatPropertyAlone) {
  SubjectSet s = mutate(reference_subject(), "broken", "broken on purpose", [](auto& sub) {
    using T = typename std::decay_t<decltype(sub)>::Scalar;
    sub.hat = [](const Vec3<T>&) -> Mat3<T> {
      std::raise(SIGSEGV);
      return Mat3<T>::Zero();
    };
    sub.euler_3_8 = [](const Vec3<T>&, const Vec3<T>&) -> Vec3<T> {
      for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    };
    sub.pairing = [](const MatX<T>&, const MatX<T>&) -> T { throw std::domain_error("pairing refuses"); };
  });
  // NaN only where NaN exists: the floats.
  auto d = std::make_shared<Subject<double>>(*s.d);
  d->hamiltonian_3_4 = [](const Vec3<double>&, const Vec3<double>&) { return std::nan(""); };
  s.d = d;
  const CheckResult r = run_check(s, {},
                                  quick({"hat_is_cross_product", "euler_form_3_8", "trace_pairing_is_dot_product",
                                         "hamiltonian_3_3_is_3_4", "euler_form_3_7"}));
  for (const char* scalar : {"double", "mp50", "exact"}) {
    EXPECT_EQ(find(r, "hat_is_cross_product", scalar)->outcome, Outcome::Crash);
    EXPECT_EQ(find(r, "euler_form_3_8", scalar)->outcome, Outcome::Timeout);
    const Verdict* p = find(r, "trace_pairing_is_dot_product", scalar);
    EXPECT_EQ(p->outcome, Outcome::Fail);
    EXPECT_NE(p->message.find("pairing refuses"), std::string::npos) << p->message;
    EXPECT_EQ(find(r, "euler_form_3_7", scalar)->outcome, Outcome::Pass);
  }
  const Verdict* nan = find(r, "hamiltonian_3_3_is_3_4", "double");
  EXPECT_EQ(nan->outcome, Outcome::Fail);
  EXPECT_NE(nan->message.find("NaN"), std::string::npos) << nan->message;
  EXPECT_EQ(find(r, "hamiltonian_3_3_is_3_4", "mp50")->outcome, Outcome::Pass);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.exit_code(), 1);
  const Verdict* crash = find(r, "hat_is_cross_product", "double");
#if defined(__SANITIZE_ADDRESS__)
  EXPECT_NE(crash->message.find("AddressSanitizer: SEGV"), std::string::npos) << crash->message;
#else
  EXPECT_NE(crash->message.find("SIGSEGV"), std::string::npos) << crash->message;
#endif
  EXPECT_NE(reproduce_command(r, *crash).find("--property hat_is_cross_product --scalar double"), std::string::npos);
}

TEST(CheckEngine, WhatIsMissingIsNotProvidedWithTheReason) {
  SubjectSet s;
  s.name = "partial";
  auto d = std::make_shared<Subject<double>>();
  d->hat = reference_subject().d->hat;
  s.d = d;  // double only, one slot
  SubjectInfo info;
  info.slot_notes["exact"]["hat"] = "does not compile for exact: example";
  auto mp = std::make_shared<Subject<Real50>>();
  mp->vee = reference_subject().mp->vee;
  s.mp = mp;
  const CheckResult r = run_check(s, info, quick({"hat_is_cross_product", "vee_inverts_hat", "euler_form_2_1"}));
  EXPECT_EQ(find(r, "hat_is_cross_product", "double")->outcome, Outcome::Pass);
  const Verdict* mp_hat = find(r, "hat_is_cross_product", "mp50");
  EXPECT_EQ(mp_hat->outcome, Outcome::NotProvided);
  EXPECT_NE(mp_hat->message.find("provided for double only"), std::string::npos) << mp_hat->message;
  EXPECT_NE(find(r, "hat_is_cross_product", "exact")->message.find("does not compile for exact"), std::string::npos);
  EXPECT_NE(find(r, "euler_form_2_1", "double")->message.find("needs slot 'euler_2_1', which is not provided"),
            std::string::npos);
  EXPECT_TRUE(r.ok());  // not provided is reported, not failed
  EXPECT_EQ(r.count(Outcome::NotProvided), 8);
  for (const auto& v : r.verdicts)
    if (v.outcome == Outcome::NotProvided) {
      EXPECT_FALSE(v.message.empty());
    }
}

// ---- claims ---------------------------------------------------------------------------------

// A test-only integrator property (registered in this test program only): one step from a fixed
// state must keep |Pi|^2 to round-off if the integrator claims it. It also records a series.
template <class T>
void test_only_casimir_claim(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& claims) {
  const Vec3<T> I(T(2), T(3) / T(2), T(1));
  const RigidBodyState<T> x0{Vec3<T>(T(3) / T(8), T(1) / T(4), T(7) / T(8)), Mat3<T>::Identity()};
  const RigidBodyState<T> x1 = in.rigid_body_step(I, x0, T(1) / T(8));
  const double change = to_double(T(abs_value(T(x1.Pi.squaredNorm() - x0.Pi.squaredNorm()))));
  const bool holds = change <= 16 * eps_double<T>();
  Series s;
  s.figure = "one step";
  s.name = "|Pi|^2 change";
  s.log_y = true;
  s.points = {{1.0, change > 0 ? change : 1e-300}};
  record_series(s);
  judge_claim("casimir", claims.casimir, holds, "||Pi1|^2 - |Pi0|^2| = " + std::to_string(change));
}
GM_PROPERTY(test_only_casimir_claim, integrator_scalars,
            {.spec = "s3.casimir",
             .title = "test only: one step keeps |Pi|^2",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {},
             .scope = Scope::Integrator,
             .step = StepKind::RigidBody,
             .judges = {"casimir"}});

template <class T>
RigidBodyState<T> rotate_step(const Vec3<T>&, const RigidBodyState<T>& x, const T&) {
  Mat3<T> R;  // an exact rotation (3-4-5 triangle): keeps |Pi|^2
  R << T(3) / T(5), T(-4) / T(5), T(0), T(4) / T(5), T(3) / T(5), T(0), T(0), T(0), T(1);
  return {R * x.Pi, x.O};
}
template <class T>
RigidBodyState<T> stretch_step(const Vec3<T>&, const RigidBodyState<T>& x, const T& h) {
  return {(x.Pi * (T(1) + h)).eval(), x.O};
}

TEST(Claims, FalseClaimsFailAndUnclaimedPropertiesAreReported) {
  SubjectSet s = mutate(reference_subject(), "with_integrators", "", [](auto& sub) {
    using T = typename std::decay_t<decltype(sub)>::Scalar;
    if constexpr (!is_exact_v<T>) {
      Integrator<T> a, b, c, d;
      a.name = "rotation_claimed";
      a.rigid_body_step = rotate_step<T>;
      b.name = "rotation_unclaimed";
      b.rigid_body_step = rotate_step<T>;
      c.name = "stretch_claimed";
      c.rigid_body_step = stretch_step<T>;
      d.name = "stretch_unclaimed";
      d.rigid_body_step = stretch_step<T>;
      sub.integrators = {a, b, c, d};
    }
  });
  for (const char* n : {"rotation_claimed", "stretch_claimed"}) {
    IntegratorClaims c;
    c.integrator = n;
    c.casimir = true;
    s.claims.push_back(c);
  }
  CheckConfig cfg = quick({"test_only_casimir_claim"});
  cfg.portraits = true;
  const CheckResult r = run_check(s, {}, cfg);
  std::map<std::string, std::string> status;
  for (const auto& i : r.integrators)
    for (const auto& row : claim_rows(r, i))
      if (row.claim == "casimir") status[i.name] = row.status;
  // Only the test's check of the casimir ran: a verified claim says by which checks it was decided.
  EXPECT_EQ(status["rotation_claimed"].rfind("verified by the checks that ran (double, mp50)", 0), 0u)
      << status["rotation_claimed"];
  EXPECT_EQ(status["rotation_unclaimed"].rfind("holds (not claimed) by the checks that ran", 0), 0u)
      << status["rotation_unclaimed"];
  EXPECT_EQ(status["stretch_claimed"], "FALSE CLAIM");
  EXPECT_EQ(status["stretch_unclaimed"], "does not hold (not claimed)");
  EXPECT_EQ(r.count(Outcome::Fail), 2);  // the false claim, in double and in mp50
  // Series carried by the verdicts and the portraits become figures, linked from the Markdown.
  const auto figures = report_figures(r);
  bool one_step = false, convergence = false;
  for (const auto& f : figures) {
    one_step = one_step || f.file.find("test_only_casimir_claim-rotation_claimed-one-step") != std::string::npos;
    convergence = convergence || f.file == "figures/portrait-stretch_claimed-convergence.svg";
  }
  EXPECT_TRUE(one_step);
  EXPECT_TRUE(convergence);
  const std::string md = markdown_report(r, nullptr);
  EXPECT_NE(md.find("**FALSE CLAIM**"), std::string::npos);
  EXPECT_NE(md.find("holds (not claimed)"), std::string::npos);
  EXPECT_NE(md.find("](figures/portrait-rotation_claimed-invariants-over-time.svg)"), std::string::npos);
}

// A check left to --thorough is not run, and every report says so (never a silent skip);
// one whose slots are missing stays NOT PROVIDED, which says more.
TEST(CheckEngine, ARunLeftToThoroughIsListedNotRun) {
  CheckConfig cfg = quick({"hat_is_cross_product", "vee_inverts_hat"});
  cfg.thorough_only = {"hat_is_cross_product/mp50"};
  cfg.thorough_only_note = "a note on why";
  const CheckResult r = run_check(reference_subject(), {}, cfg);
  EXPECT_EQ(find(r, "hat_is_cross_product", "mp50"), nullptr);
  ASSERT_NE(find(r, "hat_is_cross_product", "double"), nullptr);
  EXPECT_EQ(find(r, "hat_is_cross_product", "double")->outcome, Outcome::Pass);
  EXPECT_EQ(find(r, "vee_inverts_hat", "mp50")->outcome, Outcome::Pass);
  ASSERT_EQ(r.left_to_thorough, std::vector<std::string>{"hat_is_cross_product [mp50]"});
  EXPECT_TRUE(r.ok());
  EXPECT_NE(r.selection.find("1 costly 50-digit runs left to --thorough"), std::string::npos) << r.selection;
  const std::string md = markdown_report(r, nullptr), xml = junit_report(r);
  EXPECT_NE(md.find("## Left to --thorough"), std::string::npos);
  EXPECT_NE(md.find("`hat_is_cross_product [mp50]`"), std::string::npos);
  EXPECT_NE(xml.find("<skipped message=\"LEFT TO --thorough: a note on why\"/>"), std::string::npos) << xml;
  EXPECT_NE(json_report(r, nullptr).dump().find("\"left_to_thorough\":[\"hat_is_cross_product [mp50]\"]"),
            std::string::npos);

  SubjectSet no_hat = mutate(reference_subject(), "no_hat", "hat missing", [](auto& sub) { sub.hat = nullptr; });
  const CheckResult m = run_check(no_hat, {}, cfg);
  EXPECT_TRUE(m.left_to_thorough.empty());
  ASSERT_NE(find(m, "hat_is_cross_product", "mp50"), nullptr);
  EXPECT_EQ(find(m, "hat_is_cross_product", "mp50")->outcome, Outcome::NotProvided);
}

// spec/thorough_only.json names 50-digit runs of properties that exist (a renamed property would
// otherwise silently run again, or a typo leave nothing out).
TEST(CheckEngine, TheRunsLeftToThoroughAreFiftyDigitRunsOfRealProperties) {
  const ThoroughOnlySelection t = load_thorough_only(default_thorough_only_path());
  ASSERT_FALSE(t.checks.empty());
  for (const auto& c : t.checks) {
    const auto slash = c.find('/');
    ASSERT_NE(slash, std::string::npos) << c;
    EXPECT_EQ(c.substr(slash + 1), "mp50") << c;
    const Property* p = find_property(c.substr(0, slash));
    ASSERT_NE(p, nullptr) << c;
    EXPECT_TRUE(p->runs_in(ScalarKind::MP50)) << c;
  }
  EXPECT_NE(t.provenance.find("geomech mutants --matrix"), std::string::npos) << t.provenance;
}

}  // namespace
}  // namespace gm::harness
