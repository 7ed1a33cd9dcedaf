// A subject is an implementation under test: the bundled reference implementation, a
// deliberately wrong variant of it (a negative control), or someone else's code.
//
// Properties see a subject only through the named slots below, so adding a subject never means
// editing a property. A subject fills any subset of the slots; a property whose slots are not
// all filled is reported NOT PROVIDED, never silently skipped.
//
// Every slot is listed exactly once, in GM_SUBJECT_SLOTS: the list generates the members of
// Subject<T>, the lookup by name, and the slot table printed by `geomech slots`.
#pragma once

#include "core/lie_algebra_id.hpp"
#include "core/linalg.hpp"
#include "core/state_form.hpp"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gm {

template <class T>
using Vec3Pair = std::pair<Vec3<T>, Vec3<T>>;
template <class T>
using MatXPair = std::pair<MatX<T>, MatX<T>>;

// State of the rigid body with its attitude, (2.20): body angular momentum and O in SO(3).
template <class T>
struct RigidBodyState {
  Vec3<T> Pi;
  Mat3<T> O;
};

// State of Manakov's SO(n) rigid body with its attitude (section 2.4): M in so(n), O in SO(n).
template <class T>
struct ManakovState {
  MatX<T> M;
  MatX<T> O;
};

// Thrown when a property calls a slot the subject does not fill. Properties declare the slots
// they need, so the runner reports NOT PROVIDED before running; reaching this means a property
// forgot to declare a need, which the runner reports as an error in the property.
class SlotMissing : public std::logic_error {
 public:
  explicit SlotMissing(const char* slot)
      : std::logic_error(std::string("slot '") + slot + "' is not provided by this subject"), slot_(slot) {}
  const char* slot() const { return slot_; }

 private:
  const char* slot_;
};

template <class Sig>
class Slot;

template <class R, class... A>
class Slot<R(A...)> {
 public:
  explicit Slot(const char* name) : name_(name) {}
  Slot& operator=(std::function<R(A...)> f) {
    f_ = std::move(f);
    return *this;
  }
  explicit operator bool() const { return static_cast<bool>(f_); }
  R operator()(A... args) const {
    if (!f_) throw SlotMissing(name_);
    return f_(std::forward<A>(args)...);
  }
  const char* name() const { return name_; }
  const std::function<R(A...)>& function() const { return f_; }

 private:
  const char* name_;
  std::function<R(A...)> f_;
};

