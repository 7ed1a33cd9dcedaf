#include "harness/remote_subject.hpp"

#include "harness/protocol_codec.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <limits>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gm::protocol {

namespace fs = std::filesystem;

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
                {"manakov_step", "ManakovState<T>(const MatX<T>& A, const ManakovState<T>& x, const T& h)"}};
  return t.dump();
}

Connection::Connection(std::vector<std::string> argv, std::string language)
    : argv_(std::move(argv)), language_(std::move(language)), table_(slot_table_json()) {}

Connection::~Connection() { stop(); }

void Connection::stop() {
  if (child_ > 0 && owner_ == ::getpid()) {
    if (to_child_ >= 0) ::close(to_child_);
    to_child_ = -1;
    // Give it a moment to leave on end of input, then make sure.
    for (int i = 0; i < 50; ++i) {
      int status = 0;
      if (::waitpid(child_, &status, WNOHANG) == child_) {
        child_ = -1;
        break;
      }
      ::usleep(2000);
    }
    if (child_ > 0) {
      ::kill(child_, SIGKILL);
      ::waitpid(child_, nullptr, 0);
    }
  }
  for (int* fd : {&to_child_, &from_child_, &child_err_})
    if (*fd >= 0) ::close(*fd);
  to_child_ = from_child_ = child_err_ = -1;
  child_ = -1;
  buffer_.clear();
}

void Connection::ensure_started() {
  if (child_ > 0 && owner_ == ::getpid()) return;
  if (owner_ != ::getpid()) {
    // Inherited through fork from another process: those pipes and that child are not ours.
    for (int* fd : {&to_child_, &from_child_, &child_err_})
      if (*fd >= 0) ::close(*fd);
    to_child_ = from_child_ = child_err_ = -1;
    child_ = -1;
    buffer_.clear();
  }
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0)
    throw RemoteError(std::string("cannot create pipes: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw RemoteError(std::string("cannot fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the process that talks to us
    if (::getppid() != parent) ::_exit(127);
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    ::dup2(err[1], 2);
    ::setenv("GEOMECH_SLOT_TABLE", table_.c_str(), 1);
    std::vector<char*> a;
    for (auto& s : argv_) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    ::execvp(a[0], a.data());
    std::fprintf(stderr, "cannot run %s: %s\n", a[0], std::strerror(errno));
    ::_exit(127);
  }
  ::close(in[0]);
  ::close(out[1]);
  ::close(err[1]);
  ::fcntl(err[0], F_SETFL, ::fcntl(err[0], F_GETFL) | O_NONBLOCK);
  to_child_ = in[1];
  from_child_ = out[0];
  child_err_ = err[0];
  child_ = pid;
  owner_ = parent;
  std::signal(SIGPIPE, SIG_IGN);
  const std::string line = read_line();
  if (!table_.empty() && table_.back() == '}' && table_.find("\"probe\":false") == std::string::npos)
    table_.insert(table_.size() - 1, ",\"probe\":false");  // later starts: the harness knows what works where
  try {
    hello_ = json::parse(line);
  } catch (const std::exception& e) {
    const std::string tail = stderr_tail();
    stop();
    throw RemoteError("the implementation's first line is not a JSON handshake (" + std::string(e.what()) +
                      "): " + line.substr(0, 300) + (tail.empty() ? "" : "\n" + tail));
  }
}

std::string Connection::how_it_ended(const std::string& otherwise) {
  int status = 0;
  for (int i = 0; i < 25 && child_ > 0; ++i) {  // up to half a second for it to be reaped
    if (::waitpid(child_, &status, WNOHANG) == child_) {
      child_ = -1;
      if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        std::string how = "exited with status " + std::to_string(code);
        // A sandbox (bwrap) or a shell passes on a signal's death as 128 + the signal's number.
        if (code > 128 && code < 128 + 65) how += " (128 + " + std::to_string(code - 128) + ": " + strsignal(code - 128) + ")";
        return how;
      }
      if (WIFSIGNALED(status)) return std::string("was killed by signal ") + strsignal(WTERMSIG(status));
      return otherwise;
    }
    ::usleep(20000);
  }
  return otherwise;
}

