#include "harness/remote/remote_subject.hpp"

#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process_cpu.hpp"
#include "harness/isolation/run_queue_account.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/submission_intake.hpp"
#include "harness/languages/language.hpp"
#include "harness/remote/slot_names.hpp"

#include "core/data_path.hpp"
#include "core/declared_step.hpp"

#include "harness/isolation/isolate.hpp"
#include "harness/remote/protocol_codec.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

namespace gm::protocol {

namespace fs = std::filesystem;

bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string slot_table_json() {
  json t;
  t["protocol"] = kProtocolName;
  t["version"] = kProtocolVersion;
  t["mp50_bits"] = std::numeric_limits<Real50>::digits;
  json slots = json::array();
  for (const auto& s : subject_slots())
    slots.push_back({{"name", s.name}, {"signature", s.signature}, {"place", s.place}, {"meaning", s.meaning}});
  t["slots"] = slots;
  t["steps"] = {{"rigid_body_step", "RigidBodyState<T>(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h)"},
                {"manakov_step", "ManakovState<T>(const MatX<T>& A, const ManakovState<T>& x, const T& h)"},
                {"clebsch_step", "Vec3Pair<T>(const Vec3<T>& I, const Vec3Pair<T>& QP, const T& h)"},
                {"manakov_clebsch_step", "MatXPair<T>(const MatX<T>& A, const MatXPair<T>& QP, const T& h)"}};
  return t.dump();
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kMaxReplyBytes = 32u << 20;  // one reply line

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string program_name(const std::vector<std::string>& argv) { return argv.empty() ? std::string("?") : argv.back(); }

// Keeps the end of what the implementation prints (shown with a failure of its process).
void drain_output(ServerProcess& s) {
  if (s.output < 0) return;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(s.output, buf, sizeof buf);
    if (n > 0) {
      s.output_tail.append(buf, static_cast<std::size_t>(n));
      if (s.output_tail.size() > 16000) s.output_tail.erase(0, s.output_tail.size() - 8000);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) {  // it closed its output (it is ending)
      ::close(s.output);
      s.output = -1;
    }
    return;
  }
}

std::string with_output(const ServerProcess& s) {
  std::string tail =
      s.output_tail.size() > 4000 ? "..." + s.output_tail.substr(s.output_tail.size() - 4000) : s.output_tail;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
  return tail.empty() ? std::string() : "\nwhat it printed last:\n" + tail;
}

}  // namespace

