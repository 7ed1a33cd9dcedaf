// Tests of the harness itself: isolation (crash, abort, hang, exception, exit, runaway memory),
// the check engine on deliberately broken subjects, claims and "holds (not claimed)", the report
// writers, the trajectory reader's error messages, the reference flow, and the helpers that read
// compiler output. Nothing here compiles a student's code; tests/example_tests.cpp does that.
#include "harness/program/build.hpp"
#include "harness/engine/check.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/trajectories/reference_flow.hpp"
#include "harness/reports/report.hpp"
#include "harness/engine/integrator_verdicts.hpp"
#include "harness/reports/svg.hpp"
#include "harness/engine/thorough_only.hpp"
#include "harness/engine/trajectory.hpp"
#include "properties/support/loglog_fit.hpp"
#include "harness/engine/verdict_io.hpp"
#include "impl/reference_subject.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/tolerance.hpp"
#include "tests/support/ctest_script.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace gm::harness {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  std::string t = (fs::temp_directory_path() / "geomech-harness-XXXXXX").string();
  EXPECT_NE(::mkdtemp(t.data()), nullptr);
  return t;
}

// ---- isolation ------------------------------------------------------------------------------

TEST(Isolation, EachWayOfDyingIsToldApart) {
  IsolationOptions o;
  o.jobs = 3;
#if defined(__SANITIZE_ADDRESS__)
  // Under the sanitizers a child that calls exit() first runs LeakSanitizer's scan of the whole
  // process, which took more than 1 s on CI's loaded machine: the hang is told apart at 30 s.
  o.timeout_seconds = 30;
#else
  o.timeout_seconds = 1;
#endif
  const std::vector<std::function<std::string()>> tasks = {
      [] { return std::string("fine"); },
      []() -> std::string {
        std::fputs("about to crash\n", stderr);
        volatile int* p = nullptr;
        *p = 1;
        return "";
      },
      []() -> std::string { std::abort(); },
      []() -> std::string {
        for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      },
      []() -> std::string { throw std::runtime_error("thrown outside RapidCheck"); },
      []() -> std::string { std::exit(3); },
      [] { return std::string(1 << 20, 'x'); },  // larger than a pipe's buffer
  };
  const auto r = run_isolated(tasks, o);
  ASSERT_EQ(r.size(), tasks.size());
  EXPECT_EQ(r[0].status, TaskResult::Status::Ok);
  EXPECT_EQ(r[0].payload, "fine");
  EXPECT_EQ(r[1].status, TaskResult::Status::Crashed);
#if defined(__SANITIZE_ADDRESS__)
  // The sanitizers catch the null store (UBSan) or the SIGSEGV (ASan), report it and exit or abort:
  // the first line of their report is named.
  EXPECT_NE(r[1].detail.find("the sanitizer's report"), std::string::npos) << r[1].detail;
  EXPECT_TRUE(r[1].detail.find("null pointer") != std::string::npos ||
              r[1].detail.find("AddressSanitizer: SEGV") != std::string::npos)
      << r[1].detail;
#else
  EXPECT_EQ(r[1].signal, SIGSEGV);
  EXPECT_NE(r[1].detail.find("SIGSEGV"), std::string::npos) << r[1].detail;
#endif
  EXPECT_NE(r[1].output.find("about to crash"), std::string::npos) << r[1].output;
  EXPECT_EQ(r[2].status, TaskResult::Status::Crashed);
  EXPECT_EQ(r[2].signal, SIGABRT);
  EXPECT_EQ(r[3].status, TaskResult::Status::TimedOut);
  EXPECT_NE(r[3].detail.find("did not finish within " + std::to_string(static_cast<int>(o.timeout_seconds)) + " s"),
            std::string::npos)
      << r[3].detail;
  EXPECT_EQ(r[4].status, TaskResult::Status::Threw);
  EXPECT_NE(r[4].detail.find("thrown outside RapidCheck"), std::string::npos);
  EXPECT_EQ(r[5].status, TaskResult::Status::Crashed);
  EXPECT_NE(r[5].detail.find("exited with status 3"), std::string::npos) << r[5].detail;
  EXPECT_EQ(r[6].status, TaskResult::Status::Ok);
  EXPECT_EQ(r[6].payload.size(), std::size_t(1) << 20);
}

