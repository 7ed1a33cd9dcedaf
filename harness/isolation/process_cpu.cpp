#include "harness/isolation/process_cpu.hpp"

#include <dirent.h>
#include <sched.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace gm::harness {

namespace {

struct Stat {
  pid_t ppid = 0;
  double cpu = 0;  // own utime + stime + waited-for children's cutime + cstime, in seconds
};

// /proc/<pid>/stat: "pid (comm) state ppid ... utime stime cutime cstime ..." (fields 4, 14-17);
// comm may hold spaces and parentheses, so the fields are counted from the last ')'.
bool read_stat(pid_t pid, Stat& s) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return false;
  const auto close = line.rfind(')');
  if (close == std::string::npos) return false;
  std::istringstream rest(line.substr(close + 2));
  std::vector<std::string> field;
  for (std::string x; rest >> x && field.size() < 16;) field.push_back(x);
  if (field.size() < 15) return false;  // field[0] is the state (field 3)
  static const double tick = static_cast<double>(::sysconf(_SC_CLK_TCK));
  s.ppid = static_cast<pid_t>(std::atol(field[1].c_str()));
  s.cpu = (std::atof(field[11].c_str()) + std::atof(field[12].c_str()) + std::atof(field[13].c_str()) +
           std::atof(field[14].c_str())) /
          tick;
  return true;
}

// The run-queue delay of every thread of `pid`, in seconds, and each thread's own times and CPUs
// (into `tasks` and `cpus` when given); false when the kernel keeps no schedstat.
bool read_queued(pid_t pid, double& seconds, std::map<pid_t, TaskTimes>* tasks = nullptr,
                 std::set<int>* cpus = nullptr) {
  const std::string dir = "/proc/" + std::to_string(pid) + "/task";
  DIR* d = ::opendir(dir.c_str());
  if (!d) return false;
  bool any = false;
  while (const dirent* e = ::readdir(d)) {
    if (e->d_name[0] == '.') continue;
    std::ifstream f(dir + "/" + e->d_name + "/schedstat");
    double on_cpu_ns = 0, run_delay_ns = 0;
    if (f >> on_cpu_ns >> run_delay_ns) {
      seconds += run_delay_ns * 1e-9;
      any = true;
      const pid_t tid = static_cast<pid_t>(std::atol(e->d_name));
      if (tasks) (*tasks)[tid] = TaskTimes{on_cpu_ns * 1e-9, run_delay_ns * 1e-9};
      cpu_set_t mask;
      CPU_ZERO(&mask);
      if (cpus && ::sched_getaffinity(tid, sizeof mask, &mask) == 0)
        for (int c = 0; c < CPU_SETSIZE; ++c)
          if (CPU_ISSET(c, &mask)) cpus->insert(c);
    }
  }
  ::closedir(d);
  return any;
}

// The processes of `root`'s tree, root first.
std::vector<pid_t> tree_of(pid_t root, std::map<pid_t, Stat>& all) {
  if (DIR* d = ::opendir("/proc")) {
    while (const dirent* e = ::readdir(d)) {
      char* end = nullptr;
      const long pid = std::strtol(e->d_name, &end, 10);
      if (end == e->d_name || *end != '\0') continue;
      Stat s;
      if (read_stat(static_cast<pid_t>(pid), s)) all[static_cast<pid_t>(pid)] = s;
    }
    ::closedir(d);
  }
  std::vector<pid_t> tree;
  if (!all.count(root)) return tree;
  std::multimap<pid_t, pid_t> children;
  for (const auto& [pid, s] : all) children.emplace(s.ppid, pid);
  std::vector<pid_t> todo{root};
  while (!todo.empty()) {
    const pid_t p = todo.back();
    todo.pop_back();
    tree.push_back(p);
    auto [lo, hi] = children.equal_range(p);
    for (auto it = lo; it != hi; ++it) todo.push_back(it->second);
  }
  return tree;
}

}  // namespace

TreeTimes tree_times(pid_t root, std::map<pid_t, double>* queued_by_pid) {
  TreeTimes t;
  if (root <= 0) return t;
  std::map<pid_t, Stat> all;
  for (pid_t p : tree_of(root, all)) {
    t.cpu += all[p].cpu;
    double q = 0;
    if (read_queued(p, q, &t.tasks, &t.cpus)) {
      t.queued_known = true;
      t.queued += q;
      if (queued_by_pid) (*queued_by_pid)[p] = q;
    }
  }
  return t;
}

TreeTimes QueuedSoFar::sample(pid_t root) {
  std::map<pid_t, double> now;
  TreeTimes t = tree_times(root, &now);
  for (const auto& [pid, q] : seen_)
    if (!now.count(pid)) gone_ += q;  // ended since the last look: its last delay stays counted
  seen_ = std::move(now);
  t.queued += gone_;
  return t;
}

double tree_cpu_seconds(pid_t root) { return tree_times(root).cpu; }

double self_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double load_per_core() {
  double load = 0;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = 0;
    std::fclose(f);
  }
  const unsigned cores = std::thread::hardware_concurrency();
  return load / (cores > 0 ? cores : 1);
}

}  // namespace gm::harness
