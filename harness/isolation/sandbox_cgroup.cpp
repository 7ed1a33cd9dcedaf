#include "harness/isolation/sandbox_cgroup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPrefix = "geomech-sandbox-";

void sweep(bool force);

// One controller, as this machine offers it to the harness's own group.
struct Controller {
  std::string name;     // "pids", "memory", "cpu"
  int version = 0;      // 1 or 2; 0: not usable here
  std::string base;     // the harness's group in that hierarchy: the sandboxes' groups are made in it
  std::string why_not;  // when not usable
};

struct Mount {
  std::string root, point, fstype;
  std::vector<std::string> options;  // the super options (v1: the controllers it holds)
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) out.push_back(part);
  return out;
}

// /proc/self/mountinfo: "id parent maj:min root point options [optional...] - fstype source super".
std::vector<Mount> cgroup_mounts() {
  std::vector<Mount> out;
  std::ifstream f("/proc/self/mountinfo");
  for (std::string line; std::getline(f, line);) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string x; in >> x;) w.push_back(x);
    const auto dash = std::find(w.begin(), w.end(), "-");
    if (w.size() < 5 || dash == w.end() || dash + 3 > w.end()) continue;
    Mount m;
    m.root = w[3];
    m.point = w[4];
    m.fstype = *(dash + 1);
    m.options = split(*(dash + 3), ',');
    if (m.fstype == "cgroup" || m.fstype == "cgroup2") out.push_back(m);
  }
  return out;
}

// The group's folder: the mount point joined with its path relative to the mount's root.
std::string folder_of(const Mount& m, const std::string& path) {
  std::string rel = path;
  if (m.root != "/") {
    if (rel.rfind(m.root, 0) != 0) return {};
    rel = rel.substr(m.root.size());
  }
  std::string dir = (fs::path(m.point) / fs::path(rel).relative_path()).lexically_normal().string();
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  return dir;
}

bool write_text(const std::string& file, const std::string& text) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  return ok;
}

std::string read_line(const std::string& file) {
  std::ifstream f(file);
  std::string line;
  std::getline(f, line);
  return line;
}

// The limit files of a controller, and what they are set to; in the order they must be written.
std::vector<std::pair<std::string, std::string>> limit_files(const Controller& c, const CgroupLimits& l) {
  std::vector<std::pair<std::string, std::string>> out;
  if (c.name == "pids" && l.tasks > 0) out.emplace_back("pids.max", std::to_string(l.tasks));
  if (c.name == "memory" && l.memory_mb > 0) {
    const std::string bytes = std::to_string(static_cast<long long>(l.memory_mb) << 20);
    if (c.version == 2) {
      out.emplace_back("memory.max", bytes);
      if (fs::exists(c.base + "/memory.swap.max") || fs::exists("/sys/fs/cgroup/memory.swap.max"))
        out.emplace_back("memory.swap.max", "0");
    } else {
      out.emplace_back("memory.limit_in_bytes", bytes);
      // With swap, the total of memory and swap too (the file exists when the kernel accounts swap).
      if (fs::exists(c.base + "/memory.memsw.limit_in_bytes")) out.emplace_back("memory.memsw.limit_in_bytes", bytes);
    }
  }
  if (c.name == "cpu" && l.cpu_weight > 0) {
    if (c.version == 2)  // cgroup v2's weight: 1..10000, 100 for a nice-0 task
      out.emplace_back("cpu.weight",
                       std::to_string(std::clamp<long>(std::lround(l.cpu_weight * 100.0 / 1024.0), 1, 10000)));
    else
      out.emplace_back("cpu.shares", std::to_string(std::max<long>(2, l.cpu_weight)));
  }
  return out;
}

// Whether a group made here takes a process and its limits: a child of this process is moved into
// a probe group with a typical limit, then the group is removed.
std::string try_controller(const Controller& c) {
  CgroupLimits probe;
  probe.tasks = 64;
  probe.memory_mb = 4096;
  probe.cpu_weight = 1024;
  const std::string dir = c.base + "/geomech-probe-" + std::to_string(::getpid());
  ::rmdir(dir.c_str());
  if (::mkdir(dir.c_str(), 0755) != 0) return "cannot make a group in " + c.base + ": " + std::strerror(errno);
  std::string why;
  for (const auto& [file, value] : limit_files(c, probe))
    if (why.empty() && !write_text(dir + "/" + file, value)) why = "cannot write " + file + ": " + std::strerror(errno);
  if (why.empty()) {
    const std::string procs = dir + "/cgroup.procs";
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int fd = ::open(procs.c_str(), O_WRONLY);
      const bool ok = fd >= 0 && ::write(fd, "0", 1) == 1;
      ::_exit(ok ? 0 : 1);
    }
    int status = 0;
    if (pid < 0 || ::waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
      why = "cannot move a process into a group made in " + c.base;
  }
  for (int i = 0; i < 50 && ::rmdir(dir.c_str()) != 0 && errno == EBUSY; ++i) ::usleep(2000);
  return why;
}

