#include "harness/isolation/isolate.hpp"

#include "harness/isolation/process_cpu.hpp"
#include "harness/isolation/run_queue_account.hpp"
#include "harness/isolation/work_limit.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iostream>
#include <memory>
#include <set>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define GM_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GM_UNDER_ASAN 1
#endif
#endif

namespace gm::harness {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kOutputTail = 4096;
// A child whose output has begun a sanitizer's report is dying, not hanging: symbolising the report's
// stack (the DWARF of a large binary, compressed with -gz) can take seconds on a loaded machine, so
// such a child gets this long past the timeout to finish its report before it is stopped.
constexpr double kSanitizerGrace = 120;  // seconds
// A task's limits are judged by the kernel's accounting of the task the check waits on, never by
// the sum over its tree (harness/isolation/work_limit.hpp).

int g_worker = 0;  // this process's worker slot (set before a task's child is forked)

struct Running {
  std::size_t index;
  int worker;
  pid_t pid;
  int result_fd;
  int output_fd;
  Clock::time_point start;
  std::string result;
  std::string output;
  std::string sanitizer_report;              // the first line of a sanitizer's report in the output, if any
  TreeTimes worker0;                         // the worker's server's times when the task started
  TreeTimes times;                           // the code's CPU and run-queue delay so far (sampled)
  std::shared_ptr<QueuedSoFar> queued;       // the tree's delay, ended processes included
  std::shared_ptr<RunQueueAccount> account;  // whom the wait is owed to, task by task
  Clock::time_point sampled{};               // when `times` was last read
};

// In a sanitized build (ASan, UBSan) the sanitizer catches a crash before the signal does, prints a
// report and exits or aborts: its first line says what happened. Kept apart from the output's
// tail, which a long stack trace would push it out of.
void note_sanitizer_report(const std::string& buf, std::string& report) {
  if (!report.empty()) return;
  for (const char* marker :
       {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "ERROR: UndefinedBehaviorSanitizer", ": runtime error: "}) {
    const std::size_t at = buf.find(marker);
    if (at == std::string::npos) continue;
    const std::size_t end = buf.find('\n', at);
    if (end == std::string::npos) return;  // the line is not complete yet
    std::size_t begin = buf.rfind('\n', at);
    begin = begin == std::string::npos ? 0 : begin + 1;
    report = buf.substr(begin, end - begin);
    if (report.rfind("==", 0) == 0) {  // "==1234==ERROR: ..." -> "ERROR: ..."
      const std::size_t close = report.find("==", 2);
      if (close != std::string::npos) report.erase(0, close + 2);
    }
    return;
  }
}

void append_tail(std::string& buf, const char* data, std::size_t n, std::string* sanitizer_report) {
  buf.append(data, n);
  if (sanitizer_report) note_sanitizer_report(buf, *sanitizer_report);
  if (buf.size() > 2 * kOutputTail) buf.erase(0, buf.size() - kOutputTail);
}

// Reads what is available; returns false at end of file (or on an error other than EAGAIN).
// With sanitizer_report, only the tail of the output is kept, and a sanitizer's report is noted.
bool drain(int fd, std::string& into, std::string* sanitizer_report = nullptr) {
  const bool tail_only = sanitizer_report != nullptr;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) {
      if (tail_only)
        append_tail(into, buf, static_cast<std::size_t>(n), sanitizer_report);
      else
        into.append(buf, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return false;
    if (errno == EINTR) continue;
    return errno == EAGAIN || errno == EWOULDBLOCK;
  }
}

void write_all(int fd, const std::string& s) {
  std::size_t off = 0;
  while (off < s.size()) {
    const ssize_t n = ::write(fd, s.data() + off, s.size() - off);
    if (n < 0) {
      if (errno == EINTR) continue;
      return;
    }
    off += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void child_main(const std::function<std::string()>& task, int result_fd, int output_fd,
                             long memory_limit_mb, pid_t parent) {
  ::setpgid(0, 0);  // its own process group, so a timeout can kill whatever it started
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(120);
  ::dup2(output_fd, STDOUT_FILENO);
  ::dup2(output_fd, STDERR_FILENO);
  ::close(output_fd);
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  std::cout << std::unitbuf;
  rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
#ifndef GM_UNDER_ASAN
  if (memory_limit_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(memory_limit_mb) * 1024 * 1024;
    // Writable memory (RLIMIT_DATA), not address space: an interpreter started by the check (Node,
    // whose V8 reserves gigabytes of inaccessible address space for a WebAssembly memory) inherits it.
    rlimit data{bytes, bytes};
    ::setrlimit(RLIMIT_DATA, &data);
  }
#else
  (void)memory_limit_mb;
#endif
  std::string message;
  try {
    const std::string payload = task();
    write_all(result_fd, "R" + payload);
    ::close(result_fd);
    ::_exit(0);
  } catch (const std::exception& e) {
    message = e.what();
  } catch (...) {
    message = "an exception that is not a std::exception";
  }
  write_all(result_fd, "E" + message);
  ::close(result_fd);
  ::_exit(0);
}

TaskResult finish(Running& r, int status) {
  TaskResult t;
  t.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
  t.cpu_seconds = r.times.cpu;
  t.queued_seconds = r.times.queued;
  t.output = r.output.size() > kOutputTail ? r.output.substr(r.output.size() - kOutputTail) : r.output;
  t.sanitizer_report = r.sanitizer_report;
  if (WIFSIGNALED(status)) {
    t.status = TaskResult::Status::Crashed;
    t.signal = WTERMSIG(status);
    t.detail = "killed by " + describe_signal(t.signal);
    if (!r.sanitizer_report.empty()) t.detail += " after the sanitizer's report \"" + r.sanitizer_report + "\"";
    return t;
  }
  t.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (t.exit_code == 0 && !r.result.empty() && r.result[0] == 'R') {
    t.status = TaskResult::Status::Ok;
    t.payload = r.result.substr(1);
  } else if (t.exit_code == 0 && !r.result.empty() && r.result[0] == 'E') {
    t.status = TaskResult::Status::Threw;
    t.detail = "threw " + r.result.substr(1);
  } else {
    t.status = TaskResult::Status::Crashed;
    t.detail = "exited with status " + std::to_string(t.exit_code) +
               (r.sanitizer_report.empty()
                    ? " without reporting a result (exit() or quick_exit() called by the code under test?)"
                    : " after the sanitizer's report \"" + r.sanitizer_report + "\"");
  }
  return t;
}

}  // namespace

std::string describe_signal(int sig) {
  const char* name = nullptr;
  const char* what = ::strsignal(sig);
  switch (sig) {
    case SIGSEGV:
      name = "SIGSEGV";
      break;
    case SIGABRT:
      name = "SIGABRT";
      break;
    case SIGFPE:
      name = "SIGFPE";
      break;
    case SIGILL:
      name = "SIGILL";
      break;
    case SIGBUS:
      name = "SIGBUS";
      break;
    case SIGKILL:
      name = "SIGKILL";
      break;
    case SIGTERM:
      name = "SIGTERM";
      break;
    case SIGXCPU:
      name = "SIGXCPU";
      break;
    case SIGPIPE:
      name = "SIGPIPE";
      break;
    default:
      break;
  }
  std::string s = "signal " + std::to_string(sig);
  if (name)
    s += " (" + std::string(name) + (what ? std::string(", ") + what : std::string()) + ")";
  else if (what)
    s += " (" + std::string(what) + ")";
  return s;
}

int current_worker() { return g_worker; }

namespace {

// The order tasks start in: o.start_order when it is a permutation of the tasks, else their own.
std::vector<std::size_t> start_order(std::size_t n, const std::vector<std::size_t>& wanted) {
  std::vector<std::size_t> seq = wanted;
  std::vector<bool> seen(n, false);
  bool permutation = seq.size() == n;
  for (std::size_t i : seq) permutation = permutation && i < n && !seen[i] && (seen[i] = true);
  if (!permutation) {
    if (!seq.empty()) throw std::invalid_argument("run_isolated: start_order is not a permutation of the tasks");
    seq.resize(n);
    for (std::size_t i = 0; i < seq.size(); ++i) seq[i] = i;
  }
  return seq;
}

// Without isolation (a debugger's run): each task in this process, in turn.
void run_in_this_process(const std::vector<std::function<std::string()>>& tasks, const IsolationOptions& o,
                         const std::vector<std::size_t>& seq, const std::function<bool(int, std::size_t)>& prepare,
                         std::vector<TaskResult>& results) {
  g_worker = 0;
  for (std::size_t i : seq) {
    const auto start = Clock::now();
    if (o.on_started) o.on_started(i);
    if (prepare(0, i)) {
      try {
        results[i].payload = tasks[i]();
        results[i].status = TaskResult::Status::Ok;
      } catch (const std::exception& e) {
        results[i].status = TaskResult::Status::Threw;
        results[i].detail = std::string("threw ") + e.what();
      }
      if (o.worker_done) o.worker_done(0, true);
    }
    results[i].seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (o.on_finished) o.on_finished(i, results[i]);
  }
}

// Forks the child that runs task i as worker w, its result and output read through two pipes.
Running fork_task(const std::function<std::string()>& task, std::size_t i, int w, const std::deque<Running>& running,
                  const IsolationOptions& o, pid_t self) {
  g_worker = w;
  int rp[2], op[2];
  if (::pipe2(rp, O_CLOEXEC) != 0 || ::pipe2(op, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
  if (pid == 0) {
    for (const auto& r : running) {  // the other children's pipes are not this child's business
      ::close(r.result_fd);
      ::close(r.output_fd);
    }
    ::close(rp[0]);
    ::close(op[0]);
    child_main(task, rp[1], op[1], o.memory_limit_mb, self);
  }
  ::close(rp[1]);
  ::close(op[1]);
  ::fcntl(rp[0], F_SETFL, O_NONBLOCK);
  ::fcntl(op[0], F_SETFL, O_NONBLOCK);
  g_worker = 0;
  Running r{i, w, pid, rp[0], op[0], Clock::now(), {}, {}, {}, {}, {}, {}, {}, {}};
  r.worker0 = o.worker_times ? o.worker_times(w) : TreeTimes{};
  return r;
}

// The code's CPU and run-queue delay, read four times a second: the limit is on the work it does,
// and the kernel's accounting tells a task that sleeps from one a busy machine starves.
void sample_times(Running& r, const IsolationOptions& o, Clock::time_point now) {
  if (!r.queued) r.queued = std::make_shared<QueuedSoFar>();
  if (!r.account) r.account = std::make_shared<RunQueueAccount>(r.worker0);
  r.times = r.queued->sample(r.pid);
  std::vector<TreeTimes> trees{r.times};  // the check's tree and its server's, task by task
  if (o.worker_times) {
    TreeTimes w = o.worker_times(r.worker);
    r.times.cpu += w.cpu - r.worker0.cpu;
    r.times.queued += w.queued - r.worker0.queued;
    r.times.queued_known = r.times.queued_known || w.queued_known;
    trees.push_back(std::move(w));
  }
  r.account->look(trees, std::chrono::duration<double>(now - r.start).count());
  r.sampled = now;
}

// The result of a task stopped by a limit: whose fault, in the kernel's words (a task that waits,
// or whose own tasks hold its cores, is the code's; one the machine starves is not).
TaskResult stopped_result(const Running& r, double wall, const LimitVerdict& v) {
  TaskResult t;
  t.seconds = wall;
  t.cpu_seconds = r.times.cpu;
  t.queued_seconds = r.times.queued;
  t.output = r.output.size() > kOutputTail ? r.output.substr(r.output.size() - kOutputTail) : r.output;
  t.sanitizer_report = r.sanitizer_report;
  if (!r.sanitizer_report.empty()) {  // it was dying, not hanging: the sanitizer had reported an error
    t.status = TaskResult::Status::Crashed;
    t.detail = "stopped while writing the sanitizer's report \"" + r.sanitizer_report + "\"";
    return t;
  }
  t.status = v.machine ? TaskResult::Status::Busy : TaskResult::Status::TimedOut;
  t.detail = v.detail;
  return t;
}

// Waits, a fiftieth of a second at most, for a running task's child to write to either pipe.
void wait_for_output(const std::deque<Running>& running) {
  std::vector<pollfd> fds;
  for (const auto& r : running) {
    if (r.result_fd >= 0) fds.push_back(pollfd{r.result_fd, POLLIN, 0});
    if (r.output_fd >= 0) fds.push_back(pollfd{r.output_fd, POLLIN, 0});
  }
  ::poll(fds.data(), fds.size(), 20);
}

// Reads what the task's child has written to its pipes; a pipe at its end is closed.
void read_pipes(Running& r) {
  if (r.result_fd >= 0 && !drain(r.result_fd, r.result)) {
    ::close(r.result_fd);
    r.result_fd = -1;
  }
  if (r.output_fd >= 0 && !drain(r.output_fd, r.output, &r.sanitizer_report)) {
    ::close(r.output_fd);
    r.output_fd = -1;
  }
}

// Judges the work of a task still running against its limit; one past it (and not busy writing a
// sanitizer's report) is killed and its result recorded. True when it was stopped.
bool stop_if_over_limit(Running& r, const WorkLimit& limit, const IsolationOptions& o,
                        std::vector<TaskResult>& results) {
  // The code's CPU and run-queue delay, read four times a second: the limit is on the work it
  // does, and the kernel's accounting tells a task that sleeps from one a busy machine starves.
  const auto now = Clock::now();
  if (now - r.sampled > std::chrono::milliseconds(250)) sample_times(r, o, now);
  const double wall = std::chrono::duration<double>(now - r.start).count();
  WorkSoFar so_far;
  so_far.wall = wall;
  so_far.cpu = r.times.cpu;
  so_far.known = r.times.queued_known;
  so_far.looked_a_second = r.sampled > r.start + std::chrono::seconds(1);
  so_far.account = r.account.get();
  const LimitVerdict v = judge_work(limit, so_far);
  const bool dying = !r.sanitizer_report.empty() && wall < limit.wall_guard() + kSanitizerGrace;
  if (v.stop && !dying) {
    int status = 0;
    ::kill(-r.pid, SIGKILL);
    ::kill(r.pid, SIGKILL);
    ::waitpid(r.pid, &status, 0);
    results[r.index] = stopped_result(r, wall, v);
    return true;
  }
  return false;
}

}  // namespace

std::vector<TaskResult> run_isolated(const std::vector<std::function<std::string()>>& tasks,
                                     const IsolationOptions& o) {
  std::vector<TaskResult> results(tasks.size());
  const std::vector<std::size_t> seq = start_order(tasks.size(), o.start_order);
  // prepare_worker's failure is the task's: it did not run.
  auto prepare = [&](int w, std::size_t i) {
    if (!o.prepare_worker) return true;
    try {
      o.prepare_worker(w);
      return true;
    } catch (const std::exception& e) {
      results[i].status = TaskResult::Status::Threw;
      results[i].detail = std::string("threw ") + e.what();
      return false;
    }
  };
  if (!o.isolate) {
    run_in_this_process(tasks, o, seq, prepare, results);
    return results;
  }

  const int jobs = o.jobs < 1 ? 1 : o.jobs;
  const WorkLimit limit{o.timeout_seconds, o.wall_factor, o.wall_floor, o.busy_factor};
  std::deque<Running> running;
  std::size_t next = 0;
  const pid_t self = ::getpid();
  std::vector<bool> busy(static_cast<std::size_t>(jobs), false);

  auto start_one = [&](std::size_t i) {
    int w = 0;
    while (busy[static_cast<std::size_t>(w)]) ++w;
    if (o.on_started) o.on_started(i);
    if (!prepare(w, i)) {
      if (o.on_finished) o.on_finished(i, results[i]);
      return;
    }
    busy[static_cast<std::size_t>(w)] = true;
    running.push_back(fork_task(tasks[i], i, w, running, o, self));
  };

  while (next < tasks.size() || !running.empty()) {
    while (next < tasks.size() && static_cast<int>(running.size()) < jobs) start_one(seq[next++]);

    wait_for_output(running);
    if (o.on_idle) o.on_idle();

    for (auto it = running.begin(); it != running.end();) {
      Running& r = *it;
      read_pipes(r);
      int status = 0;
      const pid_t w = ::waitpid(r.pid, &status, WNOHANG);
      bool done = false;
      if (w == r.pid) {
        // It has ended: whatever it wrote is in the pipes (or held open by a descendant).
        if (r.result_fd >= 0) drain(r.result_fd, r.result);
        if (r.output_fd >= 0) drain(r.output_fd, r.output, &r.sanitizer_report);
        ::kill(-r.pid, SIGKILL);  // descendants it may have left behind
        results[r.index] = finish(r, status);
        done = true;
      } else {
        done = stop_if_over_limit(r, limit, o, results);
      }
      if (done) {
        if (r.result_fd >= 0) ::close(r.result_fd);
        if (r.output_fd >= 0) ::close(r.output_fd);
        busy[static_cast<std::size_t>(r.worker)] = false;
        if (o.worker_done) {
          const auto st = results[r.index].status;
          o.worker_done(r.worker, st == TaskResult::Status::Ok || st == TaskResult::Status::Threw);
        }
        const std::size_t index = r.index;
        it = running.erase(it);
        if (o.on_finished) o.on_finished(index, results[index]);
      } else {
        ++it;
      }
    }
  }
  return results;
}

}  // namespace gm::harness
