#include "harness/isolation/work_limit.hpp"

#include <algorithm>
#include <cstdio>

namespace gm::harness {

namespace {

constexpr double kWaitingShare = 0.05;    // past its time, runnable for less than this: it sleeps
constexpr double kRunnableAtGuard = 0.5;  // at the wall guard, runnable for less than this: it waits
constexpr double kStarvedShare = 0.5;     // queued by the machine for more than this: starved

std::string format(const char* fmt, auto... args) {
  char buf[1000];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

double WorkLimit::wall_guard() const { return std::max(cpu_seconds * wall_factor, cpu_seconds + wall_floor); }
double WorkLimit::busy_limit() const { return wall_guard() * std::max(1.0, busy_factor); }

LimitVerdict judge_work(const WorkLimit& limit, const WorkSoFar& w) {
  LimitVerdict v;
  const bool known = w.known && w.account;
  const RunQueueAccount none;
  const RunQueueAccount& a = known ? *w.account : none;
  const double looked = a.seconds(), waited = a.waited_runnable();
  const bool cpu_out = w.cpu > limit.cpu_seconds;
  const bool past = known && w.wall > limit.cpu_seconds && w.looked_a_second;
  const bool waiting = past && waited < kWaitingShare * looked;
  const bool starved = known && a.queued_by_machine() > kStarvedShare * looked;
  // A tree that keeps more tasks runnable than its cores starves itself, whatever else the machine
  // runs: the task it waits on queues behind its own siblings, and a single task never does.
  const bool itself = past && a.starves_itself();
  const bool wall_out = w.wall > limit.wall_guard() && (!known || waited < kRunnableAtGuard * looked);
  const bool busy_out = w.wall > limit.busy_limit();
  v.stop = cpu_out || waiting || itself || wall_out || busy_out;
  if (!v.stop) return v;

  const double waited_cpu = waited - a.waited_queued();
  const double asleep = std::max(0.0, looked - waited);
  // The tree's own load, when it has more than one task: its sums, which count each task's queue.
  const std::string tree = a.most_tasks() <= 1
                               ? std::string()
                               : format(" (its tasks, up to %d at once: %.1f s runnable, %.1f s of it queued, summed)",
                                        a.most_tasks(), a.tree_runnable(), a.tree_queued());
  if (cpu_out) {
    v.detail = format("did not finish within %.0f s of CPU time (%.0f s of wall clock) and was stopped",
                      limit.cpu_seconds, w.wall);
  } else if (!known) {
    // The kernel keeps no run-queue accounting here: waiting and starving cannot be told apart.
    v.machine = true;
    v.detail = format(
        "was stopped by the wall clock after %.0f s having had %.1f s of CPU; this kernel keeps no run-queue "
        "accounting (/proc/PID/task/TID/schedstat), so whether it slept or the machine starved it is not known",
        w.wall, w.cpu);
  } else if (itself) {
    v.detail = format(
        "did not finish within %.0f s: it starves itself: its own tasks, up to %d at once, were runnable %.1f s in "
        "%.0f s of wall clock, more than its %d %s could run, so they queued %.1f s for them (summed); the task it "
        "waits on was queued %.1f s, of which at most %.1f s while none of its own tasks ran: more runnable tasks "
        "than its share of cores, which is the code's own load",
        limit.cpu_seconds, a.most_tasks(), a.tree_runnable(), looked, a.cores(), a.cores() == 1 ? "core" : "cores",
        a.tree_queued(), a.waited_queued(), a.queued_by_machine());
  } else if (waiting || wall_out || !starved) {
    v.detail =
        format(
            "did not finish within %.0f s: stopped by the wall clock after %.0f s, of which the kernel counts, for the "
            "task it waits on, %.1f s on a CPU, %.1f s queued for one (%.1f s of it while no task of its own ran) and "
            "%.0f s asleep: it waits (a sleep, an input it reads, a lock) rather than computes",
            limit.cpu_seconds, w.wall, waited_cpu, a.waited_queued(), a.queued_by_machine(), asleep) +
        tree;
  } else {
    v.machine = true;
    v.detail =
        format(
            "could not do its work: the machine starved it, by the kernel's accounting the task it waits on was %.1f s "
            "on a CPU and %.1f s runnable but queued for one in %.0f s of wall clock, %.1f s of it while no task of "
            "its "
            "own ran (stopped at %g times the wall guard)",
            waited_cpu, a.waited_queued(), w.wall, a.queued_by_machine(), std::max(1.0, limit.busy_factor)) +
        tree;
  }
  return v;
}

}  // namespace gm::harness
