#include "harness/isolation/process.hpp"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace gm::harness {

namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t index;
  pid_t pid;
  Clock::time_point start;
  std::string capture;  // temporary file holding the output
};

// A child's output, as much of it as a caller can use (a compiler, or a program under
// test, may write gigabytes): its first kOutputHead bytes and its last kOutputTail, with the cut said.
constexpr std::size_t kOutputHead = 1u << 20, kOutputTail = 64u << 10;
std::string read_bounded(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) return {};
  const std::streamoff size = f.tellg();
  f.seekg(0);
  if (size <= static_cast<std::streamoff>(kOutputHead + kOutputTail)) {
    std::string out(static_cast<std::size_t>(size), '\0');
    f.read(out.data(), size);
    out.resize(static_cast<std::size_t>(f.gcount()));
    return out;
  }
  std::string head(kOutputHead, '\0'), tail(kOutputTail, '\0');
  f.read(head.data(), static_cast<std::streamsize>(kOutputHead));
  f.seekg(size - static_cast<std::streamoff>(kOutputTail));
  f.read(tail.data(), static_cast<std::streamsize>(kOutputTail));
  return head + "\n[... " + std::to_string(size - static_cast<std::streamoff>(kOutputHead + kOutputTail)) +
         " bytes of output cut ...]\n" + tail;
}

// Starts the process spec describes (the i-th), its output captured in a file unless it passes through;
// one that cannot be started says why in its result.
void spawn_child(const ProcessSpec& spec, std::size_t i, ProcessResult& result, std::vector<Child>& running) {
  std::string capture = spec.output_file;
  if (capture.empty() && !spec.pass_through) {
    char tmpl[] = "/tmp/geomech-process-XXXXXX";
    const int fd = ::mkstemp(tmpl);
    if (fd >= 0) ::close(fd);
    capture = tmpl;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (!capture.empty()) {
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, capture.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  }
  // Nothing a child runs (a compiler told to #include "/dev/stdin", a submission's program)
  // reads this process's input, which may be the lecturer's terminal. A child whose
  // output passes through (the user's own check) keeps the terminal.
  if (!spec.pass_through) posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  if (!spec.pass_through) {  // its own group: stopping it stops what it started (run_processes)
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  std::vector<char*> argv;
  for (const auto& a : spec.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = argv[0] ? ::posix_spawnp(&pid, argv[0], &fa, &attr, argv.data(), environ) : EINVAL;
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    result.started = false;
    result.output =
        "cannot run " + (spec.argv.empty() ? std::string("(nothing)") : spec.argv[0]) + ": " + std::strerror(rc);
    if (spec.output_file.empty() && !capture.empty()) ::unlink(capture.c_str());
    return;
  }
  result.started = true;
  result.pid = pid;
  running.push_back(Child{i, pid, Clock::now(), capture});
}

}  // namespace

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=/.,:@%") ==
                        std::string::npos)
    return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string shell_join(const std::vector<std::string>& argv) {
  std::string out;
  for (const auto& a : argv) out += (out.empty() ? "" : " ") + shell_quote(a);
  return out;
}

std::vector<ProcessResult> run_processes(const std::vector<ProcessSpec>& specs, int jobs, double timeout_seconds) {
  std::vector<ProcessResult> results(specs.size());
  std::vector<Child> running;
  std::size_t next = 0;
  if (jobs < 1) jobs = 1;

  auto start = [&](std::size_t i) { spawn_child(specs[i], i, results[i], running); };

  auto finish = [&](const Child& c, int status, bool timed_out) {
    ProcessResult& r = results[c.index];
    r.seconds = std::chrono::duration<double>(Clock::now() - c.start).count();
    r.timed_out = timed_out;
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    if (!c.capture.empty()) {
      r.output = read_bounded(c.capture);
      if (specs[c.index].output_file.empty()) ::unlink(c.capture.c_str());
    }
  };

  // A captured child leads its own group (start): the whole group is stopped.
  auto stop = [&](const Child& c) {
    ::kill(specs[c.index].pass_through ? c.pid : -c.pid, SIGKILL);
    int status = 0;
    ::waitpid(c.pid, &status, 0);
    return status;
  };
  bool cancelled = false;
  while ((next < specs.size() && !cancelled) || !running.empty()) {
    while (!cancelled && next < specs.size() && static_cast<int>(running.size()) < jobs) start(next++);
    bool any = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      const pid_t w = ::waitpid(it->pid, &status, WNOHANG);
      if (w == it->pid) {
        finish(*it, status, false);
        const ProcessResult& r = results[it->index];
        if (specs[it->index].decisive && (r.exit_code != 0 || r.signal != 0)) cancelled = true;
        it = running.erase(it);
        any = true;
      } else if (timeout_seconds > 0 &&
                 std::chrono::duration<double>(Clock::now() - it->start).count() > timeout_seconds) {
        finish(*it, stop(*it), true);
        if (specs[it->index].decisive) cancelled = true;
        it = running.erase(it);
        any = true;
      } else {
        ++it;
      }
    }
    if (cancelled) {
      for (const Child& c : running) {
        finish(c, stop(c), false);
        results[c.index].cancelled = true;
      }
      running.clear();
      for (; next < specs.size(); ++next) results[next].cancelled = true;
    }
    if (!any && !running.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return results;
}

bool die_with_parent_when_asked() {
  if (!std::getenv("GEOMECH_DIE_WITH_PARENT")) return true;
  const pid_t parent = ::getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  return ::getppid() == parent;
}

ProcessResult run_process(const ProcessSpec& spec, double timeout_seconds) {
  return run_processes({spec}, 1, timeout_seconds).front();
}

}  // namespace gm::harness