// A machine busier than its cores: `n` processes spinning on the first CPU this process may use,
// with this process (and so the children it forks) pinned there too; undone at the end of scope.
class CrowdedCore {
 public:
  explicit CrowdedCore(int n) {
    ::sched_getaffinity(0, sizeof saved_, &saved_);
    cpu_set_t one;
    CPU_ZERO(&one);
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &saved_)) {
        CPU_SET(c, &one);
        break;
      }
    ::sched_setaffinity(0, sizeof one, &one);
    for (int i = 0; i < n; ++i) {
      const pid_t pid = ::fork();
      if (pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        for (volatile unsigned long x = 0;; x = x + 1) {}
      }
      if (pid > 0) burners_.push_back(pid);
    }
  }
  ~CrowdedCore() {
    for (pid_t pid : burners_) ::kill(pid, SIGKILL);
    for (pid_t pid : burners_) ::waitpid(pid, nullptr, 0);
    ::sched_setaffinity(0, sizeof saved_, &saved_);
  }

 private:
  cpu_set_t saved_{};
  std::vector<pid_t> burners_;
};

// `seconds` of this process's CPU time, spent computing.
std::string compute_for(double seconds) {
  const double start = self_cpu_seconds();
  volatile double x = 0;
  while (self_cpu_seconds() - start < seconds)
    for (int i = 0; i < 10000; ++i) x = x + 1e-9 * i;
  return "computed";
}

// Starved is not waiting: the kernel's run-queue accounting, not the task's share of the CPU,
// tells a task the machine starves from one that sleeps. Eight processes spin on the core the task
// runs on: it gets about a ninth of it, so its 0.4 s of CPU take about 3.6 s of wall clock, past the
// 2 s wall guard. It was runnable all along, so it is let finish (before: stopped as "it waits ...
// rather than computes", a verdict on correct code); past the busy limit it is Busy, the machine's.
// The sleeping task beside it is runnable almost never, and is stopped as waiting.
TEST(Isolation, StarvedIsNotWaiting) {
  const bool kernel_tells = tree_times(::getpid()).queued_known;
  CrowdedCore crowded(8);
  IsolationOptions o;
  o.jobs = 1;
  o.timeout_seconds = 2;  // of CPU
  o.wall_factor = 1;
  o.wall_floor = 0;  // the wall guard: 2 s
  auto r = run_isolated({[] { return compute_for(0.4); },
                         []() -> std::string {
                           for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(10));
                         }},
                        o);
  ASSERT_EQ(r.size(), 2u);
  if (!kernel_tells) {  // no schedstat: waiting and starving cannot be told apart, and neither is the code's
    EXPECT_EQ(r[0].status, TaskResult::Status::Busy) << r[0].detail;
    EXPECT_NE(r[0].detail.find("is not known"), std::string::npos) << r[0].detail;
    return;
  }
  // The control: it really was starved (queued longer than it ran, and past the wall guard).
  EXPECT_GT(r[0].seconds, o.timeout_seconds) << "the task was not slowed past the wall guard: the test shows nothing";
  EXPECT_GT(r[0].queued_seconds, r[0].cpu_seconds) << r[0].seconds << " s";
  EXPECT_EQ(r[0].status, TaskResult::Status::Ok) << r[0].detail;
  EXPECT_EQ(r[1].status, TaskResult::Status::TimedOut) << r[1].detail;
  EXPECT_NE(r[1].detail.find("asleep: it waits"), std::string::npos) << r[1].detail;

  // A task whose work is done by processes that end one after the other (compilers, forked
  // sessions) was starved as much: the delay each showed before it ended still counts.
  r = run_isolated({[] {
                     for (int k = 0; k < 3; ++k) {
                       const pid_t child = ::fork();
                       if (child == 0) {
                         compute_for(0.15);
                         ::_exit(0);
                       }
                       ::waitpid(child, nullptr, 0);
                     }
                     return std::string("computed by children");
                   }},
                   o);
  EXPECT_GT(r[0].seconds, o.timeout_seconds) << "the children were not slowed past the wall guard: this shows nothing";
  EXPECT_EQ(r[0].status, TaskResult::Status::Ok) << r[0].detail;

  // Past the busy limit (here 1.25 times the wall guard, 2.5 s), the starved task is the machine's.
  o.busy_factor = 1.25;
  r = run_isolated({[] { return compute_for(0.4); }}, o);
  EXPECT_EQ(r[0].status, TaskResult::Status::Busy) << r[0].detail;
  EXPECT_NE(r[0].detail.find("the machine starved it"), std::string::npos) << r[0].detail;
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(Isolation, RunawayAllocationHitsTheMemoryLimit) {
  IsolationOptions o;
  o.memory_limit_mb = 256;
  const auto r = run_isolated({[]() -> std::string {
                                std::vector<char> big(std::size_t(2) << 30, 'x');
                                return std::to_string(big.size());
                              }},
                              o);
  EXPECT_EQ(r[0].status, TaskResult::Status::Threw);
  EXPECT_NE(r[0].detail.find("bad_alloc"), std::string::npos) << r[0].detail;
}
#endif

