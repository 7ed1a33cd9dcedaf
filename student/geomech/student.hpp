// geomech/student.hpp: plug your own implementation into the geomech property suite.
//
// Write a struct whose static member functions are named after the slots of `geomech slots`,
// preferably as templates on the scalar T, then register it with one macro:
//
//   #include <geomech/student.hpp>
//   using namespace gm;   // Vec3<T>, Mat3<T>, MatX<T>, RigidBodyState<T>, ...
//
//   struct MyRigidBody {
//     template <class T> static Mat3<T> hat(const Vec3<T>& v) { ... }
//     template <class T> static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) { ... }
//   };
//
//   struct Midpoint {                                       // an integrator (optional)
//     static constexpr const char* name = "midpoint";
//     static constexpr gm::student::Claims claims{.order = 2, .symmetric = true, .casimir = true};
//     template <class T>
//     static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) { ... }
//   };
//
//   GEOMECH_STUDENT(MyRigidBody, Midpoint);                 // the implementation, then its integrators
//
// and run `./geomech check my_rigid_body.cpp`. Only the functions you write are checked; every
// other check is reported NOT PROVIDED, with the reason.
//
// Rules of detection (C++20 requires-expressions; nothing you omit is an error):
// - A slot is filled when `Impl::template name<T>(args...)` (or, in double only, a plain
//   `Impl::name(args...)`) can be called with the slot's arguments and its result converts to the
//   slot's result type. Declare the result type; `auto` would make the compiler instantiate the
//   body just to detect the slot.
// - A function template is checked in double, in 50-digit floats (Real50) and, for the algebraic
//   slots, in exact rationals (Rational). A function written for double only is checked in double
//   and the report lists what that misses. In templates call sqrt, sin, cos, abs unqualified
//   (`using std::sqrt; sqrt(x)`) so the 50-digit overloads are found.
// - If a template does not compile for a scalar, `geomech check` drops just that slot in just that
//   scalar and says so. In your own build you can opt out: `static constexpr const char* skip_exact
//   = "all";` (or a list of slot names, "hamiltonian_3_4 clebsch_3_21"); `skip_mp50` likewise.
// - Integrators need `name`; `claims` is optional (nothing claimed), and so is `domain` (where the
//   step is meant to work: gm::student::Domain); `rigid_body_step`,
//   `manakov_step`, `clebsch_step` and `manakov_clebsch_step` are detected like slots. Integrators are
//   never run in rationals.
// - A rigid-body step may keep the state as an engine does (core/state_form.hpp): declare
//   `static constexpr const char* state = "quaternion_wxyz omega";` (attitude: matrix,
//   quaternion_wxyz, quaternion_xyzw; angular: Pi, Omega, omega, pi) and write
//   `EngineState<T> rigid_body_step(const Vec3<T>& I, const EngineState<T>& x, const T& h)`, reading
//   and returning the declared members (x.q, x.omega); the suite converts, with I.
// - A step that computes in one precision whatever it is given says so, with its reason:
//   `static constexpr const char* precision = "float";` (or "single", or "double") and
//   `precision_reason = "...";` (shown in the report; the step is then run in double only, and every
//   tolerance, plateau and trend budget of its checks uses that precision's eps: float's 1.19e-7).
// - Write no main(), or guard yours with `#ifndef GEOMECH_STUDENT_CHECK`.
#pragma once

#include "core/declared_step.hpp"
#include "core/subject.hpp"

#include <concepts>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace gm::student {

// What an integrator claims about itself; the harness verifies each claim.
struct Claims {
  int order = 0;                 // order of accuracy (0: no claim)
  bool symmetric = false;        // step(h) followed by step(-h) is the identity
  bool casimir = false;          // |Pi|^2 (rigid body) is preserved to round-off
  bool energy = false;           // the energy is preserved to round-off
  bool orthogonality = false;    // O stays orthogonal to round-off
  bool spectrum = false;         // Manakov: the eigenvalues of M are preserved to round-off
  bool poisson = false;          // the step is a Poisson map of the Lie-Poisson bracket
  bool noether = false;          // the spatial momentum O Pi (Manakov: O M O^T) is kept to round-off
  bool equivariant = false;      // step(Pi, R O) = (Pi', R O'): commutes with rotating the attitude
  bool bounded_energy = false;   // over long runs the energy error stays bounded (no secular drift)
  bool symplectic = false;       // canonical steps (clebsch_step, manakov_clebsch_step) preserve dQ ^ dP
  bool unit_quaternion = false;  // an attitude kept as a quaternion (`state`): |q| = 1 is kept to round-off
};

