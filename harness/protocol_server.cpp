#include "harness/protocol_server.hpp"

#include "harness/protocol_codec.hpp"
#include "harness/remote_subject.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <unistd.h>
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
  static json invoke(const std::function<R(A...)>& f, const json& args, const std::string& who, std::index_sequence<k...>) {
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
        if (slot == "rigid_body_step" && in.rigid_body_step)
          return ServedSlot<T, RigidBodyState<T>(const Vec3<T>&, const RigidBodyState<T>&, const T&)>::call(
              in.rigid_body_step, args, who);
        if (slot == "manakov_step" && in.manakov_step)
          return ServedSlot<T, ManakovState<T>(const MatX<T>&, const ManakovState<T>&, const T&)>::call(in.manakov_step,
                                                                                                         args, who);
        throw std::runtime_error("integrator '" + name + "' has no " + slot + " in " + scalar_word<T>());
      }
      throw std::runtime_error("no integrator is named '" + name + "'");
    }
  }
#define GM_SERVE_SLOT(name, sig, place, meaning)                                              \
  if (slot == #name) {                                                                        \
    if (!s->name) throw std::runtime_error(std::string(#name " is not provided in ") + scalar_word<T>()); \
    return ServedSlot<T, sig>::call(s->name, args, #name);                                    \
  }
  GM_SUBJECT_SLOTS(GM_SERVE_SLOT)
#undef GM_SERVE_SLOT
  throw std::runtime_error("'" + slot + "' is not a slot");
}

json claims_json(const IntegratorClaims& c) {
  return json{{"order", c.order},         {"symmetric", c.symmetric},     {"casimir", c.casimir},
              {"energy", c.energy},       {"orthogonality", c.orthogonality}, {"spectrum", c.spectrum},
              {"poisson", c.poisson},     {"noether", c.noether},         {"equivariant", c.equivariant},
              {"bounded_energy", c.bounded_energy}};
}

bool write_all(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

json hello_for(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language) {
  json h{{"protocol", kProtocolName}, {"version", kProtocolVersion}, {"language", language}, {"description", s.description}};
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
        auto it = std::find_if(integrators.begin(), integrators.end(), [&](const json& j) { return j["name"] == in.name; });
        if (it == integrators.end()) {
          json steps = json::array();
          if (in.rigid_body_step) steps.push_back("rigid_body_step");
          if (in.manakov_step) steps.push_back("manakov_step");
          json j{{"name", in.name}, {"steps", steps}, {"scalars", json::array()}};
          for (const auto& c : s.claims)
            if (c.integrator == in.name) j["claims"] = claims_json(c);
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
      json v;
      if (scalar == "double")
        v = call_in<double>(s.d.get(), c);
      else if (scalar == "mp50")
        v = call_in<Real50>(s.mp.get(), c);
      else if (scalar == "exact")
        v = call_in<Rational>(s.q.get(), c);
      else
        throw std::runtime_error("unknown scalar '" + scalar + "'");
      results.push_back(json{{"ok", std::move(v)}});
    } catch (const std::exception& e) {
      results.push_back(json{{"error", e.what()}, {"traceback", ""}});
    }
  }
  return json{{"id", request.value("id", json())}, {"results", results}};
}

int serve(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language, int in, int out) {
  if (!write_all(out, hello_for(s, info, language).dump() + "\n")) return 2;
  std::string buffer;
  char buf[65536];
  for (;;) {
    std::size_t nl;
    while ((nl = buffer.find('\n')) != std::string::npos) {
      const std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      json reply;
      try {
        reply = answer(s, json::parse(line));
      } catch (const std::exception& e) {
        write_all(out, json{{"fatal", std::string("not a request: ") + e.what()}}.dump() + "\n");
        return 2;
      }
      if (!write_all(out, reply.dump() + "\n")) return 2;
    }
    const ssize_t n = ::read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return 0;
    buffer.append(buf, static_cast<std::size_t>(n));
  }
}

}  // namespace gm::protocol
