// harness/isolation/: each way of dying told apart, a starved task from one that waits, the memory
// limit.
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
#include "tests/harness/harness_support.hpp"

namespace gm::harness {
namespace {

namespace fs = std::filesystem;
using namespace harness_testing;

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

}  // namespace
}  // namespace gm::harness
