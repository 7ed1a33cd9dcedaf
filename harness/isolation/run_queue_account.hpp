// Whom a check's wait is owed to, task by task, by the kernel's accounting (schedstat: a task's time
// on a CPU and its time runnable but queued for one, run_delay).
//
// A check waits on one task at a time in each of its trees (its own process tree, and the server of
// its worker when the code runs behind the protocol, the two taking turns: a request, its reply):
// in each look, the most runnable task of each, whichever it is (the compiler, then the program; a
// server's session). Their queue is the machine's only in the part the trees' other tasks cannot
// explain: while they queued, another task of the check that ran on a CPU may have held their core,
// so at most that other CPU time of their queue is the check's own doing. Summed over every task
// instead, N tasks of one tree that queue for one core sum to N times the wall clock: more queued
// time than wall clock is proof of the code's own load, not of a starved machine. A check whose
// tasks keep more of them runnable than the cores they may use starves itself.
#pragma once

#include "harness/isolation/process_cpu.hpp"

#include <map>
#include <vector>

namespace gm::harness {

class RunQueueAccount {
 public:
  // `baseline`: the times, at the check's start, of tasks that ran before it (its worker's
  // server, which earlier checks used); a task not in it counts from its own start.
  explicit RunQueueAccount(const TreeTimes& baseline = TreeTimes{});

  // A look at the trees the check waits on, `wall` seconds after the check started: its own, and
  // its worker's server's (or its one tree).
  void look(const std::vector<TreeTimes>& trees, double wall);
  void look(const TreeTimes& tree, double wall) { look(std::vector<TreeTimes>{tree}, wall); }

  // Over the looks so far, in seconds:
  double waited_runnable() const { return waited_runnable_; }      // the tasks waited on: on a CPU or queued
  double waited_queued() const { return waited_queued_; }          // ... queued
  double queued_by_machine() const { return queued_by_machine_; }  // ... queued while no other task of it ran
  double tree_runnable() const { return tree_runnable_; }          // every task's time runnable, summed
  double tree_queued() const { return tree_queued_; }              // ... queued, summed
  double capacity() const { return capacity_; }                    // the cores it may use times the wall clock
  double seconds() const { return wall_; }                         // the wall clock the looks cover
  int cores() const { return cores_; }                             // at the last look
  int most_tasks() const { return most_tasks_; }                   // the most tasks seen at once

  // More tasks runnable than its cores could run (on average a quarter of a task more: a single task,
  // runnable all along, stays clear of it whatever the jitter of the looks), and queued for much of
  // the time: its queue is its own doing.
  bool starves_itself() const { return tree_runnable_ > capacity_ + 0.25 * wall_ && tree_queued_ > 0.5 * wall_; }

 private:
  std::map<pid_t, TaskTimes> last_;
  double last_wall_ = 0;
  double waited_runnable_ = 0, waited_queued_ = 0, queued_by_machine_ = 0;
  double tree_runnable_ = 0, tree_queued_ = 0, capacity_ = 0, wall_ = 0;
  int cores_ = 0, most_tasks_ = 0;
};

}  // namespace gm::harness