// A failure of the process the code under test runs in, not of its code: it died, answered out of
// step, or sent what is not an answer (harness/remote/remote_subject.hpp). Never taken for a step that
// raised (properties/support/step_guard.hpp): the code did not get to say anything.
class ProcessFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// SLOT(name, signature, place in the notes, meaning)
// Signatures use T, the scalar. Arguments are in the notes' order and notation.
#define GM_SUBJECT_SLOTS(SLOT)                                                                                     \
  /* so(3) and so(n) */                                                                                            \
  SLOT(hat, Mat3<T>(const Vec3<T>& v), "(2.11)", "so(3) hat map: hat(v) w = v x w")                                \
  SLOT(vee, Vec3<T>(const Mat3<T>& m), "(2.11)", "inverse of the hat map on skew 3x3 matrices")                    \
  SLOT(pairing, T(const MatX<T>& a, const MatX<T>& b), "(2.15)", "trace pairing <A, B> = tr(A^T B)/2")             \
  SLOT(hat_n, MatX<T>(const VecX<T>& v, int n), "sec. 1, SO(4) exercise", "so(n) hat map from R^{n(n-1)/2}")       \
  SLOT(vee_n, VecX<T>(const MatX<T>& m), "sec. 1, SO(4) exercise", "inverse of hat_n")                             \
  /* matrix Lie algebras in coordinates */                                                                         \
  SLOT(lie_hat, MatX<T>(LieAlgebraId g, const VecX<T>& x), "sec. 1", "coordinates -> matrix in g")                 \
  SLOT(lie_vee, VecX<T>(LieAlgebraId g, const MatX<T>& m), "sec. 1", "matrix in g -> coordinates")                 \
  SLOT(ad_star, VecX<T>(LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu), "sec. 1, exercise",                 \
       "(ad*_xi mu)_k = xi^j mu_i c^i_jk")                                                                         \
  SLOT(so4_bracket_R6, Vec6<T>(const Vec6<T>& a, const Vec6<T>& b), "sec. 1, SO(4) exercise",                      \
       "Lie bracket of so(4) in R^6 coordinates")                                                                  \
  SLOT(ad_star_so4_R6, Vec6<T>(const Vec6<T>& xi, const Vec6<T>& mu), "sec. 1, SO(4) exercise",                    \
       "ad* of so(4) in R^6 coordinates")                                                                          \
  /* Euler's equations */                                                                                          \
  SLOT(euler_2_1, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Omega), "(2.1)", "dOmega/dt, componentwise")            \
  SLOT(euler_2_2, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Omega), "(2.2)",                                        \
       "dOmega/dt from I dOmega/dt = I Omega x Omega")                                                             \
  SLOT(euler_3_7, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Pi), "(3.7)", "dPi/dt, componentwise")                  \
  SLOT(euler_3_8, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Pi), "(3.8)", "dPi/dt = Pi x I^-1 Pi")                  \
  SLOT(euler_matrix_2_12, Mat3<T>(const Vec3<T>& I, const Mat3<T>& Pi_hat), "(2.12), (2.20)",                      \
       "dPi/dt = -[Omega_hat, Pi] for skew Pi")                                                                    \
  /* Lagrangian, Legendre transform, Hamiltonian */                                                                \
  SLOT(lagrangian_2_5, T(const Vec3<T>& I, const Vec3<T>& Omega), "(2.5)", "l = I Omega . Omega / 2")              \
  SLOT(lagrangian_2_13, T(const Vec3<T>& I, const Mat3<T>& Omega_hat), "(2.13)", "l = <I Omega_hat, Omega_hat>/2") \
  SLOT(legendre_3_1, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Omega), "(3.1)", "Pi = dl/dOmega = I Omega")         \
  SLOT(omega_3_5, Vec3<T>(const Vec3<T>& I, const Vec3<T>& Pi), "(3.5)", "Omega = dh/dPi = I^-1 Pi")               \
  SLOT(hamiltonian_3_3, T(const Vec3<T>& I, const Vec3<T>& Pi), "(3.3)", "h = Pi . Omega - l(Omega)")              \
  SLOT(hamiltonian_3_4, T(const Vec3<T>& I, const Vec3<T>& Pi), "(3.4)", "h = Pi . I^-1 Pi / 2")                   \
  SLOT(hamiltonian_2_21, T(const Vec3<T>& I, const Mat3<T>& Pi_hat), "(2.21)", "h = <Pi, Omega_hat> - l")          \
  SLOT(casimir, T(const Vec3<T>& Pi), "(2.27), sec. 3.3", "c(Pi) = |Pi|^2/2, a Casimir of the bracket (3.6)")      \
  /* Poisson brackets (evaluated from gradients at a point) */                                                     \
  SLOT(lie_poisson_2_23, T(const Mat3<T>& Pi_hat, const Mat3<T>& df_hat, const Mat3<T>& dh_hat), "(2.23), (3.10)", \
       "{f,h} = -<Pi, [df, dh]>, gradients as skew matrices")                                                      \
  SLOT(lie_poisson_3_6, T(const Vec3<T>& Pi, const Vec3<T>& df, const Vec3<T>& dh), "(3.6), (2.25)",               \
       "{f,h} = -Pi . df x dh")                                                                                    \
  SLOT(nambu_3_13, T(const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh), "(3.13)",                           \
       "{f,h} = -grad c . grad f x grad h")                                                                        \
  SLOT(nambu_motion_3_14, Vec3<T>(const Vec3<T>& dc, const Vec3<T>& dh), "(3.14)", "dx/dt = grad c x grad h")      \
  SLOT(canonical_bracket, T(const Vec3<T>& dfdq, const Vec3<T>& dfdp, const Vec3<T>& dhdq, const Vec3<T>& dhdp),   \
       "sec. 3.5", "canonical bracket on T*R^3, {q_i, p_j} = delta_ij")                                            \
  SLOT(nambu_3_16, Vec3<T>(const Vec3<T>& a, const Vec3<T>& x), "(3.16)", "the system (3.16)")                     \
  /* momentum map, Clebsch, reconstruction */                                                                      \
  SLOT(momentum_map, Vec3<T>(const Vec3<T>& q, const Vec3<T>& p), "momentum-map section", "J = p x q")             \
  SLOT(clebsch_3_21, Vec3Pair<T>(const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P), "(3.21)",                  \
       "(dQ/dt, dP/dt) with Pi = P x Q")                                                                           \
  SLOT(reconstruction_2_10, Mat3<T>(const Mat3<T>& O, const Vec3<T>& Omega), "(2.10)", "dO/dt = O Omega_hat")      \
  SLOT(spatial_momentum, Vec3<T>(const Mat3<T>& O, const Vec3<T>& Pi), "(2.30)", "pi = Ad*_{O^-1} Pi")             \
  SLOT(inertia_space, Mat3<T>(const Mat3<T>& O, const Vec3<T>& I), "Remark 2.1", "I_space = O I O^-1")             \
  SLOT(inertia_tensor_2_3, Mat3<T>(const VecX<T>& m, const MatX<T>& X), "(2.3)", "inertia of point masses")        \
  SLOT(inertia_bilinear_2_3, T(const VecX<T>& m, const MatX<T>& X, const Vec3<T>& a, const Vec3<T>& b), "(2.3)",   \
       "(a, b) = sum m (a x X).(b x X)")                                                                           \
  /* Manakov on so(n) */                                                                                           \
  SLOT(manakov_M, MatX<T>(const MatX<T>& A, const MatX<T>& Omega), "(2.34)", "M = A Omega + Omega A")              \
  SLOT(manakov_Omega, MatX<T>(const MatX<T>& A, const MatX<T>& M), "(2.34)", "Omega recovered from M")             \
  SLOT(manakov_2_34, MatX<T>(const MatX<T>& A, const MatX<T>& M), "(2.34), (2.36)", "dM/dt = [M, Omega]")          \
  SLOT(manakov_lagrangian, T(const MatX<T>& A, const MatX<T>& Omega), "Prop. 2.4", "l = -tr(Omega A Omega)/2")     \
  SLOT(manakov_clebsch_3_23, MatXPair<T>(const MatX<T>& A, const MatX<T>& Q, const MatX<T>& P), "(3.23)",          \
       "(dQ/dt, dP/dt) = (Q Omega, P Omega)")