// Where an integrator's step is meant to work (optional), as
//   static constexpr gm::student::Domain domain{.max_omega = 1e6};
// No check draws a state or step outside it, and the report states it; 0: no limit.
struct Domain {
  double max_omega = 0;  // the largest |Omega| = max |Pi_i / I_i|
  double max_pi = 0;     // the largest max |Pi_i| (Manakov: max |M_ij|)
  double min_h = 0;      // the smallest |h|
};

// What one translation unit registered for one scalar (filled by GEOMECH_STUDENT).
struct PartInfo {
  std::string registration;                       // the macro's arguments, as written
  std::string description;                        // Impl::description, if given
  std::map<std::string, std::string> slot_notes;  // slot -> why it is not filled
  std::vector<IntegratorClaims> claims;
  std::vector<std::string> warnings;
  std::vector<std::string> unchecked;  // written, but cannot be called as its slot expects
  // A piece of the scalar's compile (`geomech check` compiles the double one in pieces, see
  // WholeFile): slot_pieces 1 is the whole; the program's pieces are merged into one subject.
  int slot_piece = 0;
  int slot_pieces = 1;
};

void register_part(std::shared_ptr<const Subject<double>> s, PartInfo info);
void register_part(std::shared_ptr<const Subject<Real50>> s, PartInfo info);
void register_part(std::shared_ptr<const Subject<Rational>> s, PartInfo info);

namespace detail {

template <class... Ts>
struct type_list {};

template <class Sig>
struct signature_of;
template <class R, class... A>
struct signature_of<R(A...)> {
  using result = R;
  using args = type_list<A...>;
};

// Whether `name` is a word of the space- or comma-separated `list` ("all" matches everything).
constexpr bool listed(std::string_view list, std::string_view name) {
  std::size_t i = 0;
  while (i < list.size()) {
    while (i < list.size() && (list[i] == ' ' || list[i] == ',')) ++i;
    std::size_t j = i;
    while (j < list.size() && list[j] != ' ' && list[j] != ',') ++j;
    const std::string_view word = list.substr(i, j - i);
    if (!word.empty() && (word == name || word == "all")) return true;
    i = j;
  }
  return false;
}

// One tag per slot, generated from GM_SUBJECT_SLOTS: how to call the student's function of that
// name, and where the slot lives in Subject<T>. Compiler errors inside a student's function name
// the tag (gm::student::detail::slot_<name>), which is how `geomech check` tells which slot did
// not compile for a scalar.
#define GM_STUDENT_SLOT_TAG(name, sig, place, meaning)                                               \
  struct slot_##name {                                                                               \
    static constexpr std::string_view id = #name;                                                    \
    static constexpr std::string_view signature_text = #sig;                                         \
    template <class T>                                                                               \
    using signature = sig;                                                                           \
    template <class Impl, class T, class... A>                                                       \
    static auto call_template(A&&... a) -> decltype(Impl::template name<T>(std::forward<A>(a)...)) { \
      return Impl::template name<T>(std::forward<A>(a)...);                                          \
    }                                                                                                \
    template <class Impl, class... A>                                                                \
    static auto call_plain(A&&... a) -> decltype(Impl::name(std::forward<A>(a)...)) {                \
      return Impl::name(std::forward<A>(a)...);                                                      \
    }                                                                                                \
    template <class Impl, class T>                                                                   \
    static constexpr bool named_template = requires {                                                \
      &Impl::template name<T>;                                                                       \
    };                                                                                               \
    template <class Impl>                                                                            \
    static constexpr bool named = requires {                                                         \
      &Impl::name;                                                                                   \
    };                                                                                               \
    template <class T>                                                                               \
    static auto& member(Subject<T>& s) {                                                             \
      return s.name;                                                                                 \
    }                                                                                                \
  };
