// The limits of a whole sandbox, kept by the kernel's control groups: a number of tasks, a total of
// memory and one share of the CPU for everything the sandbox runs, however many processes it makes
// and whichever session each of them starts (a per-process limit multiplies by the processes, and
// a process that calls setsid() gets a scheduling group of its own beside its parent's).
//
// Only the harness started as root may make control groups. Each sandbox gets its own, made at its
// start under the harness's own group in each hierarchy, by the first command of the sandbox's
// chain (harness/isolation/sandbox.cpp): v2 (the unified hierarchy) where it offers a controller to
// the harness's group, else v1 where that controller is mounted (a "hybrid" machine mounts most
// controllers in v1 beside an empty v2). What cannot be made here is left out, said in words
// (cgroup_limits_in_words), and the sandbox keeps its per-process limits alone.
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

// What a sandbox's control groups hold, in MiB, tasks and the CPU weight of a nice-0 task (1024).
struct CgroupLimits {
  long memory_mb = 0;   // 0: no total
  long tasks = 0;       // 0: no count (processes and threads, the sandbox's own init among them)
  long cpu_weight = 0;  // 0: the default share
};

// The arguments of the sandbox's first command that make its groups and move it into them (see
// the prelude in sandbox.cpp: "cg=DIR", "set=FILE=VALUE", "join"), or none when no controller can
// be used here. Each element the kernel refused when this process tried it is left out.
std::vector<std::string> cgroup_arguments(const CgroupLimits& limits);

// Which limits the control groups keep on this machine, in words, for `geomech self-test` and for
// docs/UNTRUSTED.md: "tasks: pids (v1); memory: memory (v1); CPU share: cpu (v1)", or why none.
std::string cgroup_limits_in_words();

// Whether a control group keeps that limit here: "pids" (tasks), "memory" (else each process keeps an
// address-space limit of its own, harness/isolation/sandbox.cpp), "cpu" (one share).
bool cgroup_keeps(const std::string& controller);

// The CPU weight of a task at this process's nice value (the kernel's table: 1024 at 0, 15 at 19),
// so that `nice -n 19 geomech ...` reaches the sandboxes it starts.
long cpu_weight_of_this_process();

// Removes the control groups of sandboxes that have ended (empty, made more than 10 s ago, by
// this harness or another): called as sandboxes start, and as this process ends.
void sweep_ended_sandbox_groups();

}  // namespace gm::harness
