#include "harness/isolation/run_queue_account.hpp"

#include <algorithm>
#include <set>
#include <thread>

namespace gm::harness {

RunQueueAccount::RunQueueAccount(const TreeTimes& baseline) : last_(baseline.tasks) {}

void RunQueueAccount::look(const std::vector<TreeTimes>& trees, double wall) {
  const double dt = wall - last_wall_;
  if (dt <= 0) return;
  // Each task's share of this interval: a task seen before counts from then, a new one from its start.
  struct Step {
    double cpu = 0, queued = 0;
    double runnable() const { return cpu + queued; }
  };
  std::map<pid_t, TaskTimes> now;
  std::set<int> cpus;
  double cpu_all = 0;
  Step waited;  // the most runnable task of each tree, added: they take turns
  for (const TreeTimes& tree : trees) {
    Step most;
    for (const auto& [tid, t] : tree.tasks) {
      const auto before = last_.find(tid);
      const TaskTimes from = before == last_.end() ? TaskTimes{} : before->second;
      Step s;
      s.cpu = std::max(0.0, t.cpu - from.cpu);
      s.queued = std::max(0.0, t.queued - from.queued);
      cpu_all += s.cpu;
      tree_runnable_ += s.runnable();
      tree_queued_ += s.queued;
      if (s.runnable() > most.runnable()) most = s;
      now[tid] = t;
    }
    waited.cpu += most.cpu;
    waited.queued += most.queued;
    cpus.insert(tree.cpus.begin(), tree.cpus.end());
  }
  waited_runnable_ += std::min(dt, waited.runnable());
  waited_queued_ += std::min(dt, waited.queued);
  // While they queued, the check's other tasks ran for `others` seconds: at most that much of their
  // queue is the check's own doing; the rest, no task of it held a core.
  const double others = cpu_all - waited.cpu;
  queued_by_machine_ += std::min(dt, std::max(0.0, waited.queued - others));
  const unsigned machine = std::max(1u, std::thread::hardware_concurrency());
  cores_ = cpus.empty() ? static_cast<int>(machine) : static_cast<int>(cpus.size());
  capacity_ += dt * cores_;
  most_tasks_ = std::max(most_tasks_, static_cast<int>(now.size()));
  wall_ += dt;
  last_wall_ = wall;
  last_ = std::move(now);
}

}  // namespace gm::harness
