// Isolation: each task runs in a forked child process, so that a segmentation fault, an abort, a
// hang or a runaway allocation in the code under test ends that task alone. The child sends its
// result back over a pipe; its stdout and stderr are captured (the last few kilobytes are kept,
// to show with a crash). The parent runs up to `jobs` children at once and kills a child (and
// its process group) that exceeds the timeout.
//
// The calling process must be single-threaded when it calls run_isolated (fork copies only the
// calling thread).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace gm::harness {

struct TaskResult;

struct IsolationOptions {
  int jobs = 1;                  // children running at once
  // The limit of a task (issue 47: slow is judged by the work done): the CPU seconds of the code
  // under test, its child's process tree and its worker's server (worker_cpu) together. A wall
  // clock of wall_factor times as long (and at least wall_floor more) stays, for a task that waits
  // (sleeps, reads input) and uses no CPU: stopped there, it is TimedOut ("it waited") when it used
  // little CPU on an idle machine; when the machine was busy and it did work, it is started again
  // once, and stopped a second time it is Busy, not a verdict on the code.
  double timeout_seconds = 120;
  double wall_factor = 3;
  double wall_floor = 60;
  // The CPU seconds the server of worker slot w has used so far (out-of-process implementations);
  // none: the code runs in the task's own process.
  std::function<double(int)> worker_cpu;
  long memory_limit_mb = 4096;   // address-space limit of a child (not applied under AddressSanitizer)
  bool isolate = true;           // false: run the tasks in this process, one after the other (debugging)
  // Called in the parent as each task starts (index), and as it finishes (index, its result): a
  // check reports each result the moment it is known (issue 32, harness/engine/check_events.hpp).
  std::function<void(std::size_t)> on_started;
  std::function<void(std::size_t, const TaskResult&)> on_finished;
  // Called in the parent while tasks run, between looks at them (about 50 times a second): a
  // progress line that names what is running and for how long (issue 49, class mode).
  std::function<void()> on_idle;
  // Worker slots (issue 15): a running task occupies one of `jobs` slots, numbered from 0; in the
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
    Busy,      // stopped twice by the wall clock while the machine was too busy for it to do its work
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
  double seconds = 0;      // wall clock
  double cpu_seconds = 0;  // CPU of the code under test (the task's process tree and its worker's server)
  bool retried = false;    // started again after the wall clock stopped it on a busy machine
};

std::vector<TaskResult> run_isolated(const std::vector<std::function<std::string()>>& tasks,
                                     const IsolationOptions& options);

// "SIGSEGV (segmentation fault)" and the like.
std::string describe_signal(int sig);

}  // namespace gm::harness
