#include "harness/remote/protocol_server.hpp"

#include "harness/remote/protocol_codec.hpp"
#include "harness/remote/remote_subject.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

namespace gm::protocol {

namespace {

// One slot: decode the arguments by the slot's signature, call, encode the result.
template <class T, class Sig>
struct ServedSlot;

template <class T, class R, class... A>
struct ServedSlot<T, R(A...)> {
  static json call(const std::function<R(A...)>& f, const json& args, const std::string& who) {
    if (!args.is_array() || args.size() != sizeof...(A))
      throw ProtocolValueError(who + ": expected " + std::to_string(sizeof...(A)) + " arguments, got " +
                               (args.is_array() ? std::to_string(args.size()) : std::string("no array")));
    return invoke(f, args, who, std::index_sequence_for<A...>{});
  }
  template <std::size_t... k>
  static json invoke(const std::function<R(A...)>& f, const json& args, const std::string& who,
                     std::index_sequence<k...>) {
    return encode<T>(f(decode<T, std::decay_t<A>>(args[k], who + " argument " + std::to_string(k + 1))...));
  }
};

template <class T>
json call_in(const Subject<T>* s, const json& c) {
  const std::string slot = c.value("slot", "");
  const json args = c.value("args", json::array());
  if (!s) throw std::runtime_error(std::string("nothing is provided in ") + scalar_word<T>());
  if (c.contains("integrator")) {
    if constexpr (is_exact_v<T>) {
      throw std::runtime_error("integrators are not run in exact rationals");
    } else {
      const std::string name = c["integrator"].is_string() ? c["integrator"].get<std::string>() : "";
      for (const auto& in : s->integrators) {
        if (in.name != name) continue;
        const std::string who = name + "." + slot;
        if (slot == "rigid_body_step" && in.declared_step) {  // kept in a declared form: served in it
          if (!args.is_array() || args.size() != 3) throw ProtocolValueError(who + ": expected 3 arguments");
          return encode<T>(in.declared_step(decode<T, Vec3<T>>(args[0], who + " argument 1"),
                                            decode_engine_state<T>(args[1], in.form, who + " argument 2"),
                                            decode<T, T>(args[2], who + " argument 3")));
        }
        if (slot == "rigid_body_step" && in.rigid_body_step)
          return ServedSlot<T, RigidBodyState<T>(const Vec3<T>&, const RigidBodyState<T>&, const T&)>::call(
              in.rigid_body_step, args, who);
        if (slot == "manakov_step" && in.manakov_step)
          return ServedSlot<T, ManakovState<T>(const MatX<T>&, const ManakovState<T>&, const T&)>::call(in.manakov_step,
                                                                                                        args, who);
        if (slot == "clebsch_step" && in.clebsch_step)
          return ServedSlot<T, Vec3Pair<T>(const Vec3<T>&, const Vec3Pair<T>&, const T&)>::call(in.clebsch_step, args,
                                                                                                who);
        if (slot == "manakov_clebsch_step" && in.manakov_clebsch_step)
          return ServedSlot<T, MatXPair<T>(const MatX<T>&, const MatXPair<T>&, const T&)>::call(in.manakov_clebsch_step,
                                                                                                args, who);
        throw std::runtime_error("integrator '" + name + "' has no " + slot + " in " + scalar_word<T>());
      }
      throw std::runtime_error("no integrator is named '" + name + "'");
    }
  }
#define GM_SERVE_SLOT(name, sig, place, meaning)                                                          \
  if (slot == #name) {                                                                                    \
    if (!s->name) throw std::runtime_error(std::string(#name " is not provided in ") + scalar_word<T>()); \
    return ServedSlot<T, sig>::call(s->name, args, #name);                                                \
  }
  GM_SUBJECT_SLOTS(GM_SERVE_SLOT)
#undef GM_SERVE_SLOT
  throw std::runtime_error("'" + slot + "' is not a slot");
}

json claims_json(const IntegratorClaims& c) {
  json j{{"order", c.order}};
  for (const auto& b : kBooleanClaims) j[b.name] = c.*b.member;
  return j;
}

json domain_json(const StepDomain& d) {
  json j = json::object();
  if (d.max_omega > 0) j["max_omega"] = d.max_omega;
  if (d.max_pi > 0) j["max_pi"] = d.max_pi;
  if (d.min_h > 0) j["min_h"] = d.min_h;
  return j;
}

}  // namespace

json hello_for(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language) {
  json h{{"protocol", kProtocolName},
         {"version", kProtocolVersion},
         {"language", language},
         {"description", s.description}};
  json slots = json::object();
  json integrators = json::array();
  auto describe = [&](const auto* sub, const char* scalar) {
    if (!sub) return;
    json names = json::array();
    for (const auto& slot : subject_slots())
      if (sub->provides(slot.name)) names.push_back(slot.name);
    slots[scalar] = names;
    using T = typename std::remove_pointer_t<decltype(sub)>::Scalar;
    if constexpr (!is_exact_v<T>)
      for (const auto& in : sub->integrators) {
        auto it =
            std::find_if(integrators.begin(), integrators.end(), [&](const json& j) { return j["name"] == in.name; });
        if (it == integrators.end()) {
          json steps = json::array();
          if (in.rigid_body_step) steps.push_back("rigid_body_step");
          if (in.manakov_step) steps.push_back("manakov_step");
          if (in.clebsch_step) steps.push_back("clebsch_step");
          if (in.manakov_clebsch_step) steps.push_back("manakov_clebsch_step");
          json j{{"name", in.name}, {"steps", steps}, {"scalars", json::array()}};
          if (!in.form.is_notes()) j["state"] = state_form_words(in.form);
          for (const auto& c : s.claims)
            if (c.integrator == in.name) {
              j["claims"] = claims_json(c);
              if (!c.precision.empty()) j["precision"] = c.precision;
              if (!c.precision_reason.empty()) j["precision_reason"] = c.precision_reason;
              if (c.domain.declared()) j["domain"] = domain_json(c.domain);
            }
          integrators.push_back(j);
          it = integrators.end() - 1;
        }
        (*it)["scalars"].push_back(scalar);
      }
  };
  describe(s.d.get(), "double");
  describe(s.mp.get(), "mp50");
  describe(s.q.get(), "exact");
  h["slots"] = slots;
  h["integrators"] = integrators;
  h["repeat"] = true;
  json notes = json::object();
  for (const auto& [scalar, m] : info.slot_notes)
    for (const auto& [slot, why] : m) notes[scalar][slot] = why;
  h["notes"] = notes;
  json unavailable = json::object();
  for (const auto& [scalar, why] : info.scalar_unavailable) unavailable[scalar] = why;
  h["scalar_unavailable"] = unavailable;
  h["warnings"] = info.warnings;
  h["unchecked"] = info.unchecked;
  return h;
}

json answer(const SubjectSet& s, const json& request) {
  json results = json::array();
  for (const auto& c : request.at("calls")) {
    const std::string scalar = c.value("scalar", "");
    try {
      auto one = [&](const json& call) {
        if (scalar == "double") return call_in<double>(s.d.get(), call);
        if (scalar == "mp50") return call_in<Real50>(s.mp.get(), call);
        if (scalar == "exact") return call_in<Rational>(s.q.get(), call);
        throw std::runtime_error("unknown scalar '" + scalar + "'");
      };
      json v;
      if (c.contains("repeat")) {
        // A run of steps (docs/PROTOCOL.md): each step's state, encoded as its reply, is the next
        // step's argument, as if the harness had made the calls one by one.
        const int n = c["repeat"].is_number_integer() ? c["repeat"].get<int>() : 0;
        if (!c.contains("integrator") || n < 1 || !c.contains("args") || !c["args"].is_array() || c["args"].size() != 3)
          throw std::runtime_error(
              "\"repeat\" needs an integrator's step, its three arguments and a count of at least 1");
        json call = c;
        v = json::array();
        for (int k = 0; k < n; ++k) {
          json x = one(call);
          call["args"][1] = x;
          v.push_back(std::move(x));
        }
      } else {
        v = one(c);
      }
      results.push_back(json{{"ok", std::move(v)}});
    } catch (const std::exception& e) {
      results.push_back(json{{"error", e.what()}, {"traceback", ""}});
    }
  }
  return json{{"id", request.value("id", json())}, {"results", results}};
}

namespace {

// Request lines from a descriptor (raw reads, no stdio buffer: a session's copy made by fork takes
// over the same input, and the server resumes after it without losing a byte).
class LineReader {
 public:
  explicit LineReader(int fd) : fd_(fd) {}
  // The next line without its newline; false at the end of input.
  bool next(std::string& line) {
    for (;;) {
      const auto nl = buffer_.find('\n');
      if (nl != std::string::npos) {
        line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return true;
      }
      char buf[65536];
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      buffer_.append(buf, static_cast<std::size_t>(n));
    }
  }

 private:
  int fd_;
  std::string buffer_;
};

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) return std::string("was killed by signal ") + strsignal(WTERMSIG(status));
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "ended";
}

// Answers requests until the input ends (returns 0) or, in a session, until {"session": "end"}
// (returns 1 after replying); 2 after a line that is not a request (a fatal reply is written).
int serve_requests(const SubjectSet& s, LineReader& in, int out, bool in_session) {
  std::string line;
  while (in.next(line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // the empty line after each request
    json req;
    try {
      req = json::parse(line);
      if (!req.is_object()) throw std::runtime_error("not an object");
    } catch (const std::exception& e) {
      write_all(out, json{{"fatal", std::string("not a request: ") + e.what()}}.dump() + "\n");
      return 2;
    }
    const json id = req.value("id", json());
    if (req.contains("session")) {
      const std::string what = req["session"].is_string() ? req["session"].get<std::string>() : "";
      if (what == "end" && in_session) {
        write_all(out, json{{"id", id}, {"session", "ended"}}.dump() + "\n");
        return 1;
      }
      if (what != "begin" || in_session) {
        write_all(out, json{{"id", id}, {"fatal", "unexpected session request '" + what + "'"}}.dump() + "\n");
        return 2;
      }
      // A session: a copy of this process answers the check's calls, so that the check sees the
      // implementation as the handshake left it and leaves nothing behind.
      int done[2];
      if (::pipe(done) != 0) {
        write_all(
            out,
            json{{"id", id}, {"fatal", std::string("cannot create a pipe: ") + std::strerror(errno)}}.dump() + "\n");
        return 2;
      }
      const pid_t pid = ::fork();
      if (pid == 0) {
        ::close(done[0]);
        write_all(out, json{{"id", id}, {"session", "begun"}, {"pid", ::getpid()}}.dump() + "\n");
        const int r = serve_requests(s, in, out, true);
        if (r == 1) (void)!::write(done[1], "E", 1);
        ::_exit(r == 2 ? 2 : 0);
      }
      ::close(done[1]);
      int status = 0;
      bool ended = false;
      if (pid > 0) {
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        // Ended only if the copy said so with its 'E' and then exited normally: code under test
        // that writes into every descriptor it finds (examples/hostile/forged_verdict.cpp) reaches
        // this pipe too, and must not pass for a session that ended.
        char c = 0;
        ended = ::read(done[0], &c, 1) == 1 && c == 'E' && WIFEXITED(status) && WEXITSTATUS(status) == 0;
      }
      ::close(done[0]);
      if (pid < 0)
        write_all(out, json{{"id", id}, {"fatal", std::string("cannot fork: ") + std::strerror(errno)}}.dump() + "\n");
      else if (!ended)  // it died during the session: the harness is waiting for a reply
        write_all(out, json{{"id", nullptr}, {"died", how_it_ended(status)}}.dump() + "\n");
      continue;
    }
    if (!write_all(out, answer(s, req).dump() + "\n")) return 2;
  }
  return 0;
}

}  // namespace

int serve(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language, int in, int out) {
  json h = hello_for(s, info, language);
  h["sessions"] = true;
  if (!write_all(out, h.dump() + "\n")) return 2;
  LineReader reader(in);
  const int r = serve_requests(s, reader, out, false);
  return r == 2 ? 2 : 0;
}

}  // namespace gm::protocol
