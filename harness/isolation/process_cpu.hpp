// CPU time of processes (issue 47: slow is judged by the work done, not by the clock of a busy
// machine). A check's budget of cases and its "too slow or hangs" verdict count the CPU time of the
// code under test: the check's own process tree, and the tree of the implementation's server when
// the code runs behind the protocol (a Python session runs in a fork of its server). A generous
// wall clock stays, for sleeps and waits, which use no CPU.
#pragma once

#include <sys/types.h>

namespace gm::harness {

// What the kernel says of a process tree's time: the CPU it had, and how long its runnable tasks
// waited on a run queue for a core (schedstat's run_delay; the time neither on a CPU nor queued
// was spent asleep: a sleep, a read, a lock). A task that is runnable but not running is starved;
// one that sleeps waits. `queued_known` is false where the kernel keeps no schedstat.
struct TreeTimes {
  double cpu = 0;
  double queued = 0;
  bool queued_known = false;
  TreeTimes& operator+=(const TreeTimes& o) {
    cpu += o.cpu;
    queued += o.queued;
    queued_known = queued_known || o.queued_known;
    return *this;
  }
};

// The tree's CPU (as tree_cpu_seconds) and the run-queue delay of every live task (thread) in it,
// from /proc/<pid>/task/<tid>/schedstat. The delay of tasks that have ended is not counted.
TreeTimes tree_times(pid_t root);

// utime + stime of `root` and of every process below it, alive or waited for (cutime, cstime), in
// seconds; 0 when it does not exist. Reads /proc (Linux).
double tree_cpu_seconds(pid_t root);

// The CPU time of this process (all its threads), in seconds.
double self_cpu_seconds();

// The machine's one-minute load average per core (above 1: runnable work waits for a core).
double load_per_core();

}  // namespace gm::harness