// One step of an integrator for the rigid body with attitude (Pi, O), or for Manakov's (M, O); or,
// in the canonical variables of the Clebsch formulations, for (3.21) on T*R^3 (Q, P) with
// H(Q, P) = h(P x Q), and for (3.23) on T*R^{n x n} (Q, P) with Manakov's energy of M = Q^T P - P^T Q
// (the symplecticity claim acts on these).
template <class T>
struct Integrator {
  std::string name;
  Slot<RigidBodyState<T>(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h)> rigid_body_step{"rigid_body_step"};
  Slot<ManakovState<T>(const MatX<T>& A, const ManakovState<T>& x, const T& h)> manakov_step{"manakov_step"};
  Slot<Vec3Pair<T>(const Vec3<T>& I, const Vec3Pair<T>& QP, const T& h)> clebsch_step{"clebsch_step"};
  Slot<MatXPair<T>(const MatX<T>& A, const MatXPair<T>& QP, const T& h)> manakov_clebsch_step{"manakov_clebsch_step"};
  // Optional: n consecutive steps from x, the state after each, as n calls of the step would give.
  // An implementation behind the protocol fills them, so that a long run costs one round trip per
  // chunk of steps instead of one per step (harness/remote/remote_subject.cpp); properties reach them
  // through properties/integrators/support/step_runs.hpp, which calls the step n times when they are empty.
  std::function<std::vector<RigidBodyState<T>>(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h, int n)>
      rigid_body_run;
  std::function<std::vector<ManakovState<T>>(const MatX<T>& A, const ManakovState<T>& x, const T& h, int n)>
      manakov_run;
  // The form the integrator keeps the rigid body's state in (core/state_form.hpp): the notes' (Pi, O)
  // unless it declares another (a quaternion, omega, ...). Then its own step is `declared_step` (and
  // `declared_run`), and core/declared_step.hpp makes rigid_body_step of it: the properties see
  // (Pi, O), the suite owns the conversions.
  StateForm form;
  Slot<EngineState<T>(const Vec3<T>& I, const EngineState<T>& x, const T& h)> declared_step{"rigid_body_step"};
  std::function<std::vector<EngineState<T>>(const Vec3<T>& I, const EngineState<T>& x, const T& h, int n)> declared_run;
};

template <class T>
struct Subject {
  using Scalar = T;

#define GM_DECLARE_SLOT(name, sig, place, meaning) Slot<sig> name{#name};
  GM_SUBJECT_SLOTS(GM_DECLARE_SLOT)
#undef GM_DECLARE_SLOT

  std::vector<Integrator<T>> integrators;