std::string Connection::stderr_tail() {
  std::string s;
  if (child_err_ < 0) return s;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(child_err_, buf, sizeof buf);
    if (n <= 0) break;
    s.append(buf, static_cast<std::size_t>(n));
    if (s.size() > 20000) s.erase(0, s.size() - 20000);
  }
  return s;
}

std::string Connection::read_line() {
  for (;;) {
    const auto nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      std::string line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      return line;
    }
    char buf[65536];
    const ssize_t n = ::read(from_child_, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string how = how_it_ended("closed its output");
      const std::string tail = stderr_tail();
      throw RemoteError("the implementation's process (" + (argv_.empty() ? std::string("?") : argv_.back()) + ") " + how +
                        (tail.empty() ? std::string() : ":\n" + tail));
    }
    buffer_.append(buf, static_cast<std::size_t>(n));
  }
}

const json& Connection::hello() {
  std::lock_guard lock(mutex_);
  ensure_started();
  return hello_;
}

std::vector<Reply> Connection::call_batch(const std::vector<Call>& calls) {
  std::lock_guard lock(mutex_);
  ensure_started();
  json req;
  req["id"] = next_id_++;
  json cs = json::array();
  for (const auto& c : calls) {
    json j{{"slot", c.slot}, {"scalar", c.scalar}, {"args", c.args}};
    if (!c.integrator.empty()) j["integrator"] = c.integrator;
    cs.push_back(std::move(j));
  }
  req["calls"] = std::move(cs);
  const std::string text = req.dump() + "\n";
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(to_child_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string how = how_it_ended("stopped reading its input");
      const std::string tail = stderr_tail();
      throw RemoteError("cannot send a request: the implementation's process (" +
                        (argv_.empty() ? std::string("?") : argv_.back()) + ") " + how +
                        " (a server answers every request and ends only when its input ends)" +
                        (tail.empty() ? std::string() : ":\n" + tail));
    }
    done += static_cast<std::size_t>(n);
  }
  const std::string line = read_line();
  json rep;
  try {
    rep = json::parse(line);
  } catch (const std::exception& e) {
    throw RemoteError("the implementation answered with something that is not JSON (" + std::string(e.what()) +
                      "): " + line.substr(0, 300) +
                      " (only protocol lines may go to stdout: print diagnostics to stderr)");
  }
  if (rep.contains("fatal"))
    throw RemoteError("the implementation's server failed: " + rep["fatal"].dump());
  if (!rep.contains("results") || !rep["results"].is_array() || rep["results"].size() != calls.size())
    throw RemoteError("the implementation's reply has no \"results\" array of " + std::to_string(calls.size()) +
                      " entries: " + line.substr(0, 300));
  std::vector<Reply> out;
  for (const auto& r : rep["results"]) {
    Reply x;
    if (r.contains("ok")) {
      x.ok = true;
      x.result = r["ok"];
    } else {
      x.error = r.contains("error") && r["error"].is_string() ? r["error"].get<std::string>() : r.dump();
      if (r.contains("traceback") && r["traceback"].is_string()) x.error += "\n" + r["traceback"].get<std::string>();
    }
    out.push_back(std::move(x));
  }
  return out;
}

json Connection::call(const Call& c) {
  auto r = call_batch({c});
  if (!r[0].ok) {
    const std::string who = c.integrator.empty() ? c.slot : c.integrator + "." + c.slot;
    throw RemoteCallError((language_.empty() ? std::string("the implementation") : language_) + " function '" + who +
                          "' (" + c.scalar + ") raised an error:\n" + r[0].error);
  }
  return std::move(r[0].result);
}

// ---- the handshake ------------------------------------------------------------------------------