GM_SUBJECT_SLOTS(GM_STUDENT_SLOT_TAG)
#undef GM_STUDENT_SLOT_TAG

template <class T>
constexpr const char* scalar_word() {
  if constexpr (std::is_same_v<T, double>)
    return "double";
  else if constexpr (std::is_same_v<T, Real50>)
    return "mp50";
  else
    return "exact";
}

// Slots the student (skip_exact / skip_mp50) or the build (GEOMECH_SKIP_SLOTS, set by
// `geomech check` when a slot does not compile for this scalar) asked to leave out.
template <class Impl, class T>
constexpr const char* skipped_by_student(std::string_view slot) {
  if constexpr (std::is_same_v<T, Rational>) {
    if constexpr (requires { std::string_view(Impl::skip_exact); })
      if (listed(Impl::skip_exact, slot)) return "left out by the implementation (skip_exact)";
  } else if constexpr (std::is_same_v<T, Real50>) {
    if constexpr (requires { std::string_view(Impl::skip_mp50); })
      if (listed(Impl::skip_mp50, slot)) return "left out by the implementation (skip_mp50)";
  }
  return nullptr;
}

// What one compile of the file registers. A student's own build registers all of it (WholeFile);
// `geomech check` compiles it in pieces, each described by the macros that
// geomech/detail/scalar_selection.hpp reads (after this header, which may come precompiled: GCC
// rejects a precompiled header when a macro it tested changed, so this header tests none of them).
struct WholeFile {
  static constexpr int scalar = -1;      // -1: all three; else 0 double, 1 mp50, 2 exact
  static constexpr int slot_pieces = 1;  // 1: every slot; 0: none; 2: one of two pieces (slot_piece_of)
  static constexpr int slot_piece = 0;
  static constexpr bool integrators = true;
  static constexpr std::string_view skip_slots = "";  // left out: they do not compile for this scalar
};

// The two pieces of the slots, split where the cost of compiling them splits: the Manakov slots of
// SO(n) (piece 1), whose dynamic-size matrix code costs as much to compile as all the others
// together (piece 0). docs/PERFORMANCE.md has the measurement.
constexpr int slot_piece_of(std::string_view slot) { return slot.substr(0, 8) == "manakov_" ? 1 : 0; }

template <class Sel>
constexpr bool in_this_piece(std::string_view slot) {
  if constexpr (Sel::slot_pieces == 2)
    return slot_piece_of(slot) == Sel::slot_piece;
  else
    return Sel::slot_pieces == 1;
}

// The build asked to leave the slot out (`geomech check`, when it does not compile for this scalar).
template <class Sel>
constexpr bool skipped_by_build(std::string_view slot) {
  return listed(Sel::skip_slots, slot);
}

template <class Slot, class Impl, class T, class Sel, class R, class... A>
void fill_slot(Subject<T>& s, PartInfo& info, type_list<A...>) {
  if constexpr (skipped_by_student<Impl, T>(Slot::id) != nullptr) {
    info.slot_notes[std::string(Slot::id)] = skipped_by_student<Impl, T>(Slot::id);
  } else if constexpr (skipped_by_build<Sel>(Slot::id)) {
    info.slot_notes[std::string(Slot::id)] =
        std::string("does not compile for ") + scalar_word<T>() + " (see the compiler's message in the report)";
  } else if constexpr (requires(A... a) {
                         { Slot::template call_template<Impl, T>(a...) } -> std::convertible_to<R>;
                       }) {
    Slot::member(s) = [](A... a) -> R { return Slot::template call_template<Impl, T>(a...); };
  } else if constexpr (std::is_same_v<T, double> && requires(A... a) {
                         { Slot::template call_plain<Impl>(a...) } -> std::convertible_to<R>;
                       }) {
    Slot::member(s) = [](A... a) -> R { return Slot::template call_plain<Impl>(a...); };
  } else if constexpr (Slot::template named_template<Impl, T> ||
                       (std::is_same_v<T, double> && Slot::template named<Impl>)) {
    info.slot_notes[std::string(Slot::id)] =
        "a function named '" + std::string(Slot::id) + "' exists, but it cannot be called as " +
        std::string(Slot::signature_text) + " (check its parameters and result type against `geomech slots`)";
  }
}