Connection::Connection(std::vector<std::string> argv, std::string language)
    : argv_(std::move(argv)), language_(std::move(language)), table_(slot_table_json()), owner_(::getpid()) {
  void* p = ::mmap(nullptr, sizeof(SlotState) * kMaxWorkers, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw RemoteError(std::string("cannot map shared memory: ") + std::strerror(errno));
  slots_ = static_cast<SlotState*>(p);
}

Connection::~Connection() {
  stop();
  if (::getpid() == owner_ && slots_) ::munmap(slots_, sizeof(SlotState) * kMaxWorkers);
}

void Connection::kill_server(ServerProcess& s) {
  if (s.to >= 0) ::close(s.to);  // a server ends when its input ends
  s.to = -1;
  if (s.pid > 0) {
    bool gone = false;
    for (int i = 0; i < 50 && !gone; ++i) {
      if (::waitpid(s.pid, nullptr, WNOHANG) == s.pid)
        gone = true;
      else
        ::usleep(2000);
    }
    ::kill(-s.pid, SIGKILL);  // its process group: a session's copy too
    if (!gone) {
      ::kill(s.pid, SIGKILL);
      ::waitpid(s.pid, nullptr, 0);
    }
  }
  for (int* fd : {&s.replies, &s.output})
    if (*fd >= 0) ::close(*fd);
  s = ServerProcess{};
}

void Connection::stop() {
  std::lock_guard lock(mutex_);
  const pid_t me = ::getpid();
  if (me == owner_)
    for (auto& s : pool_) kill_server(s);
  if (own_pid_ == me) kill_server(own_);
}

void Connection::start(ServerProcess& s) {
  int in[2], rep[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(rep, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0)
    throw RemoteError(std::string("cannot create pipes: ") + std::strerror(errno));
  // Octave has no fdopen: its server opens /proc/self/fd/3, which checks the pipe's own mode, and
  // a pipe made by root is 0600 root's. The sandbox runs the server as nobody when the harness is
  // root (CI), where every Octave submission failed its handshake ("fprintf: invalid stream
  // number"); the pipe is shared with that one process alone, so its mode may be open.
  ::fchmod(rep[1], 0666);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw RemoteError(std::string("cannot fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the process that talks to it
    if (::getppid() != parent) ::_exit(127);
    ::setpgid(0, 0);  // its own group: stopping it stops a session's copy too
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    ::dup2(out[1], 2);
    if (rep[1] == 3)
      ::fcntl(3, F_SETFD, 0);
    else
      ::dup2(rep[1], 3);  // the reply channel: what the implementation prints cannot be taken for a reply
    ::setenv("GEOMECH_SLOT_TABLE", table_.c_str(), 1);
    ::setenv("GEOMECH_REPLY_FD", "3", 1);
    std::vector<char*> a;
    for (auto& x : argv_) a.push_back(const_cast<char*>(x.c_str()));
    a.push_back(nullptr);
    ::execvp(a[0], a.data());
    std::fprintf(stderr, "cannot run %s: %s\n", a[0], std::strerror(errno));
    ::_exit(127);
  }
  ::close(in[0]);
  ::close(rep[1]);
  ::close(out[1]);
  ::fcntl(out[0], F_SETFL, ::fcntl(out[0], F_GETFL) | O_NONBLOCK);
  s = ServerProcess{};
  s.pid = pid;
  s.to = in[1];
  s.replies = rep[0];
  s.output = out[0];
  std::signal(SIGPIPE, SIG_IGN);
  // Whether the sandbox started the program is bubblewrap's word (harness/isolation/sandbox.hpp),
  // asked once the process has ended before its handshake; the report is removed either way.
  std::string line;
  try {
    line = read_reply(s, "its handshake", handshake_seconds);
  } catch (const RemoteMachineFault&) {
    (void)harness::sandbox_start(pid);
    kill_server(s);
    throw;
  } catch (const RemoteError& e) {
    int status = 0;
    const bool ended = s.pid < 0 || ::waitpid(s.pid, &status, WNOHANG) == s.pid;
    if (ended) s.pid = -1;
    const harness::SandboxStart st = harness::sandbox_start(pid);
    kill_server(s);
    if (ended && st.reported && !st.started)
      throw RemoteMachineFault(
          "the grader's machine, not the implementation: the sandbox could not start its process (" +
          program_name(argv_) + "): " + e.what() + ". Fix: `geomech self-test` says what the sandbox lacks");
    throw;
  }
  (void)harness::sandbox_start(pid);  // it started: its report is not needed
  try {
    hello_ = json::parse(line);
  } catch (const std::exception& e) {
    const std::string tail = with_output(s);
    kill_server(s);
    throw RemoteError("the implementation's first line is not a JSON handshake (" + std::string(e.what()) +
                      "): " + line.substr(0, 300) + tail);
  }
  sessions_ = hello_.is_object() && hello_.value("sessions", false);
  // Later starts: the harness knows what works where, the server need not probe again.
  if (!table_.empty() && table_.back() == '}' && table_.find("\"probe\":false") == std::string::npos)
    table_.insert(table_.size() - 1, ",\"probe\":false");
}

std::string Connection::died(ServerProcess& s, const std::string& otherwise) {
  int status = 0;
  for (int i = 0; i < 25 && s.pid > 0; ++i) {  // up to half a second for it to be reaped
    if (::waitpid(s.pid, &status, WNOHANG) == s.pid) {
      s.pid = -1;
      if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        std::string how = "exited with status " + std::to_string(code);
        // A sandbox (bwrap) or a shell passes on a signal's death as 128 + the signal's number.
        if (code > 128 && code < 128 + 65)
          how += " (128 + " + std::to_string(code - 128) + ": " + strsignal(code - 128) + ")";
        return how;
      }
      if (WIFSIGNALED(status)) return std::string("was killed by signal ") + strsignal(WTERMSIG(status));
      return otherwise;
    }
    ::usleep(20000);
  }
  return otherwise;
}

std::string Connection::read_reply(ServerProcess& s, const std::string& what, double deadline_seconds) {
  const auto start = Clock::now();
  // A deadline is on the work of the implementation's process tree, judged by the kernel's
  // accounting as a check's limit is (harness/isolation/work_limit.hpp): its CPU time, a wall guard
  // for a process that sleeps, and the machine's fault only when it starved the task waited on.
  harness::WorkLimit limit = reply_limit;
  limit.cpu_seconds = deadline_seconds;
  const harness::TreeTimes before =
      deadline_seconds > 0 && s.pid > 0 ? harness::tree_times(s.pid) : harness::TreeTimes{};
  harness::RunQueueAccount account(before);
  auto looked = start;
  for (;;) {
    const auto nl = s.buffer.find('\n');
    if (nl != std::string::npos) {
      std::string line = s.buffer.substr(0, nl);
      s.buffer.erase(0, nl + 1);
      return line;
    }
    pollfd fds[2] = {{s.replies, POLLIN, 0}, {s.output, POLLIN, 0}};
    int wait_ms = 1000;
    if (deadline_seconds > 0 && s.pid > 0) {
      wait_ms = 250;
      if (Clock::now() - looked >= std::chrono::milliseconds(250)) {
        looked = Clock::now();
        const harness::TreeTimes now = harness::tree_times(s.pid);
        account.look(now, seconds_since(start));
        harness::WorkSoFar so_far;
        so_far.wall = seconds_since(start);
        so_far.cpu = now.cpu - before.cpu;
        so_far.known = now.queued_known;
        so_far.looked_a_second = account.seconds() > 1;
        so_far.account = &account;
        const harness::LimitVerdict v = harness::judge_work(limit, so_far);
        if (v.stop) {
          drain_output(s);
          const std::string head = "the implementation's process (" + program_name(argv_) + ") did not answer " + what +
                                   " within " + std::to_string(static_cast<int>(deadline_seconds)) + " s";
          if (v.machine)
            throw RemoteMachineFault("the grader's machine, not the implementation: " + head + ": it " + v.detail +
                                     ". Fix: run it again on a less busy machine");
          throw RemoteError(head + " (of CPU time; does loading it run a long computation, or wait for input?): it " +
                            v.detail + with_output(s));
        }
      }
    }
    const int n_fds = s.output >= 0 ? 2 : 1;
    if (::poll(fds, n_fds, wait_ms) < 0 && errno != EINTR)
      throw RemoteError(std::string("cannot wait for the implementation: ") + std::strerror(errno));
    drain_output(s);
    if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    char buf[65536];
    const ssize_t n = ::read(s.replies, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {
      drain_output(s);
      const std::string how = died(s, "closed its reply channel");
      throw RemoteError("the implementation's process (" + program_name(argv_) + ") " + how + " before it answered " +
                        what + with_output(s));
    }
    s.buffer.append(buf, static_cast<std::size_t>(n));
    // A reply is one line; one longer than any the protocol needs (the longest, a run of 512 steps of
    // Manakov's n = 6 in 50 digits, is about 2 MiB) is a flood, not a reply: the
    // implementation's process is not read further.
    if (s.buffer.size() > kMaxReplyBytes && s.buffer.find('\n') == std::string::npos) {
      s.buffer.clear();
      throw RemoteError("the implementation's process (" + program_name(argv_) + ") answered " + what +
                        " with more than " + std::to_string(kMaxReplyBytes >> 20) +
                        " MiB on one line: a flood, not a reply (nothing more of it is read)");
    }
  }
}

json Connection::request(ServerProcess& s, const json& req, const std::string& what, double deadline_seconds) {
  return request_text(s, req.dump(), req["id"].get<long>(), what, deadline_seconds);
}

json Connection::request_text(ServerProcess& s, const std::string& text, long id, const std::string& what,
                              double deadline_seconds) {
  // The empty line after each request: Octave's fgetl returns a line only once it has seen the next
  // byte; every server skips empty lines.
  if (!write_all(s.to, text + "\n\n")) {
    drain_output(s);
    const std::string how = died(s, "stopped reading its input");
    throw RemoteError("cannot send " + what + ": the implementation's process (" + program_name(argv_) + ") " + how +
                      " (a server answers every request and ends only when its input ends)" + with_output(s));
  }
  const std::string line = read_reply(s, what, deadline_seconds);
  json rep;
  try {
    rep = json::parse(line);
  } catch (const std::exception& e) {
    throw RemoteError("the implementation answered " + what + " with something that is not JSON (" + e.what() +
                      "): " + line.substr(0, 300) + with_output(s));
  }
  if (!rep.is_object())
    throw RemoteError("the implementation's reply to " + what + " is not a JSON object: " + line.substr(0, 300));
  if (rep.contains("died"))
    throw RemoteError(
        "the implementation's process " +
        harness::bounded_text(rep["died"].is_string() ? rep["died"].get<std::string>() : rep["died"].dump()) +
        " while answering " + what + with_output(s));
  if (rep.contains("fatal"))
    throw RemoteError(
        "the implementation's server failed on " + what + ": " +
        harness::bounded_text(rep["fatal"].is_string() ? rep["fatal"].get<std::string>() : rep["fatal"].dump()) +
        with_output(s));
  if (!rep.contains("id") || rep["id"] != id)
    throw RemoteError("the implementation's reply to " + what + " answers another request (id " +
                      (rep.contains("id") ? rep["id"].dump() : std::string("missing")) + ", expected " +
                      std::to_string(id) + ")");
  return rep;
}

harness::TreeTimes Connection::server_times(int w) const {
  // The server of slot w (a session runs in a fork of it), or this process's own copy.
  pid_t pid = -1;
  if (w >= 0 && static_cast<std::size_t>(w) < pool_.size() && pool_[static_cast<std::size_t>(w)].running())
    pid = pool_[static_cast<std::size_t>(w)].pid;
  else if (own_.running() && own_pid_ == ::getpid())
    pid = own_.pid;
  return pid > 0 ? harness::tree_times(pid) : harness::TreeTimes{};
}

ServerProcess& Connection::server_for_this_process() {
  const pid_t me = ::getpid();
  const int w = harness::current_worker();
  if (me == owner_) {  // not in a check's process: --no-isolation, the handshake, a direct use
    if (pool_.size() <= static_cast<std::size_t>(w)) pool_.resize(static_cast<std::size_t>(w) + 1);
    if (!pool_[static_cast<std::size_t>(w)].running()) start(pool_[static_cast<std::size_t>(w)]);
    return pool_[static_cast<std::size_t>(w)];
  }
  // A session only on a server prepared for this worker slot by the process that forked this one
  // (run_isolated); any other fork starts a copy of its own.
  if (sessions_ && abandoned_pid_ != me && static_cast<std::size_t>(w) < prepared_.size() &&
      prepared_[static_cast<std::size_t>(w)] && pool_[static_cast<std::size_t>(w)].running()) {
    ServerProcess& s = pool_[static_cast<std::size_t>(w)];  // started by the owner before this process was forked
    if (session_pid_ != me) {
      slots_[w].session_open = 1;
      slots_[w].in_flight = 1;
      const json r = request(s, json{{"id", next_id_++}, {"session", "begin"}}, "the request to start a session", 60);
      if (r.value("session", "") != "begun")
        throw RemoteError("the implementation's server did not start a session: " + r.dump().substr(0, 300));
      slots_[w].in_flight = 0;
      session_pid_ = me;
    }
    return s;
  }
  if (own_pid_ != me) {  // inherited from another process: not ours
    own_ = ServerProcess{};
    own_pid_ = me;
  }
  if (!own_.running()) start(own_);
  return own_;
}

const json& Connection::hello() {
  std::lock_guard lock(mutex_);
  server_for_this_process();
  return hello_;
}

void Connection::prepare_worker(int w) {
  std::lock_guard lock(mutex_);
  if (::getpid() != owner_ || w < 0 || w >= kMaxWorkers || !sessions_) return;
  if (pool_.size() <= static_cast<std::size_t>(w)) pool_.resize(static_cast<std::size_t>(w) + 1);
  ServerProcess& s = pool_[static_cast<std::size_t>(w)];
  if (s.running() && (slots_[w].session_open || slots_[w].in_flight)) kill_server(s);
  slots_[w] = SlotState{0, 0};
  if (!s.running()) start(s);
  if (prepared_.size() <= static_cast<std::size_t>(w)) prepared_.resize(static_cast<std::size_t>(w) + 1, false);
  prepared_[static_cast<std::size_t>(w)] = true;
}

void Connection::worker_done(int w, bool ended_normally) {
  std::lock_guard lock(mutex_);
  if (::getpid() != owner_ || w < 0 || w >= kMaxWorkers || static_cast<std::size_t>(w) >= pool_.size()) return;
  ServerProcess& s = pool_[static_cast<std::size_t>(w)];
  if (static_cast<std::size_t>(w) < prepared_.size()) prepared_[static_cast<std::size_t>(w)] = false;
  if (!slots_[w].session_open) return;  // the check called nothing
  bool clean = ended_normally && !slots_[w].in_flight && s.running();
  if (clean) {
    try {  // the session's copy answers and ends; the server is back as the handshake left it
      const json r = request(s, json{{"id", next_id_++}, {"session", "end"}}, "the request to end a session", 30);
      clean = r.value("session", "") == "ended";
    } catch (const RemoteError&) {
      clean = false;
    }
  }
  if (!clean) kill_server(s);  // started again by the next prepare_worker
  slots_[w] = SlotState{0, 0};
}

std::vector<Reply> Connection::call_batch(const std::vector<Call>& calls) {
  std::vector<std::string> args_texts;
  args_texts.reserve(calls.size());
  for (const auto& c : calls) args_texts.push_back(c.args.dump());
  protocol_counts().calls += static_cast<long>(calls.size());
  return exchange(calls, args_texts);
}

std::vector<Reply> Connection::exchange(const std::vector<Call>& calls, const std::vector<std::string>& args_texts) {
  std::lock_guard lock(mutex_);
  const pid_t me = ::getpid();
  // The request {"id", "calls": [{"slot", "scalar", "args", "integrator"?, "repeat"?}, ...]}, written
  // out directly: the arguments are already text (the memory's key), and are not copied again.
  const long id = next_id_++;
  std::string req = "{\"id\":" + std::to_string(id) + ",\"calls\":[";
  for (std::size_t i = 0; i < calls.size(); ++i) {
    const Call& c = calls[i];
    if (i > 0) req += ',';
    req += "{\"slot\":" + json(c.slot).dump() + ",\"scalar\":" + json(c.scalar).dump() + ",\"args\":" + args_texts[i];
    if (!c.integrator.empty()) req += ",\"integrator\":" + json(c.integrator).dump();
    if (c.repeat > 0) req += ",\"repeat\":" + std::to_string(c.repeat);
    req += '}';
  }
  req += "]}";
  const std::string what = calls.empty()
                               ? std::string("an empty request")
                               : "the call of '" + (calls[0].integrator.empty() ? "" : calls[0].integrator + ".") +
                                     calls[0].slot + "' (" + calls[0].scalar + ")";
  const int w = harness::current_worker();
  ServerProcess& s = server_for_this_process();
  const bool session = me != owner_ && sessions_ && session_pid_ == me && abandoned_pid_ != me;
  json rep;
  try {
    if (session) slots_[w].in_flight = 1;
    const auto asked = std::chrono::steady_clock::now();
    ++protocol_counts().round_trips;
    rep = request_text(s, req, id, what, 0);
    protocol_counts().waiting_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
    if (!rep.contains("results") || !rep["results"].is_array() || rep["results"].size() != calls.size())
      throw RemoteError("the implementation's reply to " + what + " has no \"results\" array of " +
                        std::to_string(calls.size()) + " entries: " + rep.dump().substr(0, 300));
    if (session) slots_[w].in_flight = 0;
  } catch (const RemoteError&) {
    // The server's state is unknown now (it died, or answered out of step): it is not used again.
    // Later calls of this process go to a copy started afresh, so that shrinking a failure still
    // tries each input for real; the worker's server is restarted for the next check (its
    // in-flight mark stays set).
    if (session)
      abandoned_pid_ = me;
    else
      kill_server(s);
    throw;
  }
  std::vector<Reply> out;
  out.reserve(calls.size());
  for (auto& r : rep["results"]) {
    Reply x;
    if (r.is_object() && r.contains("ok")) {
      x.ok = true;
      x.result = std::move(r["ok"]);
    } else {
      // A message and a traceback of any size are shown up to kMessageCap bytes each.
      x.error = harness::bounded_text(r.is_object() && r.contains("error") && r["error"].is_string()
                                          ? r["error"].get<std::string>()
                                          : r.dump(-1, ' ', false, json::error_handler_t::replace));
      if (r.is_object() && r.contains("traceback") && r["traceback"].is_string())
        x.error += "\n" + harness::bounded_text(r["traceback"].get<std::string>());
    }
    out.push_back(std::move(x));
  }
  return out;
}

json Connection::call(const Call& c) {
  auto function = [&] {  // named only in an error
    const std::string who = c.integrator.empty() ? c.slot : c.integrator + "." + c.slot;
    return (language_.empty() ? std::string("the implementation") : language_) + " function '" + who + "' (" +
           c.scalar + ")";
  };
  // A repeated call is answered from memory (harness/remote/call_memo.hpp); a run of steps is not kept.
  const std::string args_text = c.args.dump();  // the memory's key, and the request's arguments
  ++protocol_counts().calls;
  std::string key;
  std::optional<json> known;  // remembered, and asked again to compare
  if (c.repeat == 0) {
    key = c.integrator + '\n' + c.slot + '\n' + c.scalar + '\n' + args_text;
    std::lock_guard lock(memo_mutex_);
    bool recheck = false;
    if (const json* m = memo_.find(key, &recheck)) {
      if (!recheck) return ++protocol_counts().memo_hits, *m;
      known = *m;
    }
  }
  auto r = exchange({c}, {args_text});
  if (!r[0].ok) throw RemoteCallError(function() + " raised an error:\n" + r[0].error);
  if (known) {
    const std::string differs = CallMemo::compare(*known, r[0].result);
    if (!differs.empty())
      throw RemoteCallError(function() +
                            " answered the same arguments twice, differently (is it a function of its "
                            "arguments only? a persistent or global variable, or a random draw, makes it not):\n"
                            "  arguments: " +
                            args_text.substr(0, 400) + "\n  " + differs);
    return std::move(r[0].result);
  }
  if (c.repeat == 0) {
    std::lock_guard lock(memo_mutex_);
    memo_.remember(key, r[0].result);
  }
  return std::move(r[0].result);
}

// ---- the handshake ------------------------------------------------------------------------------

namespace {
bool is_scalar_word(const std::string& s) { return s == "double" || s == "mp50" || s == "exact"; }

// One integrator of the handshake: its name (checked: it names figures and is typed in
// --integrator), steps, scalars, claims, state form, precision and domain. What it declares that the
// suite does not know goes to `d.unchecked` (so the check cannot pass on it); a malformed field
// throws RemoteError through `bad`.
RemoteDescription::Integrator parse_integrator(const json& i, RemoteDescription& d,
                                               const std::function<RemoteError(const std::string&)>& bad) {
  RemoteDescription::Integrator x;
  x.name = i.at("name").get<std::string>();
  // An integrator's name names figures and report sections and is typed in --integrator:
  // letters, digits and "_.-", at most 64 (it is the submission's text).
  if (x.name.empty() || x.name.size() > 64 ||
      x.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-") !=
          std::string::npos)
    throw bad("an integrator's name must be 1 to 64 letters, digits, '_', '.' or '-'; got '" +
              harness::inert_text(harness::bounded_text(x.name, 200)) + "'");
  for (const auto& s : i.value("steps", json::array())) x.steps.push_back(s.get<std::string>());
  for (const auto& s : i.value("scalars", json::array({"double"}))) x.scalars.push_back(s.get<std::string>());
  if (i.contains("claims") && i["claims"].is_object()) {
    const json& c = i["claims"];
    x.has_claims = true;
    x.claims.integrator = x.name;
    x.claims.order = c.value("order", 0);
    std::set<std::string> known{"order"};
    for (const auto& bc : kBooleanClaims) {
      x.claims.*bc.member = c.value(bc.name, false);
      known.insert(bc.name);
    }
    // A claim the suite does not know is not verified, so it fails the check (UNCHECKED)
    // instead of passing with a warning, naming the claim it probably means and every known one.
    for (const auto& [k, v] : c.items())
      if (!known.count(k)) {
        const std::vector<std::string> names(known.begin(), known.end());
        const std::string guess = harness::closest_claim(k, names);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        d.unchecked.push_back("integrator '" + x.name + "' claims '" + k +
                              "', which is not a claim the suite knows, so " + "nothing can verify it" +
                              (guess.empty() ? "" : "; did you mean '" + guess + "'?") + " The claims are: " + list);
      }
  }
  // The form its rigid-body step keeps the state in, and the precision it states.
  if (i.contains("state")) {
    try {
      x.form = parse_state_form(i["state"].is_string() ? i["state"].get<std::string>() : i["state"].dump());
    } catch (const std::exception& e) {
      d.unchecked.push_back("integrator '" + x.name + "' declares its state as " + i["state"].dump().substr(0, 80) +
                            ": " + e.what());
      x.steps.erase(std::remove(x.steps.begin(), x.steps.end(), "rigid_body_step"), x.steps.end());
    }
  }
  x.claims.integrator = x.name;
  if (i.contains("precision") && i["precision"].is_string()) {
    x.claims.precision = i["precision"].get<std::string>();
    x.has_claims = true;
  }
  if (i.contains("precision_reason") && i["precision_reason"].is_string())
    x.claims.precision_reason = i["precision_reason"].get<std::string>();
  // Where the step is meant to work: positive numbers, each optional.
  if (i.contains("domain") && i["domain"].is_object() && !i["domain"].empty()) {
    x.has_claims = true;
    x.claims.integrator = x.name;
    for (const auto& [k, v] : i["domain"].items()) {
      double* field = k == "max_omega" ? &x.claims.domain.max_omega
                      : k == "max_pi"  ? &x.claims.domain.max_pi
                      : k == "min_h"   ? &x.claims.domain.min_h
                                       : nullptr;
      if (!field) {
        d.unchecked.push_back("integrator '" + x.name + "' declares its domain with '" + harness::inert_text(k) +
                              "', which the suite does not know (max_omega, max_pi, min_h)");
        continue;
      }
      if (!v.is_number() || !(v.get<double>() > 0) || !std::isfinite(v.get<double>()))
        throw bad("integrator '" + x.name + "': domain '" + k + "' must be a positive number, got " + v.dump());
      *field = v.get<double>();
    }
  }
  return x;
}

}  // namespace

RemoteDescription parse_hello(const json& h) {
  auto bad = [](const std::string& why) { return RemoteError("handshake: " + why); };
  if (!h.is_object()) throw bad("not a JSON object");
  if (h.contains("fatal"))
    throw RemoteError("the implementation could not start: " + harness::bounded_text(h["fatal"].is_string()
                                                                                         ? h["fatal"].get<std::string>()
                                                                                         : h["fatal"].dump()));
  if (h.value("protocol", "") != kProtocolName)
    throw bad(std::string("\"protocol\" must be \"") + kProtocolName + "\"");
  if (!h.contains("version") || !h["version"].is_number_integer() || h["version"].get<int>() != kProtocolVersion)
    throw bad("this harness speaks version " + std::to_string(kProtocolVersion) + "; the implementation speaks " +
              (h.contains("version") ? h["version"].dump() : std::string("none")));
  RemoteDescription d;
  d.language = h.value("language", "unknown");
  d.language_version = h.contains("language_version") && h["language_version"].is_string()
                           ? h["language_version"].get<std::string>()
                           : "";
  d.interpreter = h.contains("interpreter") && h["interpreter"].is_string() ? h["interpreter"].get<std::string>() : "";
  d.description = h.value("description", "");
  if (h.contains("slots")) {
    if (!h["slots"].is_object()) throw bad("\"slots\" must map each scalar to a list of slot names");
    for (const auto& [scalar, list] : h["slots"].items()) {
      if (scalar != "double" && scalar != "mp50" && scalar != "exact") throw bad("unknown scalar '" + scalar + "'");
      for (const auto& s : list) {
        const std::string name = s.get<std::string>();
        if (!is_slot_name(name)) {
          d.warnings.push_back("'" + name + "' is not a slot of this harness (see `geomech slots`) and is ignored");
          continue;
        }
        d.slots[scalar].insert(name);
      }
    }
  }
  if (h.contains("integrators"))
    for (const auto& i : h["integrators"]) d.integrators.push_back(parse_integrator(i, d, bad));
  // What the implementation says of itself is its own text: each bounded, notes only on
  // slots and scalars there are, at most kMaxRemarks warnings and unchecked items (the rest counted).
  auto text = [](const json& j) { return harness::bounded_text(j.is_string() ? j.get<std::string>() : j.dump()); };
  constexpr std::size_t kMaxRemarks = 64;
  auto listed = [&](const json& list, std::vector<std::string>& into, const char* what) {
    if (!list.is_array()) return;
    for (const auto& w : list)
      if (into.size() < kMaxRemarks) into.push_back(text(w));
    if (list.size() > kMaxRemarks)
      into.push_back(std::to_string(list.size() - kMaxRemarks) + " more " + what +
                     " of the implementation's are not shown");
  };
  if (h.contains("notes") && h["notes"].is_object())
    for (const auto& [scalar, slots] : h["notes"].items())
      if (is_scalar_word(scalar) && slots.is_object())
        for (const auto& [slot, why] : slots.items())
          if (is_slot_name(slot)) d.notes[scalar][slot] = text(why);
  if (h.contains("warnings")) listed(h["warnings"], d.warnings, "warnings");
  if (h.contains("unchecked")) listed(h["unchecked"], d.unchecked, "items it could not check");
  d.repeat = h.value("repeat", false);
  if (h.contains("scalar_unavailable") && h["scalar_unavailable"].is_object())
    for (const auto& [scalar, why] : h["scalar_unavailable"].items())
      if (is_scalar_word(scalar)) d.scalar_unavailable[scalar] = text(why);
  return d;
}

// ---- the subject ----------------------------------------------------------------------------------

namespace {

template <class T, class Sig>
struct RemoteSlot;

template <class T, class R, class... A>
struct RemoteSlot<T, R(A...)> {
  static std::function<R(A...)> make(std::shared_ptr<Connection> conn, const char* slot, std::string integrator = "") {
    // An integrator's step may return NaN or an infinity: what it computed, for the checks to name.
    const Values values = integrator.empty() ? Values::finite : Values::any;
    return [conn, slot, integrator, values](A... a) -> R {
      Call c{slot, scalar_word<T>(), json::array({encode<T, std::decay_t<A>>(a)...}), integrator};
      const json result = conn->call(c);
      // Decoded first without the text that names the function (a reply that decodes needs none);
      // a reply that does not is decoded again, to throw the same error with the function named.
      static const std::string unnamed;
      try {
        return decode<T, R>(result, unnamed, values);
      } catch (const ProtocolValueError&) {}
      const std::string who = (integrator.empty() ? std::string() : integrator + ".") + slot;
      try {
        return decode<T, R>(
            result, "the result of " + conn->language() + " function '" + who + "' (" + scalar_word<T>() + ")", values);
      } catch (const ProtocolValueError& e) {
        throw ProtocolValueError(std::string(e.what()) + "; the reply was " + result.dump().substr(0, 300));
      }
    };
  }
};

// An integrator's run of n steps in one call ("repeat": n): the list of the n states.
template <class T, class State, class Param>
std::function<std::vector<State>(const Param&, const State&, const T&, int)> remote_run(
    std::shared_ptr<Connection> conn, const char* slot, std::string integrator) {
  return [conn, slot, integrator](const Param& p, const State& x, const T& h, int n) {
    Call c{slot, scalar_word<T>(), json::array({encode<T, Param>(p), encode<T, State>(x), encode<T, T>(h)}), integrator,
           n};
    const json result = conn->call(c);
    const std::string what = "the run of " + std::to_string(n) + " steps of " + conn->language() + " function '" +
                             integrator + "." + slot + "' (" + scalar_word<T>() + ")";
    if (!result.is_array() || static_cast<int>(result.size()) != n)
      throw ProtocolValueError(what + ": expected a list of " + std::to_string(n) + " states; the reply was " +
                               result.dump().substr(0, 300));
    std::vector<State> out;
    out.reserve(n);
    for (const auto& r : result) out.push_back(decode<T, State>(r, what, Values::any));
    return out;
  };
}

template <class T>
std::shared_ptr<Subject<T>> make_part(const std::shared_ptr<Connection>& conn, const RemoteDescription& d) {
  const char* scalar = scalar_word<T>();
  auto it = d.slots.find(scalar);
  auto s = std::make_shared<Subject<T>>();
  bool any = false;
  if (it != d.slots.end()) {
    const auto& have = it->second;
#define GM_REMOTE_SLOT(name, sig, place, meaning)    \
  if (have.count(#name)) {                           \
    s->name = RemoteSlot<T, sig>::make(conn, #name); \
    any = true;                                      \
  }
    GM_SUBJECT_SLOTS(GM_REMOTE_SLOT)
#undef GM_REMOTE_SLOT
  }
  if constexpr (!is_exact_v<T>) {
    for (const auto& i : d.integrators) {
      if (std::find(i.scalars.begin(), i.scalars.end(), scalar) == i.scalars.end()) continue;
      Integrator<T> in;
      in.name = i.name;
      for (const auto& step : i.steps) {
        if (step == "rigid_body_step" && !i.form.is_notes()) {
          // Kept in a declared form: the step is called with, and answers, that form; the suite
          // converts (core/declared_step.hpp).
          const StateForm form = i.form;
          const std::string name = i.name;
          in.form = form;
          in.declared_step = [conn, form, name](const Vec3<T>& I, const EngineState<T>& x, const T& h) {
            Call c{"rigid_body_step", scalar_word<T>(), json::array({encode<T>(I), encode<T>(x), encode<T>(h)}), name};
            return decode_engine_state<T>(conn->call(c), form,
                                          "the result of " + conn->language() + " function '" + name +
                                              ".rigid_body_step' (" + scalar_word<T>() + ")");
          };
          if (d.repeat)
            in.declared_run = [conn, form, name](const Vec3<T>& I, const EngineState<T>& x, const T& h, int n) {
              Call c{"rigid_body_step", scalar_word<T>(), json::array({encode<T>(I), encode<T>(x), encode<T>(h)}), name,
                     n};
              const json result = conn->call(c);
              const std::string what = "the run of " + std::to_string(n) + " steps of " + conn->language() +
                                       " function '" + name + ".rigid_body_step' (" + scalar_word<T>() + ")";
              if (!result.is_array() || static_cast<int>(result.size()) != n)
                throw ProtocolValueError(what + ": expected a list of " + std::to_string(n) +
                                         " states; the reply was " + result.dump().substr(0, 300));
              std::vector<EngineState<T>> out;
              for (const auto& r : result) out.push_back(decode_engine_state<T>(r, form, what));
              return out;
            };
          adapt_declared_step(in);
        } else if (step == "rigid_body_step") {
          in.rigid_body_step =
              RemoteSlot<T, RigidBodyState<T>(const Vec3<T>&, const RigidBodyState<T>&, const T&)>::make(
                  conn, "rigid_body_step", i.name);
          if (d.repeat) in.rigid_body_run = remote_run<T, RigidBodyState<T>, Vec3<T>>(conn, "rigid_body_step", i.name);
        } else if (step == "manakov_step") {
          in.manakov_step = RemoteSlot<T, ManakovState<T>(const MatX<T>&, const ManakovState<T>&, const T&)>::make(
              conn, "manakov_step", i.name);
          if (d.repeat) in.manakov_run = remote_run<T, ManakovState<T>, MatX<T>>(conn, "manakov_step", i.name);
        } else if (step == "clebsch_step")
          in.clebsch_step = RemoteSlot<T, Vec3Pair<T>(const Vec3<T>&, const Vec3Pair<T>&, const T&)>::make(
              conn, "clebsch_step", i.name);
        else if (step == "manakov_clebsch_step")
          in.manakov_clebsch_step = RemoteSlot<T, MatXPair<T>(const MatX<T>&, const MatXPair<T>&, const T&)>::make(
              conn, "manakov_clebsch_step", i.name);
      }
      s->integrators.push_back(std::move(in));
      any = true;
    }
  }
  return any ? s : nullptr;
}

}  // namespace

SubjectSet remote_subject(const std::shared_ptr<Connection>& conn, const std::string& name,
                          harness::SubjectInfo& info) {
  const RemoteDescription d = parse_hello(conn->hello());
  // The server that answered the handshake stays: it is worker 0's. With sessions, each check opens
  // one on its worker's server; without, each check's process starts its own copy.
  if (!conn->sessions()) conn->stop();
  info.prepare_worker = [conn](int w) { conn->prepare_worker(w); };
  info.out_of_process = true;
  info.worker_done = [conn](int w, bool normally) { conn->worker_done(w, normally); };
  info.worker_times = [conn](int w) { return conn->server_times(w); };
  // In a check's own process, its case budget counts the CPU of the code under test: this
  // process's and its server's.
  // The server's CPU is read from /proc for its whole tree (a session is a fork of it), which scans
  // every process of the machine: sampled at most every 20 ms (the budgets are seconds; a sample per
  // case made /proc the suite's largest cost after the JSON, docs/PERFORMANCE.md).
  set_code_cpu_clock([conn] {
    struct Sample {
      pid_t pid = -1;
      std::chrono::steady_clock::time_point at;
      double server_cpu = 0;
    };
    static Sample last;  // per process: a check's process starts with its parent's, and resamples
    const auto now = std::chrono::steady_clock::now();
    if (last.pid != ::getpid() || now - last.at >= std::chrono::milliseconds(20))
      last = Sample{::getpid(), now, conn->server_times(harness::current_worker()).cpu};
    return harness::self_cpu_seconds() + last.server_cpu;
  });
  SubjectSet s;
  s.name = name;
  s.description = d.description.empty() ? "a " + d.language + " implementation"
                                        : harness::inert_text(harness::bounded_text(d.description, 400));
  s.d = make_part<double>(conn, d);
  s.mp = make_part<Real50>(conn, d);
  s.q = make_part<Rational>(conn, d);
  for (const auto& i : d.integrators)
    if (i.has_claims) s.claims.push_back(i.claims);
  for (const auto& i : d.integrators)
    if (!i.claims.precision.empty()) {  // the author's own words: inert text (md_inline quotes it in a report)
      auto& c = s.claims[static_cast<std::size_t>(
          std::find_if(s.claims.begin(), s.claims.end(),
                       [&](const IntegratorClaims& x) { return x.integrator == i.name; }) -
          s.claims.begin())];
      c.precision = harness::inert_text(c.precision);
      c.precision_reason = harness::inert_text(c.precision_reason);
    }
  for (const auto& [scalar, slots] : d.notes)
    for (const auto& [slot, why] : slots) info.slot_notes[scalar][slot] = harness::inert_text(why);
  for (const auto& w : d.warnings) info.warnings.push_back(harness::inert_text(w));
  // The language the server speaks, as its row knows it (harness/languages/language.hpp); a
  // language of no row keeps the suite's words.
  const harness::Language* spoken = harness::language_named(d.language);
  if (spoken) info.language = spoken;
  // Which interpreter ran it, and its version, as the server says.
  if (!d.interpreter.empty())
    info.interpreter = harness::inert_text(d.interpreter) +
                       (d.language_version.empty()
                            ? std::string()
                            : " (" + (spoken && !spoken->version_label.empty() ? spoken->version_label + " " : "") +
                                  harness::inert_text(d.language_version) + ")");
  // "did you mean" for a function named like a slot but not as one (`energy`, `euler`).
  if (spoken && spoken->function_names && !info.source.empty()) {
    std::vector<std::string> names;
    std::error_code ec;
    if (!info.cells.empty()) {  // a notebook: its code cells, as they run
      for (const auto& c : info.cells)
        for (auto& n : spoken->function_names(c.code))
          if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(std::move(n));
    } else if (std::filesystem::is_directory(info.source, ec)) {
      if (spoken->folder_of_files)
        for (const auto& e : std::filesystem::directory_iterator(info.source, ec))
          if (e.path().extension() == spoken->extensions.front()) names.push_back(e.path().stem().string());
    } else {
      try {  // a stranger's file: read without following a link (harness/isolation/submission_intake.hpp)
        names = spoken->function_names(harness::read_stranger_file(info.source));
      } catch (const harness::RefusedEntry&) {
        // not read: no advice
      }
    }
    for (const auto& advice : harness::slot_name_advice(names)) info.warnings.push_back(advice);
  }
  for (const auto& u : d.unchecked) info.unchecked.push_back(harness::inert_text(u));
  for (const auto& [scalar, why] : d.scalar_unavailable) info.scalar_unavailable[scalar] = harness::inert_text(why);
  for (const char* scalar : {"double", "mp50", "exact"}) {
    const bool have = (std::string(scalar) == "double" ? s.d != nullptr
                       : std::string(scalar) == "mp50" ? s.mp != nullptr
                                                       : s.q != nullptr);
    if (!have && !info.scalar_unavailable.count(scalar))
      info.scalar_unavailable[scalar] =
          d.language + " implementation provides nothing in " + scalar + (spoken ? spoken->scalars_note : "");
  }
  return s;
}

}  // namespace gm::protocol
