// The property registry. A property is one executable check of one statement of the notes:
// it names its spec/ catalogue entry (like test262's esid), the slots of the subject it needs,
// its tolerance class, and the negative controls (deliberately wrong subjects, by name) that
// must make it fail. Its body is a function template over the scalar, instantiated here for
// double, Real50 and (for algebraic identities) Rational.
//
// Register a property in its own .cpp under the folder of its part of the notes (properties/README.md)
// with
//   GM_PROPERTY(body_template, all_scalars | float_scalars, {.spec = ..., .title = ..., ...});
// (its id is the function's name, spelt once, there).
// Nothing else needs editing: tests, the report and the student harness all read the registry, and
// spec/CATALOGUE.md names the file (recorded by GM_PROPERTY).
#pragma once

#include "core/subject.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gm {

// DESIGN.md, "Tolerance classes".
enum class ToleranceClass {
  Exact,       // algebraic identity: residual 0 in rationals, k * eps(T) * scale in floats
  Roundoff,    // floating-point evaluation or exact conservation: k * eps(T) * scale
  Truncation,  // integrators: judged by the measured convergence slope against the claimed order
};
const char* tolerance_name(ToleranceClass t);

// The integrator step a property drives (core/subject.hpp, Integrator).
// RigidBodyMatrix: a rigid-body step whose attitude is its own matrix (not one the suite made of a
// quaternion: its orthogonality is the user's merit only then); RigidBodyQuaternion: a rigid-body
// step kept with a quaternion (core/state_form.hpp), driven in its own form.
enum class StepKind { None, RigidBody, Manakov, Clebsch, ManakovClebsch, RigidBodyMatrix, RigidBodyQuaternion };
// Whether `i` has the step of kind k (None: any integrator), and the step's name.
template <class I>
bool has_step_kind(const I& i, StepKind k) {
  switch (k) {
    case StepKind::RigidBody:
      return static_cast<bool>(i.rigid_body_step);
    case StepKind::RigidBodyMatrix:
      return i.rigid_body_step && !i.form.has_quaternion();
    case StepKind::RigidBodyQuaternion:
      return i.declared_step && i.form.has_quaternion();
    case StepKind::Manakov:
      return static_cast<bool>(i.manakov_step);
    case StepKind::Clebsch:
      return static_cast<bool>(i.clebsch_step);
    case StepKind::ManakovClebsch:
      return static_cast<bool>(i.manakov_clebsch_step);
    case StepKind::None:
      break;
  }
  return true;
}
const char* step_name(StepKind k);

enum class Scope {
  Subject,     // runs once per subject
  Integrator,  // runs once per integrator of the subject (with that integrator's claims)
};

template <class T>
using SubjectBody = std::function<void(const Subject<T>&)>;
template <class T>
using IntegratorBody = std::function<void(const Subject<T>&, const Integrator<T>&, const IntegratorClaims&)>;

// Default number of random cases per scalar. Multiprecision and rational arithmetic cost 10x to
// 1000x more than double, so fewer cases run there; each case is still fully random.
struct Cases {
  int d = 100;
  int mp = 25;
  int q = 25;
};

struct PropertyDef {
  std::string id{};   // stable, snake_case: the test name, the function's name (set by GM_PROPERTY)
  std::string spec;   // catalogue entry id
  std::string title;  // the statement being checked, one line
  ToleranceClass tolerance = ToleranceClass::Exact;
  std::vector<std::string> needs;              // subject slots used
  std::vector<std::string> negative_controls;  // mutant names that must fail this property
  Cases cases{};
  Scope scope = Scope::Subject;    // set by the registration tag
  StepKind step = StepKind::None;  // Integrator scope: the step function it drives
  // Integrator scope: the claims this property decides ("order", "casimir", ...; the
  // names of IntegratorClaims). A claim is verified only when every property that judges it ran all
  // its cases and passed (harness/checking/integrator_verdicts.hpp).
  std::vector<std::string> judges{};
  // The file that registers it, from properties/ on ("properties/s3_4_nambu/nambu_bracket.cpp"):
  // set by GM_PROPERTY from __FILE__ (also inside a unity batch, where the file is #included).
  std::string file{};
};