template <class Slot, class Impl, class T, class Sel>
void fill(Subject<T>& s, PartInfo& info) {
  if constexpr (in_this_piece<Sel>(Slot::id)) {
    using Sig = signature_of<typename Slot::template signature<T>>;
    fill_slot<Slot, Impl, T, Sel, typename Sig::result>(s, info, typename Sig::args{});
  }
}

template <class Impl, class T, class Sel = WholeFile>
void fill_all(Subject<T>& s, PartInfo& info) {
#define GM_STUDENT_FILL(name, sig, place, meaning) fill<slot_##name, Impl, T, Sel>(s, info);
  GM_SUBJECT_SLOTS(GM_STUDENT_FILL)
#undef GM_STUDENT_FILL
}

template <class Int>
constexpr bool has_name = requires {
  {std::string_view(Int::name)};
};

// "computes in double (stated: the engine is built in double)".
template <class Int>
std::string stated_precision_note() {
  std::string why;
  if constexpr (requires { std::string_view(Int::precision_reason); }) why = Int::precision_reason;
  return "computes in " + std::string(Int::precision) +
         (why.empty() ? std::string(" (stated, without a reason)") : " (stated: " + why + ")");
}

// Whether the integrator states a precision the suite knows, "double", "float" or "single", where the
// compiler can read it (a constexpr member, as the docs write it): then its steps compute in that
// precision whatever they are given, and are compiled and run in double only (a float step driven
// in 50 digits computes in float all the same).
constexpr bool is_known_precision(std::string_view p) { return p == "double" || p == "float" || p == "single"; }
template <class Int>
constexpr bool states_known_precision() {
  if constexpr (requires { typename std::bool_constant<is_known_precision(std::string_view(Int::precision))>; })
    return is_known_precision(std::string_view(Int::precision));
  else
    return false;
}