// The controllers as this machine offers them, tried once (as root only: nobody else may make groups).
const std::vector<Controller>& controllers() {
  // Never destroyed: the sweep at this process's end (registered below, so run after a static
  // made here would be gone) still reads it.
  static const std::vector<Controller>& found = *new std::vector<Controller>([] {
    std::vector<Controller> out;
    const std::vector<Mount> mounts = cgroup_mounts();
    std::string v2_path;
    std::vector<std::pair<std::vector<std::string>, std::string>> v1;  // (controllers, path)
    {
      std::ifstream f("/proc/self/cgroup");
      for (std::string line; std::getline(f, line);) {
        const auto a = line.find(':'), b = line.find(':', a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string ids = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
        if (line.substr(0, a) == "0" && ids.empty())
          v2_path = path;
        else
          v1.emplace_back(split(ids, ','), path);
      }
    }
    for (const char* name : {"pids", "memory", "cpu"}) {
      Controller c;
      c.name = name;
      if (::geteuid() != 0) {
        c.why_not = "the harness does not run as root";
        out.push_back(c);
        continue;
      }
      // v2, where the harness's group hands the controller to the groups made in it.
      for (const auto& m : mounts) {
        if (m.fstype != "cgroup2" || v2_path.empty()) continue;
        const std::string base = folder_of(m, v2_path);
        if (base.empty()) continue;
        const auto offered = split(read_line(base + "/cgroup.controllers"), ' ');
        if (std::find(offered.begin(), offered.end(), name) == offered.end()) continue;
        const auto given = split(read_line(base + "/cgroup.subtree_control"), ' ');
        if (std::find(given.begin(), given.end(), name) == given.end() &&
            !write_text(base + "/cgroup.subtree_control", std::string("+") + name)) {
          c.why_not = std::string("cgroup v2 offers ") + name + " but " + base +
                      " cannot hand it to groups made in it (a group that holds processes, the harness's own, "
                      "may not: run the harness in a group of its own)";
          continue;
        }
        c.version = 2;
        c.base = base;
      }
      // v1, where it is mounted.
      if (c.version == 0)
        for (const auto& [ids, path] : v1) {
          if (std::find(ids.begin(), ids.end(), name) == ids.end()) continue;
          for (const auto& m : mounts)
            if (m.fstype == "cgroup" && std::find(m.options.begin(), m.options.end(), name) != m.options.end()) {
              c.base = folder_of(m, path);
              if (!c.base.empty()) c.version = 1;
            }
        }
      if (c.version == 0 && c.why_not.empty()) c.why_not = std::string("no cgroup hierarchy offers ") + name + " here";
      if (c.version != 0)
        if (std::string why = try_controller(c); !why.empty()) {
          c.why_not = why;
          c.version = 0;
        }
      out.push_back(c);
    }
    std::atexit([] { sweep(true); });
    return out;
  }());
  return found;
}

const Controller* usable(const std::string& name) {
  for (const auto& c : controllers())
    if (c.name == name && c.version != 0) return &c;
  return nullptr;
}

}  // namespace

std::vector<std::string> cgroup_arguments(const CgroupLimits& limits) {
  std::vector<std::string> out;
  sweep_ended_sandbox_groups();
  for (const char* name : {"pids", "memory", "cpu"}) {
    const Controller* c = usable(name);
    if (!c) continue;
    const auto files = limit_files(*c, limits);
    if (files.empty()) continue;
    out.push_back("cg=" + c->base);
    for (const auto& [file, value] : files) out.push_back("set=" + file + "=" + value);
    out.push_back("join");
  }
  return out;
}

std::string cgroup_limits_in_words() {
  std::string out;
  for (const auto& c : controllers()) {
    const std::string what = c.name == "pids" ? "tasks" : c.name == "memory" ? "memory total" : "CPU share";
    out += (out.empty() ? "" : "; ") + what + ": " +
           (c.version != 0 ? "cgroup v" + std::to_string(c.version) + " " + c.name + " in " + c.base
                           : "none (" + c.why_not + ")");
  }
  return out;
}

bool cgroup_keeps(const std::string& controller) { return usable(controller) != nullptr; }

long cpu_weight_of_this_process() {
  // The kernel's sched_prio_to_weight, nice -20 .. 19 (kernel/sched/core.c).
  static const long weight[40] = {88761, 71755, 56483, 46273, 36291, 29154, 23254, 18705, 14949, 11916,
                                  9548,  7620,  6100,  4904,  3906,  3121,  2501,  1991,  1586,  1277,
                                  1024,  820,   655,   526,   423,   335,   272,   215,   172,   137,
                                  110,   87,    70,    56,    45,    36,    29,    23,    18,    15};
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, 0);
  if (errno != 0) return 1024;
  return weight[std::clamp(nice, -20, 19) + 20];
}

void sweep_ended_sandbox_groups() { sweep(false); }

namespace {

// At most every 10 s (each sandbox that starts asks), or now (as this process ends).
void sweep(bool force) {
  static std::mutex m;
  static auto last = std::chrono::steady_clock::time_point{};
  if (::geteuid() != 0) return;
  std::lock_guard lock(m);
  const auto now = std::chrono::steady_clock::now();
  if (!force && last != std::chrono::steady_clock::time_point{} && now - last < std::chrono::seconds(10)) return;
  last = now;
  for (const auto& c : controllers()) {
    if (c.version == 0) continue;
    DIR* d = ::opendir(c.base.c_str());
    if (!d) continue;
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name.rfind(kPrefix, 0) != 0) continue;
      // A sandbox's group is named by the pid of its first process, which lives as long as the
      // sandbox (it becomes bubblewrap's monitor): a group whose process is gone belongs to an ended
      // sandbox. A group still holding a task is not removed by the kernel (EBUSY) in any case.
      const long pid = std::atol(name.c_str() + std::char_traits<char>::length(kPrefix));
      if (pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)) continue;
      // As this process ends, a sandbox it just ended may still be leaving (its init, reparented,
      // not yet reaped): a moment's grace.
      const std::string dir = c.base + "/" + name;
      for (int i = 0; ::rmdir(dir.c_str()) != 0 && errno == EBUSY && force && i < 40; ++i) ::usleep(5000);
    }
    ::closedir(d);
  }
}

}  // namespace

}  // namespace gm::harness