// `def` with its id the name of its function (`fn`, GM_PROPERTY's first argument; a `def` that
// spells an id of its own throws std::logic_error: a name is spelt once) and `file` set to `path`
// from its last "properties/" folder on (source_in_tree), whatever the build's source directory is.
PropertyDef registered_as(PropertyDef def, std::string_view fn, std::string_view path);
std::string source_in_tree(std::string_view path);

struct Property : PropertyDef {
  explicit Property(PropertyDef def) : PropertyDef(std::move(def)) {}

  SubjectBody<double> d;
  SubjectBody<Real50> mp;
  SubjectBody<Rational> q;
  IntegratorBody<double> int_d;
  IntegratorBody<Real50> int_mp;

  bool runs_in(ScalarKind k) const;
};

// All registered properties, sorted by id.
const std::vector<Property>& properties();
const Property* find_property(std::string_view id);

struct AllScalars {};             // double, Real50 and Rational
struct FloatScalars {};           // double and Real50
struct IntegratorScalars {};      // double and Real50, once per integrator of the subject
struct IntegratorMp50Scalars {};  // Real50 only (a check only 50 digits can make: the 50-digit floor)
inline constexpr AllScalars all_scalars{};
inline constexpr FloatScalars float_scalars{};
inline constexpr IntegratorScalars integrator_scalars{};
inline constexpr IntegratorMp50Scalars integrator_mp50_scalars{};

void register_property(Property p);

struct Registrar {
  template <class Body>
  Registrar(AllScalars, PropertyDef def, Body body) {
    Property p{std::move(def)};
    p.d = [body](const Subject<double>& s) { body(s); };
    p.mp = [body](const Subject<Real50>& s) { body(s); };
    p.q = [body](const Subject<Rational>& s) { body(s); };
    register_property(std::move(p));
  }
  template <class Body>
  Registrar(FloatScalars, PropertyDef def, Body body) {
    Property p{std::move(def)};
    p.d = [body](const Subject<double>& s) { body(s); };
    p.mp = [body](const Subject<Real50>& s) { body(s); };
    register_property(std::move(p));
  }
  template <class Body>
  Registrar(IntegratorScalars, PropertyDef def, Body body) {
    Property p{std::move(def)};
    p.scope = Scope::Integrator;
    p.int_d = [body](const Subject<double>& s, const Integrator<double>& i, const IntegratorClaims& c) {
      body(s, i, c);
    };
    p.int_mp = [body](const Subject<Real50>& s, const Integrator<Real50>& i, const IntegratorClaims& c) {
      body(s, i, c);
    };
    register_property(std::move(p));
  }
  template <class Body>
  Registrar(IntegratorMp50Scalars, PropertyDef def, Body body) {
    Property p{std::move(def)};
    p.scope = Scope::Integrator;
    p.int_mp = [body](const Subject<Real50>& s, const Integrator<Real50>& i, const IntegratorClaims& c) {
      body(s, i, c);
    };
    register_property(std::move(p));
  }
};

}  // namespace gm

#define GM_PROPERTY_CONCAT2(a, b) a##b
#define GM_PROPERTY_CONCAT(a, b) GM_PROPERTY_CONCAT2(a, b)

// GM_PROPERTY(fn, all_scalars | float_scalars | integrator_scalars, {.spec = ..., ...}):
// registers the function template `fn` as the property whose id is "fn", taking (const Subject<T>&),
// or for integrator_scalars (const Subject<T>&, const Integrator<T>&, const IntegratorClaims&).
#define GM_PROPERTY(fn, scalars, ...)                                                 \
  static const ::gm::Registrar GM_PROPERTY_CONCAT(gm_property_registrar_, fn) {       \
    ::gm::scalars, ::gm::registered_as(::gm::PropertyDef __VA_ARGS__, #fn, __FILE__), \
        [](const auto&... args) { fn(args...); }                                      \
  }