// An integrator's steps in scalar T (errors inside them name gm_integrator_of).
template <class Int, class T>
void gm_integrator_of(Subject<T>& s, PartInfo& info) {
  static_assert(has_name<Int>,
                "geomech: every integrator type given to GEOMECH_STUDENT needs "
                "`static constexpr const char* name = \"...\";`");
  using RS = RigidBodyState<T>;
  using MS = ManakovState<T>;
  if constexpr (!std::is_same_v<T, double> && states_known_precision<Int>()) {
    // Stated "double": nothing of it is compiled for T (the compile of a file of engines in double
    // costs what one scalar costs); the steps it has as templates on T are noted with the reason.
    const std::pair<bool, const char*> steps[] = {
        {requires(const Vec3<T>& a, const RS& x, const T& h){Int::template rigid_body_step<T>(a, x, h);
  }
  || requires(const Vec3<T>& a, const EngineState<T>& x, const T& h) { Int::template rigid_body_step<T>(a, x, h); }
  , "rigid_body_step"
}
, {requires(const MatX<T>& a, const MS& x, const T& h){Int::template manakov_step<T>(a, x, h);
}  // namespace detail
, "manakov_step"
}  // namespace gm::student
, {requires(const Vec3<T>& a, const Vec3Pair<T>& x, const T& h){Int::template clebsch_step<T>(a, x, h);
}
, "clebsch_step"
}
, {
  requires(const MatX<T>& a, const MatXPair<T>& x, const T& h) { Int::template manakov_clebsch_step<T>(a, x, h); }
  , "manakov_clebsch_step"
}
}
;
for (const auto& [has, step] : steps)
  if (has) {
    std::string key = Int::name;  // appended, not `+`: GCC 12 warns wrongly (-Warray-bounds) on that
    key.append(".").append(step);
    info.slot_notes[key] = stated_precision_note<Int>();
  }
return;
}
Integrator<T> in;
in.name = std::string(Int::name);
// Each step is detected like a slot: a template on the scalar, or (double only) a plain function.
#define GM_INTEGRATOR_STEP(step, ArgT, StateT)                                                                     \
  if constexpr (requires(const ArgT& a, const StateT& x, const T& h) {                                             \
                  { Int::template step<T>(a, x, h) } -> std::convertible_to<StateT>;                               \
                })                                                                                                 \
    in.step = [](const ArgT& a, const StateT& x, const T& h) -> StateT { return Int::template step<T>(a, x, h); }; \
  else if constexpr (std::is_same_v<T, double> && requires(const ArgT& a, const StateT& x, const T& h) {           \
                       { Int::step(a, x, h) } -> std::convertible_to<StateT>;                                      \
                     })                                                                                            \
    in.step = [](const ArgT& a, const StateT& x, const T& h) -> StateT { return Int::step(a, x, h); };
GM_INTEGRATOR_STEP(rigid_body_step, Vec3<T>, RS)
// A step kept in a declared form (`state`): the suite converts (core/declared_step.hpp).
if constexpr (requires { std::string_view(Int::state); }) {
  using ES = EngineState<T>;
  StateForm form;
  std::string bad;
  try {
    form = parse_state_form(Int::state);
  } catch (const std::exception& e) {
    bad = e.what();
  }
  if (!bad.empty()) {
    if constexpr (std::is_same_v<T, double>)
      info.unchecked.push_back("integrator '" + std::string(Int::name) + "' declares state = \"" +
                               std::string(Int::state) + "\": " + bad);
  } else if (in.rigid_body_step && !form.is_notes()) {
    if constexpr (std::is_same_v<T, double>)
      info.unchecked.push_back("integrator '" + std::string(Int::name) + "' declares state = \"" +
                               std::string(Int::state) +
                               "\" but its rigid_body_step takes the notes' RigidBodyState; take and return "
                               "EngineState<T> (its members " +
                               attitude_key(form.attitude) + " and " + angular_key(form.angular) + ")");
    in.rigid_body_step = {};
  } else if (!in.rigid_body_step) {
    if constexpr (requires(const Vec3<T>& a, const ES& x, const T& h) {
                    { Int::template rigid_body_step<T>(a, x, h) } -> std::convertible_to<ES>;
                  })
      in.declared_step = [](const Vec3<T>& a, const ES& x, const T& h) -> ES {
        return Int::template rigid_body_step<T>(a, x, h);
      };
    else if constexpr (std::is_same_v<T, double> && requires(const Vec3<T>& a, const ES& x, const T& h) {
                         { Int::rigid_body_step(a, x, h) } -> std::convertible_to<ES>;
                       })
      in.declared_step = [](const Vec3<T>& a, const ES& x, const T& h) -> ES { return Int::rigid_body_step(a, x, h); };
    if (in.declared_step) {
      in.form = form;
      adapt_declared_step(in);
    }
  }
}
GM_INTEGRATOR_STEP(manakov_step, MatX<T>, MS)
GM_INTEGRATOR_STEP(clebsch_step, Vec3<T>, Vec3Pair<T>)
GM_INTEGRATOR_STEP(manakov_clebsch_step, MatX<T>, MatXPair<T>)
#undef GM_INTEGRATOR_STEP
if constexpr (requires { std::string_view(Int::precision); }) {
  // A stated precision: "double", "float" or "single" runs the steps in double only, and the report
  // says why; any other is named as not a precision.
  if constexpr (std::is_same_v<T, double>)
    if (!is_known_precision(std::string_view(Int::precision)))
      info.unchecked.push_back("integrator '" + std::string(Int::name) + "' states precision = \"" +
                               std::string(Int::precision) +
                               "\", which is not a precision the suite knows: state \"float\" (or \"single\") or "
                               "\"double\"; its steps are judged at the scalar's own precision");
  if constexpr (!std::is_same_v<T, double>)
    if (is_known_precision(std::string_view(Int::precision))) {
      const std::pair<bool, const char*> steps[] = {
          {static_cast<bool>(in.rigid_body_step), "rigid_body_step"},
          {static_cast<bool>(in.manakov_step), "manakov_step"},
          {static_cast<bool>(in.clebsch_step), "clebsch_step"},
          {static_cast<bool>(in.manakov_clebsch_step), "manakov_clebsch_step"}};
      for (const auto& [has, step] : steps)
        if (has) info.slot_notes[std::string(Int::name) + "." + step] = stated_precision_note<Int>();
      return;
    }
}
if (in.rigid_body_step || in.manakov_step || in.clebsch_step || in.manakov_clebsch_step)
  s.integrators.push_back(std::move(in));
else if constexpr (std::is_same_v<T, double>)
  info.unchecked.push_back("integrator '" + std::string(Int::name) +
                           "' has none of rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h), "
                           "manakov_step(const MatX<T>& A, const ManakovState<T>& x, const T& h), "
                           "clebsch_step(const Vec3<T>& I, const Vec3Pair<T>& QP, const T& h) or "
                           "manakov_clebsch_step(const MatX<T>& A, const MatXPair<T>& QP, const T& h) with the "
                           "expected signature (see `geomech slots`; a step taking EngineState<T> declares its "
                           "`state`), so none of its claims can be checked");
}