RemoteDescription parse_hello(const json& h) {
  auto bad = [](const std::string& why) { return RemoteError("handshake: " + why); };
  if (!h.is_object()) throw bad("not a JSON object");
  if (h.contains("fatal"))
    throw RemoteError("the implementation could not start: " +
                      (h["fatal"].is_string() ? h["fatal"].get<std::string>() : h["fatal"].dump()));
  if (h.value("protocol", "") != kProtocolName)
    throw bad(std::string("\"protocol\" must be \"") + kProtocolName + "\"");
  if (!h.contains("version") || !h["version"].is_number_integer() || h["version"].get<int>() != kProtocolVersion)
    throw bad("this harness speaks version " + std::to_string(kProtocolVersion) + "; the implementation speaks " +
              (h.contains("version") ? h["version"].dump() : std::string("none")));
  RemoteDescription d;
  d.language = h.value("language", "unknown");
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
    for (const auto& i : h["integrators"]) {
      RemoteDescription::Integrator x;
      x.name = i.at("name").get<std::string>();
      for (const auto& s : i.value("steps", json::array())) x.steps.push_back(s.get<std::string>());
      for (const auto& s : i.value("scalars", json::array({"double"}))) x.scalars.push_back(s.get<std::string>());
      if (i.contains("claims") && i["claims"].is_object()) {
        const json& c = i["claims"];
        x.has_claims = true;
        x.claims.integrator = x.name;
        x.claims.order = c.value("order", 0);
        x.claims.symmetric = c.value("symmetric", false);
        x.claims.casimir = c.value("casimir", false);
        x.claims.energy = c.value("energy", false);
        x.claims.orthogonality = c.value("orthogonality", false);
        x.claims.spectrum = c.value("spectrum", false);
        x.claims.poisson = c.value("poisson", false);
        x.claims.noether = c.value("noether", false);
        x.claims.equivariant = c.value("equivariant", false);
        x.claims.bounded_energy = c.value("bounded_energy", false);
        static const std::set<std::string> known{"order",         "symmetric", "casimir", "energy",
                                                 "orthogonality", "spectrum",  "poisson", "noether",
                                                 "equivariant",   "bounded_energy"};
        for (const auto& [k, v] : c.items())
          if (!known.count(k)) d.warnings.push_back("integrator '" + x.name + "' claims '" + k + "', which is not a claim the harness knows (ignored)");
      }
      d.integrators.push_back(std::move(x));
    }
  if (h.contains("notes"))
    for (const auto& [scalar, slots] : h["notes"].items())
      for (const auto& [slot, why] : slots.items()) d.notes[scalar][slot] = why.is_string() ? why.get<std::string>() : why.dump();
  if (h.contains("warnings"))
    for (const auto& w : h["warnings"]) d.warnings.push_back(w.is_string() ? w.get<std::string>() : w.dump());
  if (h.contains("unchecked"))
    for (const auto& w : h["unchecked"]) d.unchecked.push_back(w.is_string() ? w.get<std::string>() : w.dump());
  if (h.contains("scalar_unavailable") && h["scalar_unavailable"].is_object())
    for (const auto& [scalar, why] : h["scalar_unavailable"].items())
      d.scalar_unavailable[scalar] = why.is_string() ? why.get<std::string>() : why.dump();
  return d;
}

// ---- the subject ----------------------------------------------------------------------------------

