// CPU time of processes (issue 47: slow is judged by the work done, not by the clock of a busy
// machine). A check's budget of cases and its "too slow or hangs" verdict count the CPU time of the
// code under test: the check's own process tree, and the tree of the implementation's server when
// the code runs behind the protocol (a Python session runs in a fork of its server). A generous
// wall clock stays, for sleeps and waits, which use no CPU.
#pragma once

#include <sys/types.h>

namespace gm::harness {

// utime + stime of `root` and of every process below it, alive or waited for (cutime, cstime), in
// seconds; 0 when it does not exist. Reads /proc (Linux).
double tree_cpu_seconds(pid_t root);

// The CPU time of this process (all its threads), in seconds.
double self_cpu_seconds();

// The machine's one-minute load average per core (above 1: runnable work waits for a core).
double load_per_core();

}  // namespace gm::harness
