// CPU time of processes (slow is judged by the work done, not by the clock of a busy
// machine). A check's budget of cases and its "too slow or hangs" verdict count the CPU time of the
// code under test: the check's own process tree, and the tree of the implementation's server when
// the code runs behind the protocol (a Python session runs in a fork of its server). A generous
// wall clock stays, for sleeps and waits, which use no CPU.
#pragma once

#include <map>
#include <set>

#include <sys/types.h>

namespace gm::harness {

// One task (a thread) as schedstat counts it: its time on a CPU and its time runnable but queued
// for one (run_delay), in seconds since it started.
struct TaskTimes {
  double cpu = 0;
  double queued = 0;
};

// What the kernel says of a process tree's time: the CPU it had, and how long its runnable tasks
// waited on a run queue for a core (schedstat's run_delay; the time neither on a CPU nor queued
// was spent asleep: a sleep, a read, a lock). A task that is runnable but not running is starved;
// one that sleeps waits. `queued_known` is false where the kernel keeps no schedstat. The sums are
// over tasks: N tasks of one tree that queue for one core sum to N times the wall clock, so whom a
// check waits on is judged per task (harness/isolation/run_queue_account.hpp).
struct TreeTimes {
  double cpu = 0;
  double queued = 0;
  bool queued_known = false;
  std::map<pid_t, TaskTimes> tasks;  // each live task of the tree, by its thread id
  std::set<int> cpus;                // the CPUs its live tasks may run on (the union of their affinities)
  TreeTimes& operator+=(const TreeTimes& o) {
    cpu += o.cpu;
    queued += o.queued;
    queued_known = queued_known || o.queued_known;
    tasks.insert(o.tasks.begin(), o.tasks.end());
    cpus.insert(o.cpus.begin(), o.cpus.end());
    return *this;
  }
};

// The tree's CPU (as tree_cpu_seconds) and the run-queue delay of every live task (thread) in it,
// from /proc/<pid>/task/<tid>/schedstat, with each task's own times and the CPUs it may use. The kernel keeps no delay for a process that has ended:
// `queued_by_pid`, when given, is the delay of each live process, for a caller that samples the tree
// and keeps what the processes that ended had last shown (QueuedSoFar).
TreeTimes tree_times(pid_t root, std::map<pid_t, double>* queued_by_pid = nullptr);

// The run-queue delay of a tree so far, sampled: the live processes' delay now, plus what each
// process that has ended (a compiler, a forked session) showed when last seen.
class QueuedSoFar {
 public:
  // The tree's times now, with `queued` counting the ended processes too.
  TreeTimes sample(pid_t root);

 private:
  std::map<pid_t, double> seen_;
  double gone_ = 0;
};

// utime + stime of `root` and of every process below it, alive or waited for (cutime, cstime), in
// seconds; 0 when it does not exist. Reads /proc (Linux).
double tree_cpu_seconds(pid_t root);

// The CPU time of this process (all its threads), in seconds.
double self_cpu_seconds();

// The machine's one-minute load average per core (above 1: runnable work waits for a core).
double load_per_core();

}  // namespace gm::harness
