// harness/isolation/: each way of dying told apart, a starved task from one that waits, the memory
// limit.
#include "harness/checking/check.hpp"
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/thorough_only.hpp"
#include "harness/checking/trajectory.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/isolation/run_queue_account.hpp"
#include "harness/isolation/work_limit.hpp"
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

// Whom a wait is owed to, from the kernel's accounting of each task (harness/isolation/
// run_queue_account.hpp), on accounts written here: no timing, no machine.
TreeTimes tasks_at(const std::vector<TaskTimes>& times, int cores) {
  TreeTimes t;
  t.queued_known = true;
  for (std::size_t i = 0; i < times.size(); ++i) t.tasks[static_cast<pid_t>(100 + i)] = times[i];
  for (int c = 0; c < cores; ++c) t.cpus.insert(c);
  return t;
}

// `n` tasks looked at `looks` times, a second apart, each of them `cpu` and `queued` seconds of
// every second.
RunQueueAccount account_of(int n, double cpu, double queued, int cores, int looks = 10) {
  RunQueueAccount a;
  for (int k = 1; k <= looks; ++k)
    a.look(tasks_at(std::vector<TaskTimes>(static_cast<std::size_t>(n), TaskTimes{k * cpu, k * queued}), cores), k);
  return a;
}

TEST(RunQueueAccount, AHerdOfItsOwnIsNotAStarvedMachine) {
  // One task queued 90% of the time, the tree's only one: the machine held its core.
  const RunQueueAccount alone = account_of(1, 0.1, 0.9, 1);
  EXPECT_NEAR(alone.queued_by_machine(), 9.0, 1e-9);
  EXPECT_FALSE(alone.starves_itself());
  // Ten tasks sharing one core, each 0.1 s on it and 0.9 s queued a second: summed, the queue is nine
  // times the wall clock (what the old accounting called starved); per task, every second of the
  // waited-on task's queue is explained by its siblings' CPU, and the tree starves itself.
  const RunQueueAccount herd = account_of(10, 0.1, 0.9, 1);
  EXPECT_NEAR(herd.tree_queued(), 90.0, 1e-9);
  EXPECT_GT(herd.tree_queued(), herd.seconds()) << "the control: summed, the herd's queue outgrows the wall clock";
  EXPECT_NEAR(herd.queued_by_machine(), 0.0, 1e-9);
  EXPECT_TRUE(herd.starves_itself());
  EXPECT_LE(herd.waited_runnable(), herd.seconds());
  // Two tasks on two cores, each queued 90% by others: as many runnable as cores, the machine's.
  const RunQueueAccount pair = account_of(2, 0.1, 0.9, 2);
  EXPECT_NEAR(pair.queued_by_machine(), 8.0, 1e-9);
  EXPECT_FALSE(pair.starves_itself());
}

TEST(WorkLimit, OnlyAStarvedTaskIsTheMachines) {
  const WorkLimit limit{1, 1, 0, 4};  // 1 s of CPU, the wall guard at 1 s, the busy limit at 4 s
  auto judge = [&](const RunQueueAccount& a, double wall, double cpu) {
    WorkSoFar w;
    w.wall = wall;
    w.cpu = cpu;
    w.known = true;
    w.looked_a_second = true;
    w.account = &a;
    return judge_work(limit, w);
  };
  // Starved at the busy limit: the machine's.
  const RunQueueAccount starved = account_of(1, 0.1, 0.9, 1, 5);
  EXPECT_FALSE(judge(starved, 0.9, 0.1).stop);
  EXPECT_FALSE(judge(starved, 3, 0.3).stop) << "runnable all along: it goes on past the wall guard";
  const LimitVerdict busy = judge(starved, 5, 0.5);
  EXPECT_TRUE(busy.stop && busy.machine) << busy.detail;
  EXPECT_NE(busy.detail.find("the machine starved it"), std::string::npos) << busy.detail;
  // A herd of its own: the code's, past its time, in words that say so.
  const RunQueueAccount herd = account_of(10, 0.01, 0.5, 1, 2);
  const LimitVerdict self = judge(herd, 2, 0.2);
  EXPECT_TRUE(self.stop && !self.machine) << self.detail;
  EXPECT_NE(self.detail.find("it starves itself"), std::string::npos) << self.detail;
  EXPECT_NE(self.detail.find("more runnable tasks than its share of cores"), std::string::npos) << self.detail;
  // Asleep past its time: the code's, at once.
  const RunQueueAccount asleep = account_of(1, 0.001, 0.0, 1, 2);
  const LimitVerdict waits = judge(asleep, 2, 0.002);
  EXPECT_TRUE(waits.stop && !waits.machine) << waits.detail;
  EXPECT_NE(waits.detail.find("asleep: it waits"), std::string::npos) << waits.detail;
  // Its CPU time: the code's.
  const LimitVerdict cpu = judge(starved, 1.5, 1.2);
  EXPECT_TRUE(cpu.stop && !cpu.machine) << cpu.detail;
  // No accounting: the wall guard, and nobody knows.
  WorkSoFar unknown;
  unknown.wall = 1.5;
  const LimitVerdict blind = judge_work(limit, unknown);
  EXPECT_TRUE(blind.stop && blind.machine) << blind.detail;
  EXPECT_NE(blind.detail.find("is not known"), std::string::npos) << blind.detail;
}

// A herd of the task's own children, pinned to its core and waking together, while the task
// sleeps (the attack of a submission that would pass its TIMEOUT off as a starved machine): the
// code's TIMEOUT, in the kernel's words, even with the busy limit close. The control: summed over
// the tree, its queue outgrows the wall clock, as the old accounting read it.
TEST(Isolation, AHerdOfItsOwnChildrenStarvesItself) {
  if (!tree_times(::getpid()).queued_known) GTEST_SKIP() << "this kernel keeps no schedstat";
  IsolationOptions o;
  o.timeout_seconds = 1;
  o.wall_factor = 1;
  o.wall_floor = 0;
  o.busy_factor = 3;
  const auto r = run_isolated({[]() -> std::string {
                                cpu_set_t mine, one;
                                ::sched_getaffinity(0, sizeof mine, &mine);
                                CPU_ZERO(&one);
                                for (int c = 0; c < CPU_SETSIZE; ++c)
                                  if (CPU_ISSET(c, &mine)) {
                                    CPU_SET(c, &one);
                                    break;
                                  }
                                ::sched_setaffinity(0, sizeof one, &one);
                                for (int k = 0; k < 16; ++k)
                                  if (::fork() == 0) {
                                    using Clock = std::chrono::steady_clock;
                                    for (;;) {
                                      const auto period = std::chrono::milliseconds(100);
                                      std::this_thread::sleep_for(period - Clock::now().time_since_epoch() % period);
                                      const auto start = Clock::now();
                                      while (Clock::now() - start < std::chrono::milliseconds(30)) {}
                                    }
                                  }
                                for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
                              }},
                              o);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].status, TaskResult::Status::TimedOut) << r[0].detail;
  EXPECT_NE(r[0].detail.find("it starves itself"), std::string::npos) << r[0].detail;
  EXPECT_GT(r[0].queued_seconds, r[0].seconds) << "the control: summed, the herd's queue should outgrow the wall clock";
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