template <class Int>
IntegratorClaims claims_of() {
  IntegratorClaims c;
  c.integrator = std::string(Int::name);
  if constexpr (requires { Int::claims; }) {
    const auto& k = Int::claims;
    c.order = k.order;
    // The same members by the same names (gm::student::Claims mirrors IntegratorClaims).
    c.symmetric = k.symmetric;
    c.casimir = k.casimir;
    c.energy = k.energy;
    c.orthogonality = k.orthogonality;
    c.spectrum = k.spectrum;
    c.poisson = k.poisson;
    c.noether = k.noether;
    c.equivariant = k.equivariant;
    c.bounded_energy = k.bounded_energy;
    c.symplectic = k.symplectic;
    c.unit_quaternion = k.unit_quaternion;
  }
  if constexpr (requires { std::string_view(Int::precision); }) c.precision = Int::precision;
  if constexpr (requires { std::string_view(Int::precision_reason); }) c.precision_reason = Int::precision_reason;
  if constexpr (requires { Int::domain; }) {
    c.domain.max_omega = Int::domain.max_omega;
    c.domain.max_pi = Int::domain.max_pi;
    c.domain.min_h = Int::domain.min_h;
  }
  return c;
}

template <class T, class Sel, class Impl, class... Ints>
void register_scalar(const char* registration) {
  auto s = std::make_shared<Subject<T>>();
  PartInfo info;
  info.registration = registration;
  info.slot_piece = Sel::slot_piece;
  info.slot_pieces = Sel::slot_pieces;
  if constexpr (requires { std::string_view(Impl::description); }) info.description = Impl::description;
  fill_all<Impl, T, Sel>(*s, info);
  if constexpr (!std::is_same_v<T, Rational> && Sel::integrators) (gm_integrator_of<Ints, T>(*s, info), ...);
  (info.claims.push_back(claims_of<Ints>()), ...);
  register_part(std::shared_ptr<const Subject<T>>(std::move(s)), std::move(info));
}

// The scalars a translation unit registers (Sel::scalar < 0: all three, else the one named).
template <class Sel, class Impl, class... Ints>
int register_all(const char* registration) {
  if constexpr (Sel::scalar < 0 || Sel::scalar == 0) register_scalar<double, Sel, Impl, Ints...>(registration);
  if constexpr (Sel::scalar < 0 || Sel::scalar == 1) register_scalar<Real50, Sel, Impl, Ints...>(registration);
  if constexpr (Sel::scalar < 0 || Sel::scalar == 2) register_scalar<Rational, Sel, Impl, Ints...>(registration);
  return 0;
}

}  // namespace detail
}  // namespace gm::student

// GEOMECH_STUDENT(Implementation, Integrator1, Integrator2, ...): registers the implementation
// (a struct with static member functions named after slots) and its integrators. Use it once.
// GEOMECH_STUDENT_SELECTION names what the compile registers (see WholeFile); it is expanded where
// the macro is used, after geomech/detail/scalar_selection.hpp may have redefined it.
#ifndef GEOMECH_STUDENT_SELECTION
#define GEOMECH_STUDENT_SELECTION ::gm::student::detail::WholeFile
#endif
#define GEOMECH_STUDENT(...)                                        \
  [[maybe_unused]] static const int geomech_student_registration_ = \
      ::gm::student::detail::register_all<GEOMECH_STUDENT_SELECTION, __VA_ARGS__>(#__VA_ARGS__)