namespace {

template <class T, class Sig>
struct RemoteSlot;

template <class T, class R, class... A>
struct RemoteSlot<T, R(A...)> {
  static std::function<R(A...)> make(std::shared_ptr<Connection> conn, const char* slot, std::string integrator = "") {
    return [conn, slot, integrator](A... a) -> R {
      Call c{slot, scalar_word<T>(), json::array({encode<T, std::decay_t<A>>(a)...}), integrator};
      const json result = conn->call(c);
      const std::string who = (integrator.empty() ? std::string() : integrator + ".") + slot;
      try {
        return decode<T, R>(result, "the result of " + conn->language() + " function '" + who + "' (" +
                                        scalar_word<T>() + ")");
      } catch (const ProtocolValueError& e) {
        throw ProtocolValueError(std::string(e.what()) + "; the reply was " + result.dump().substr(0, 300));
      }
    };
  }
};

template <class T>
std::shared_ptr<Subject<T>> make_part(const std::shared_ptr<Connection>& conn, const RemoteDescription& d) {
  const char* scalar = scalar_word<T>();
  auto it = d.slots.find(scalar);
  auto s = std::make_shared<Subject<T>>();
  bool any = false;
  if (it != d.slots.end()) {
    const auto& have = it->second;
#define GM_REMOTE_SLOT(name, sig, place, meaning)                   \
  if (have.count(#name)) {                                          \
    s->name = RemoteSlot<T, sig>::make(conn, #name);                \
    any = true;                                                     \
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
        if (step == "rigid_body_step")
          in.rigid_body_step =
              RemoteSlot<T, RigidBodyState<T>(const Vec3<T>&, const RigidBodyState<T>&, const T&)>::make(conn, "rigid_body_step", i.name);
        else if (step == "manakov_step")
          in.manakov_step =
              RemoteSlot<T, ManakovState<T>(const MatX<T>&, const ManakovState<T>&, const T&)>::make(conn, "manakov_step", i.name);
      }
      s->integrators.push_back(std::move(in));
      any = true;
    }
  }
  return any ? s : nullptr;
}

}  // namespace

SubjectSet remote_subject(const std::shared_ptr<Connection>& conn, const std::string& name, harness::SubjectInfo& info) {
  const RemoteDescription d = parse_hello(conn->hello());
  conn->stop();  // each process that calls a slot starts its own copy
  SubjectSet s;
  s.name = name;
  s.description = d.description.empty() ? "a " + d.language + " implementation" : d.description;
  s.d = make_part<double>(conn, d);
  s.mp = make_part<Real50>(conn, d);
  s.q = make_part<Rational>(conn, d);
  for (const auto& i : d.integrators)
    if (i.has_claims) s.claims.push_back(i.claims);
  for (const auto& [scalar, slots] : d.notes)
    for (const auto& [slot, why] : slots) info.slot_notes[scalar][slot] = why;
  for (const auto& w : d.warnings) info.warnings.push_back(w);
  for (const auto& u : d.unchecked) info.unchecked.push_back(u);
  for (const auto& [scalar, why] : d.scalar_unavailable) info.scalar_unavailable[scalar] = why;
  for (const char* scalar : {"double", "mp50", "exact"}) {
    const bool have = (std::string(scalar) == "double" ? s.d != nullptr
                       : std::string(scalar) == "mp50" ? s.mp != nullptr
                                                       : s.q != nullptr);
    if (!have && !info.scalar_unavailable.count(scalar))
      info.scalar_unavailable[scalar] = d.language + " implementation provides nothing in " + scalar +
                                        (d.language == "octave" ? " (Octave code is checked in double only)" : "");
  }
  return s;
}

std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why) {
  const fs::path p(file);
  const std::string src = GM_SOURCE_DIR;
  std::error_code ec;
  if (p.extension() == ".py") {
    if (language) *language = "python";
    const char* py = std::getenv("GEOMECH_PYTHON");
    // Debian's interpreter, where python3-mpmath and python3-numpy are installed (not whatever
    // python3 comes first on PATH); $GEOMECH_PYTHON overrides.
    const std::string deflt = fs::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
    return {py && *py ? py : deflt, "-u", src + "/student/python/geomech_server.py", file};
  }
  if (p.extension() == ".m" || (fs::is_directory(p, ec) && !fs::is_empty(p, ec))) {
    if (language) *language = "octave";
    const char* oc = std::getenv("GEOMECH_OCTAVE");
    return {oc && *oc ? oc : "octave-cli", "--no-gui", "--quiet", "--no-init-file", "--no-history",
            src + "/student/octave/geomech_server.m", file};
  }
  if (why) *why = "not a .py or .m file (nor a folder of .m files)";
  return {};
}

}  // namespace gm::protocol