// ---- the check engine on broken subjects ------------------------------------------------------

const Verdict* find(const CheckResult& r, const std::string& property, const std::string& scalar) {
  for (const auto& v : r.verdicts)
    if (v.property == property && v.scalar == scalar) return &v;
  return nullptr;
}

CheckConfig quick(std::vector<std::string> props) {
  CheckConfig c;
  c.properties = std::move(props);
  c.jobs = 3;
  c.timeout_seconds = 1;
  c.portraits = false;
  return c;
}

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
            {.id = "test_only_casimir_claim",
             .spec = "s3.casimir",
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
  decide_first_fixes(r);  // as the engine does, once the verdicts are complete
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

// The precompiled geomech/student.hpp only saves time, and GCC drops an unusable one without a
// word, so this asks the compiler: the cached compile command of a one-slot file, run again with
// -Winvalid-pch, must not say the .gch was rejected. Control: the same command with a macro the
// header tests (as a retry with GEOMECH_SKIP_INTEGRATORS has) must say so.
TEST(Build, ThePrecompiledStudentHeaderIsUsed) {
  const Toolchain tc = load_toolchain(default_toolchain_path());
  ASSERT_FALSE(tc.precompiled_header.empty()) << tc.path << " names no precompiled header with a .gch beside it";
  const fs::path dir = temp_dir();
  const fs::path src = dir / "one_slot.cpp";
  std::ofstream(src) << "#include <geomech/student.hpp>\nusing namespace gm;\nstruct OneSlot {\n"
                        "  template <class T> static Mat3<T> hat(const Vec3<T>& v) {\n"
                        "    Mat3<T> m; m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0); return m; }\n"
                        "};\nGEOMECH_STUDENT(OneSlot);\n";
  BuildOptions o;
  o.cache_dir = (dir / "cache").string();
  o.mp50 = o.exact = false;
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
  const std::string control = compiler_says(" -DGEOMECH_SKIP_INTEGRATORS=1");
  EXPECT_NE(control.find("not used"), std::string::npos) << control;
  fs::remove_all(dir);
}

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

TEST(TrajectoryFiles, ARunTooLongForTheReferenceIsRefusedAtOnce) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "long.txt") << "# geomech-trajectory 1\n# system: rigid_body\n# inertia: 2 1.5 1\n# step: 1\n"
                                  << "0 1000 2000 3000\n1e9 1000 2000 3000\n";
  const auto t0 = std::chrono::steady_clock::now();
  try {
    check_trajectories({(dir / "long.txt").string()}, {});
    ADD_FAILURE() << "accepted";
  } catch (const TrajectoryError& e) {
    EXPECT_NE(std::string(e.what()).find("Taylor steps"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
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

std::vector<std::string> labels(const std::string& suite, const std::string&) {
  if (suite == "TrajectoryFiles") return {"meta", "harness", "bad-input"};
  if (suite == "RemoteSubject" || suite == "ProtocolCodec") return {"meta", "harness", "protocol", "python"};
  if (suite == "Gradebook" || suite == "SourceCalls" || suite == "HtmlPage" || suite == "ClassRecord" ||
      suite == "Autograder")
    return {"meta", "harness", "lecturer"};
  return {"meta", "harness"};
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

int main(int argc, char** argv) {
  if (gm::testing_support::maybe_write_ctest_script(argc, argv, gm::harness::labels)) return 0;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