  // Whether the slot with this name is filled; throws std::invalid_argument for a name that is
  // not a slot at all (a typo in a property's needs must not read as "not provided").
  bool provides(std::string_view slot) const {
#define GM_PROVIDES_SLOT(name, sig, place, meaning) \
  if (slot == #name) return static_cast<bool>(name);
    GM_SUBJECT_SLOTS(GM_PROVIDES_SLOT)
#undef GM_PROVIDES_SLOT
    throw std::invalid_argument("no subject slot is named '" + std::string(slot) + "'");
  }
};

struct SlotInfo {
  const char* name;
  const char* signature;
  const char* place;
  const char* meaning;
};

// The slot table, in declaration order.
const std::vector<SlotInfo>& subject_slots();
bool is_slot_name(std::string_view name);

// What an integrator's author claims about it; the harness verifies every claim.
// Where an integrator's step is meant to work: an engine may refuse or reset states
// above some speed, or steps below some size. Nothing outside is drawn by any check, the report
// states the domain, and a step that raises outside an undeclared one is told it may declare it.
// 0: no limit.
struct StepDomain {
  double max_omega = 0;  // the largest |Omega| = max |Pi_i / I_i| (Manakov: max |M_ij| / min a_i)
  double max_pi = 0;     // the largest max |Pi_i| (Manakov: max |M_ij|; Clebsch: max(|Q|, |P|))
  double min_h = 0;      // the smallest |h|
  bool declared() const { return max_omega > 0 || max_pi > 0 || min_h > 0; }
};

struct IntegratorClaims {
  std::string integrator;        // name of the Integrator this describes
  int order = 0;                 // claimed order of accuracy (0: no claim)
  bool symmetric = false;        // time-reversible: step(h) then step(-h) is the identity
  bool casimir = false;          // preserves |Pi|^2 (or the spectrum of M) to round-off
  bool energy = false;           // preserves h to round-off
  bool orthogonality = false;    // keeps O orthogonal to round-off
  bool spectrum = false;         // keeps the spectrum of M (Manakov) to round-off
  bool poisson = false;          // is a Poisson map for the Lie-Poisson bracket
  bool noether = false;          // keeps the spatial momentum O Pi (Manakov: O M O^T) to round-off (Thm 2.2)
  bool equivariant = false;      // step(Pi, R O) = (Pi', R O') for every rotation R (left invariance)
  bool bounded_energy = false;   // long runs: energy error bounded, no secular drift
  bool symplectic = false;       // canonical steps (clebsch_step, manakov_clebsch_step): dPhi^T J dPhi = J
  bool unit_quaternion = false;  // an attitude kept as a quaternion: |q| = 1 is kept to round-off
  // Not a claim: the precision the author states for the step ("double": it computes in double
  // whatever it is given, so it is run in double only) and why ("the engine is built in double"),
  // shown in the report beside the claims.
  std::string precision = {};
  std::string precision_reason = {};
  StepDomain domain{};  // where the step is meant to work (not a claim: a statement of scope)
};

// The yes/no claims by name, in the order reports list them (`order`, a number, comes before them):
// the one list the protocol, the student header and the reports read.
struct BooleanClaim {
  const char* name;
  bool IntegratorClaims::*member;
};
inline constexpr BooleanClaim kBooleanClaims[] = {{"symmetric", &IntegratorClaims::symmetric},
                                                  {"casimir", &IntegratorClaims::casimir},
                                                  {"energy", &IntegratorClaims::energy},
                                                  {"orthogonality", &IntegratorClaims::orthogonality},
                                                  {"spectrum", &IntegratorClaims::spectrum},
                                                  {"poisson", &IntegratorClaims::poisson},
                                                  {"noether", &IntegratorClaims::noether},
                                                  {"equivariant", &IntegratorClaims::equivariant},
                                                  {"bounded_energy", &IntegratorClaims::bounded_energy},
                                                  {"symplectic", &IntegratorClaims::symplectic},
                                                  {"unit_quaternion", &IntegratorClaims::unit_quaternion}};

// A subject in every scalar it supports. A subject written only for double has mp and q empty
// and is told which checks it therefore misses.
struct SubjectSet {
  std::string name;
  std::string description;
  std::shared_ptr<const Subject<double>> d;
  std::shared_ptr<const Subject<Real50>> mp;
  std::shared_ptr<const Subject<Rational>> q;
  std::vector<IntegratorClaims> claims;

  template <class T>
  const Subject<T>* get() const {
    if constexpr (std::is_same_v<T, double>)
      return d.get();
    else if constexpr (std::is_same_v<T, Real50>)
      return mp.get();
    else
      return q.get();
  }

  const IntegratorClaims* claims_for(std::string_view integrator) const {
    for (const auto& c : claims)
      if (c.integrator == integrator) return &c;
    return nullptr;
  }
};

// A copy of `base` with `patch(subject)` applied to each of its scalar instantiations; `patch` is a
// generic callable taking Subject<T>& (this is how negative controls are made).
template <class Patch>
SubjectSet mutate(const SubjectSet& base, std::string name, std::string description, Patch&& patch) {
  SubjectSet out = base;
  out.name = std::move(name);
  out.description = std::move(description);
  if (base.d) {
    auto s = std::make_shared<Subject<double>>(*base.d);
    patch(*s);
    out.d = s;
  }
  if (base.mp) {
    auto s = std::make_shared<Subject<Real50>>(*base.mp);
    patch(*s);
    out.mp = s;
  }
  if (base.q) {
    auto s = std::make_shared<Subject<Rational>>(*base.q);
    patch(*s);
    out.q = s;
  }
  return out;
}

}  // namespace gm
