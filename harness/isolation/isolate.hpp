// Isolation: each task runs in a forked child process, so that a segmentation fault, an abort, a
// hang or a runaway allocation in the code under test ends that task alone. The child sends its
// result back over a pipe; its stdout and stderr are captured (the last few kilobytes are kept,
// to show with a crash). The parent runs up to `jobs` children at once and kills a child (and
// its process group) that exceeds the timeout.
//
// The calling process must be single-threaded when it calls run_isolated (fork copies only the
// calling thread).
#pragma once

#include "harness/isolation/process_cpu.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gm::harness {

struct TaskResult;

struct IsolationOptions {
  int jobs = 1;  // children running at once
  // The limit of a task (slow is judged by the work done): the CPU seconds of the code under test,
  // its child's process tree and its worker's server (worker_times) together. A wall clock of
  // wall_factor times as long (and at least wall_floor more) stays, for a task that waits (sleeps,
  // reads input) and uses no CPU. Which it is, the kernel says, of the task the check waits on (the
  // most runnable task of its trees, harness/isolation/run_queue_account.hpp): runnable (on a CPU or
  // queued for one, schedstat's run_delay) for less than half the wall guard, it slept and is TimedOut
  // ("it waits"); runnable for more, it was computing or starved and goes on. A tree whose own tasks
  // keep more of them runnable than its cores is TimedOut past its time ("it starves itself"). Only a
  // machine that kept that task queued, while no task of its own ran, for most of busy_factor times
  // the wall guard stops it as Busy: the machine's fault.
  double timeout_seconds = 120;
  double wall_factor = 3;
  double wall_floor = 60;
  double busy_factor = 8;  // a starved task is stopped, as Busy, at this many times the wall guard
  // The CPU and run-queue delay the server of worker slot w has had so far (out-of-process
  // implementations); none: the code runs in the task's own process.
  std::function<TreeTimes(int)> worker_times;
  long memory_limit_mb = 4096;  // writable-memory limit of a child, RLIMIT_DATA (not under AddressSanitizer)
  bool isolate = true;          // false: run the tasks in this process, one after the other (debugging)
  // Called in the parent as each task starts (index), and as it finishes (index, its result): a
  // check reports each result the moment it is known (harness/checking/check_events.hpp).
  std::function<void(std::size_t)> on_started;
  std::function<void(std::size_t, const TaskResult&)> on_finished;
  // Called in the parent while tasks run, between looks at them (about 50 times a second): a
  // progress line that names what is running and for how long (class mode).
  std::function<void()> on_idle;
  // Worker slots: a running task occupies one of `jobs` slots, numbered from 0; in the
  // task, current_worker() is its slot. prepare_worker(w) runs in this process before a task is
  // started in slot w (an implementation running out of process keeps one server per slot, started
  // here so that the children share it); if it throws, the task is not run and ends as Threw with
  // that message. worker_done(w, ended_normally) runs here after the task has ended: normally
  // means it returned or threw, not that it crashed or was stopped at the timeout.
  std::function<void(int)> prepare_worker;
  std::function<void(int, bool)> worker_done;
  // The order in which the tasks start: a permutation of their indices (empty: as given). Results
  // stay indexed as the tasks are.
  std::vector<std::size_t> start_order;
};

// The worker slot of the task running in this process (0 outside run_isolated).
int current_worker();

struct TaskResult {
  enum class Status {
    Ok,        // the task returned; `payload` holds what it returned
    Crashed,   // killed by a signal, or exited without a result (std::exit, a stray _exit, ...)
    TimedOut,  // killed after the timeout
    Threw,     // the task threw an exception outside the property machinery (message in `detail`)
    Busy,      // the machine's fault: starved of CPU past the busy limit, or the kernel cannot tell
  };
  Status status = Status::Crashed;
  std::string payload;
  std::string output;  // the tail of what the child wrote to stdout and stderr
  std::string detail;  // how it ended, in words: "killed by signal 11 (SIGSEGV, segmentation fault)"
  // In a sanitized build, the first line of a sanitizer's report in the output (quoted in `detail`):
  // the sanitizer catches a crash before the signal does, and exits or aborts.
  std::string sanitizer_report;
  int signal = 0;
  int exit_code = 0;
  double seconds = 0;         // wall clock
  double cpu_seconds = 0;     // CPU of the code under test (the task's process tree and its worker's server)
  double queued_seconds = 0;  // ... and the time its runnable tasks waited for a core (summed over them)
};

std::vector<TaskResult> run_isolated(const std::vector<std::function<std::string()>>& tasks,
                                     const IsolationOptions& options);

// "SIGSEGV (segmentation fault)" and the like.
std::string describe_signal(int sig);

}  // namespace gm::harness
