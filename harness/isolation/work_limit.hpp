// A limit on the work of a task, judged by the kernel's accounting: every limit the harness sets on
// code under test (a check's time, a server's handshake) is its CPU time, with a wall clock for a
// task that sleeps, and only a machine that starved the task it waits on is the machine's fault.
//
//   - its CPU time past `cpu_seconds`: the code's ("did not finish within N s of CPU time");
//   - past its time, the task it waits on runnable for almost none of it (5%): it waits, the code's;
//   - past its time, its own tasks keeping more of them runnable than its cores can run (on average
//     a quarter of a task more): it starves itself, the code's, however busy the machine is beside it
//     (the task it waits on queues behind its own siblings; a single task never starves itself);
//   - at the wall guard (`wall_factor` times its time, at least `wall_floor` more), that task
//     runnable for less than half of it: it waits, the code's;
//   - at the busy limit (`busy_factor` times the wall guard): the machine's when that task was queued
//     for more than half of the wall clock while no task of its own ran (it was starved); else the
//     code's, in the words of what the accounting shows;
//   - where the kernel keeps no run-queue accounting, the wall guard stops it, as the machine's
//     (whether it slept or was starved is not known).
#pragma once

#include "harness/isolation/run_queue_account.hpp"

#include <string>

namespace gm::harness {

struct WorkLimit {
  double cpu_seconds = 120;
  double wall_factor = 3;
  double wall_floor = 60;
  double busy_factor = 8;
  double wall_guard() const;
  double busy_limit() const;
};

// What a task has done so far.
struct WorkSoFar {
  double wall = 0;               // since it started
  double cpu = 0;                // the CPU time of the code under test (its trees)
  bool known = false;            // the kernel keeps run-queue accounting (schedstat)
  bool looked_a_second = false;  // the account covers more than its first second
  const RunQueueAccount* account = nullptr;
};

struct LimitVerdict {
  bool stop = false;     // a limit is reached
  bool machine = false;  // ... and it is the machine's fault, not the code's
  std::string detail;    // in words, after "the check ...": "did not finish within ...", "could not do its work: ..."
};

LimitVerdict judge_work(const WorkLimit& limit, const WorkSoFar& w);

}  // namespace gm::harness
