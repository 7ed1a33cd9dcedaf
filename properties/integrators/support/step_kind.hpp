// The two kinds of step an integrator offers, the rigid body with attitude (Pi, O) and Manakov's
// (M, O) with A = diag(a), as one trait each, so that a claim about an integrator is written once
// over the kind (properties/integrators/integrator_claims.cpp). A trait gives only what differs:
// the state and case types, the draws of a case (the generators' calls in their order: a verdict
// is reproduced from its seed only if they do not move), a run of steps, the distance between
// states, the case in the notes' names, the explaining wrapper of a false claim, and the words of
// a message that name the kind. What a claim checks for one kind only is a flag of the trait. The
// local order and the 50-digit floor of integrator_regimes.cpp are written over them too.
#pragma once

#include "core/subject.hpp"
#include "properties/integrators/support/roundoff_drift.hpp"
#include "properties/integrators/support/step_field.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/scalar_text.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace gm::stepkind {

struct NoCallback {
  template <class X>
  void operator()(int, const X&) const {}
};

// ---------------------------------------------------------------------------------------------
// The rigid body with attitude.

template <class T, class Each = NoCallback>
RigidBodyState<T> run(const Integrator<T>& in, const Vec3<T>& I, RigidBodyState<T> x, const T& h, int steps,
                      const Each& each = {}) {
  for (int n = 0; n < steps; ++n) {
    x = in.rigid_body_step(I, x, h);
    each(n + 1, x);
  }
  return x;
}

// A rigid-body case by the notes' names.
template <class T>
std::string rigid_body_inputs(const Vec3<T>& I, const RigidBodyState<T>& x) {
  return named("I", I) + named("Pi", x.Pi) + named("O", x.O);
}

template <class T>
T state_distance(const RigidBodyState<T>& a, const RigidBodyState<T>& b) {
  return std::max(max_abs((a.Pi - b.Pi).eval()), max_abs((a.O - b.O).eval()));
}

// A body and a state, drawn in this order: I, then Pi, then O.
template <class T>
struct RigidBodyCase {
  Vec3<T> I;
  RigidBodyState<T> x0;
};

// ---------------------------------------------------------------------------------------------
// Manakov's (M, O), A = diag(a).

template <class T>
struct ManakovCase {
  int n;
  std::vector<T> a;
  MatX<T> A;
  ManakovState<T> x0;
};

template <class T>
ManakovCase<T> draw_manakov_case(int lo, int hi) {
  ManakovCase<T> m;
  m.n = dyn::pick<T>(rc::gen::inRange(lo, hi + 1), "n");
  m.a = dyn::draw_generic_manakov_a<T>(m.n);
  m.A = dyn::diag_of(m.a);
  m.x0 = ManakovState<T>{dyn::draw_generic_skew<T>(m.n), dyn::pick<T>(gen::rotation<T>(m.n))};
  return m;
}

// A Manakov case by the notes' names, with the step h.
template <class T>
std::string manakov_inputs(const ManakovCase<T>& m, const T& h) {
  return named("A", m.A) + named("M", m.x0.M) + named("O", m.x0.O) + named("h", h);
}

template <class T, class Each = NoCallback>
ManakovState<T> run(const Integrator<T>& in, const MatX<T>& A, ManakovState<T> x, const T& h, int steps,
                    const Each& each = {}) {
  for (int n = 0; n < steps; ++n) {
    x = in.manakov_step(A, x, h);
    each(n + 1, x);
  }
  return x;
}

template <class T>
T state_distance(const ManakovState<T>& a, const ManakovState<T>& b) {
  return std::max(max_abs((a.M - b.M).eval()), max_abs((a.O - b.O).eval()));
}

// ---------------------------------------------------------------------------------------------
// The traits.

struct RigidBodyKind {
  template <class T>
  using State = RigidBodyState<T>;
  template <class T>
  using Case = RigidBodyCase<T>;

  // The prefix of a message naming the step: none, the rigid body's being the plain step; and the
  // kind in a series' title ("invariants: ", "convergence: ").
  static constexpr const char* step_words = "";
  static constexpr const char* series_kind = "";
  // Symmetry: a step that returns its input for h < 0 is said to (Manakov's check does not look);
  // the evidence is the inputs alone, without the explanation of Manakov's.
  static constexpr bool says_ignored_negative_step = true;
  static constexpr bool explains_symmetry = false;
  // Poisson: the bracket (3.6) in Pi, a 3 x 3 structure matrix.
  static constexpr const char* poisson_words = "D Phi J(Pi) D Phi^T = J(Phi(Pi)): a Poisson map for (3.6)";

  // Invariants over 64 steps of h = 1/8: round-off accumulates at most linearly, k = 16 per step
  // and per degree of the invariant. The rigid body's claim also tries a fourth state turned by
  // 1 rad a step, and names a bias per step (support/roundoff_drift.hpp) or a cap on the turn of a
  // step as the cause, by experiment.
  static constexpr int invariant_steps = 64;
  static constexpr bool has_large_turn = true;

  // lo and hi bound Manakov's n; the rigid body has none.
  template <class T>
  static Case<T> draw_case(int = 0, int = 0) {
    Case<T> c;
    c.I = dyn::draw_generic_inertia<T>();
    c.x0.Pi = dyn::draw_generic_momentum<T>();
    c.x0.O = dyn::draw_attitude<T>();
    return c;
  }

  template <class T>
  static State<T> step(const Integrator<T>& in, const Case<T>& c, const State<T>& x, const T& h) {
    return in.rigid_body_step(c.I, x, h);
  }

  template <class T, class Each = NoCallback>
  static State<T> run_from(const Integrator<T>& in, const Case<T>& c, const State<T>& x, const T& h, int steps,
                           const Each& each = {}) {
    return run(in, c.I, x, h, steps, each);
  }

  template <class T>
  static const Vec3<T>& body(const Case<T>& c) {
    return c.I;
  }

  // An invariant of the rigid body is a function of (I, x).
  template <class T, class Invariant>
  static auto value(const Invariant& invariant, const Case<T>& c, const State<T>& x) {
    return invariant(c.I, x);
  }

  // The momentum scaled by lambda: the same motion in other units, with h scaled by 1/lambda.
  template <class T>
  static Case<T> scaled(const Case<T>& c, const T& lambda) {
    return Case<T>{c.I, State<T>{(c.x0.Pi * lambda).eval(), c.x0.O}};
  }

  template <class T, class Invariant>
  static const roundoffdrift::Drift& drift(const Integrator<T>& in, const std::string& name,
                                           const Invariant& invariant) {
    return roundoffdrift::rigid_body_drift<T>(in, name, invariant);
  }

  template <class T>
  static std::string invariant_inputs(const Case<T>& c, const T& h, int steps, bool large_turn) {
    return rigid_body_inputs(c.I, c.x0) + "    h = " + to_string_full(h) + ", " + std::to_string(steps) +
           " steps (the case with the worst residual" + (large_turn ? ": one step turns the body by 1 rad)\n" : ")\n");
  }

  // In units of the scale, which is max(1, |Pi|) <= 1 for these draws.
  template <class T>
  static T symmetric_residual(const Case<T>& c, const State<T>& back) {
    return state_distance(back, c.x0);
  }

  template <class T>
  static std::string symmetric_inputs(const Case<T>& c, const T&) {
    return rigid_body_inputs(c.I, c.x0) + "    h = 1/4\n";
  }

  // Order: h = 1/8 halved down to 1/128, t = 1; where fewer than three steps stand above the
  // round-off floor the claim reruns sped up, and (a float step) at a fixed state; a run stops at
  // its first error that is not finite.
  static constexpr bool has_order_reruns = true;
  static constexpr const char* order_steps_words = "h = 1/8, halved down to 1/128; t = 1";
  static std::vector<int> order_steps() { return {8, 16, 32, 64, 128}; }
  static std::vector<std::string> part_names() { return {"Pi", "O"}; }

  template <class T>
  static State<T> oracle(const Case<T>& c, const T& t) {
    return dyn::oracle_rigid_body(c.I, c.x0, {t}).front();
  }

  template <class T>
  static T order_scale(const Case<T>& c) {
    return dyn::at_least_one(norm_inf(c.x0.Pi));
  }

  // The errors of the parts (Pi, O) of y against the exact state.
  template <class T>
  static std::pair<double, double> part_errors(const State<T>& y, const State<T>& exact) {
    return {to_double(T(max_abs(Vec3<T>(y.Pi - exact.Pi)))), to_double(T(max_abs(Mat3<T>(y.O - exact.O))))};
  }

  template <class T>
  static std::string order_where(const Case<T>&) {
    return "";
  }

  template <class T>
  static std::string order_inputs(const Case<T>& c, const std::string& steps) {
    return rigid_body_inputs(c.I, c.x0) + "    " + steps + "\n";
  }

  // |Pi| <= 1 here: the scale roundoff_factor8 (of |Pi|^2 roundoff_factor8).
  template <class T>
  static T poisson_scale() {
    return deriv::roundoff_factor8<T>();
  }

  template <class T, class States, class Judge>
  static void explaining(const Integrator<T>& in, const Case<T>& c, States&& states, const std::vector<double>& hs,
                         Judge&& judge) {
    stepfield::explaining_step(in, c.I, std::forward<States>(states), hs, std::forward<Judge>(judge));
  }

  // The local order (integrator_regimes.cpp, 3. at its top): one step from a generic case drawn as
  // draw_case draws it, at h = c 2^-k t_s with the time scale t_s = 1 / max(1, |Omega|) of the motion
  // (its steps as h |Omega|, h / t_s), the error relative to |Pi| (not at least 1: the state's own
  // size), against the floor of one step as it is.
  template <class T>
  static Case<T> draw_local_case() {
    return draw_case<T>();
  }

  template <class T>
  static T local_time_scale(const Case<T>& c) {
    return T(1) / dyn::at_least_one(T(norm_inf(c.x0.Pi) / c.I.minCoeff()));
  }

  template <class T>
  static std::vector<State<T>> oracle_at(const Case<T>& c, const std::vector<T>& times) {
    return dyn::oracle_rigid_body(c.I, c.x0, times);
  }

  template <class T>
  static T local_size(const Case<T>& c) {
    return norm_inf(c.x0.Pi);
  }

  template <class T>
  static double local_h(const T& h, const T& t_s) {
    return to_double(T(h / t_s));
  }

  template <class T>
  static double local_floor(double floor, const Case<T>&) {
    return floor;
  }

  template <class T>
  static std::string local_where(const Case<T>&) {
    return "";
  }

  template <class T>
  static std::string local_inputs(const Case<T>& c, const T& factor, const T& t_s) {
    return named("I", c.I) + named("Pi", c.x0.Pi) + named("O", c.x0.O) +
           "    h = c 2^-k t, c = " + to_string_full(factor) + ", t = " + to_string_full(t_s) + "\n";
  }

  // The 50-digit floor (integrator_regimes.cpp, 2. at its top), from the local order's case: the
  // error relative to |Pi|; a failure names its cause by the step's own field and precision
  // (stepfield::explain_rigid_body_step), and the bound is printed.
  static constexpr bool probes_floor = true;

  template <class T>
  static T momentum_size(const Case<T>& c) {
    return norm_inf(c.x0.Pi);
  }

  template <class T>
  static std::string floor_bound_words(const T& bound) {
    return " (local error C h^2) and the bound is 2^-60 = " + to_string_full(bound);
  }

  template <class T>
  static std::string case_names(const Case<T>& c) {
    return named("I", c.I) + named("Pi", c.x0.Pi) + named("O", c.x0.O);
  }
};

struct ManakovKind {
  template <class T>
  using State = ManakovState<T>;
  template <class T>
  using Case = ManakovCase<T>;

  static constexpr const char* step_words = "Manakov ";
  static constexpr const char* series_kind = " (Manakov)";
  static constexpr bool says_ignored_negative_step = false;
  static constexpr bool explains_symmetry = true;
  static constexpr const char* poisson_words =
      "D Phi J(M) D Phi^T = J(Phi(M)): a Poisson map for the Lie-Poisson bracket of so(4)*";

  // The worst drift over 32 steps of h = 1/8 (with |M_ij| up to 1 a fourth-order method drifts by
  // ~(h |Omega|)^5 ~ 1e-6 per step: far above the round-off bound in double too). No fourth state
  // and no cause by experiment.
  static constexpr int invariant_steps = 32;

  static constexpr bool has_large_turn = false;

  // n in [lo, hi]; the symmetric claim's, [3, 5], by default.
  template <class T>
  static Case<T> draw_case(int lo = 3, int hi = 5) {
    return draw_manakov_case<T>(lo, hi);
  }

  template <class T>
  static State<T> step(const Integrator<T>& in, const Case<T>& c, const State<T>& x, const T& h) {
    return in.manakov_step(c.A, x, h);
  }

  template <class T, class Each = NoCallback>
  static State<T> run_from(const Integrator<T>& in, const Case<T>& c, const State<T>& x, const T& h, int steps,
                           const Each& each = {}) {
    return run(in, c.A, x, h, steps, each);
  }

  template <class T>
  static const MatX<T>& body(const Case<T>& c) {
    return c.A;
  }

  // An invariant of Manakov's body is a function of the case (n, a, A) and x.
  template <class T, class Invariant>
  static auto value(const Invariant& invariant, const Case<T>& c, const State<T>& x) {
    return invariant(c, x);
  }

  // M scaled by lambda (the case as run keeps n, a and A).
  template <class T>
  static Case<T> scaled(const Case<T>& c, const T& lambda) {
    Case<T> m = c;
    m.x0.M *= lambda;
    return m;
  }

  // No experiment for a bias per step: an empty cause, never systematic.
  template <class T, class Invariant>
  static const roundoffdrift::Drift& drift(const Integrator<T>&, const std::string&, const Invariant&) {
    static const roundoffdrift::Drift none{};
    return none;
  }

  template <class T>
  static std::string invariant_inputs(const Case<T>& c, const T& h, int steps, bool) {
    return manakov_inputs(c, h) + "    (" + std::to_string(steps) + " steps; the case with the worst residual)\n";
  }

  // |M_ij| <= 1 and n <= 5 here: the scale n (entries of products summed over n terms).
  template <class T>
  static T symmetric_residual(const Case<T>& c, const State<T>& back) {
    return state_distance(back, c.x0) / T(c.n);
  }

  template <class T>
  static std::string symmetric_inputs(const Case<T>& c, const T& h) {
    return manakov_inputs(c, h);
  }

  // Order: h = 1/8 halved down to 1/64, t = 1, n in [3, 4]; no reruns, and every run to its end.
  static constexpr bool has_order_reruns = false;
  static constexpr const char* order_steps_words = "(h halved down to 1/64)";
  static std::vector<int> order_steps() { return {8, 16, 32, 64}; }
  static std::vector<std::string> part_names() { return {"M", "O"}; }

  template <class T>
  static State<T> oracle(const Case<T>& c, const T& t) {
    return dyn::oracle_manakov(c.a, c.x0, {t}).front();
  }

  template <class T>
  static T order_scale(const Case<T>& c) {
    return dyn::at_least_one(norm_inf(c.x0.M));
  }

  // The errors of the parts (M, O) of y against the exact state.
  template <class T>
  static std::pair<double, double> part_errors(const State<T>& y, const State<T>& exact) {
    return {to_double(T(max_abs(MatX<T>(y.M - exact.M)))), to_double(T(max_abs(MatX<T>(y.O - exact.O))))};
  }

  template <class T>
  static std::string order_where(const Case<T>& c) {
    return " on Manakov, n = " + std::to_string(c.n);
  }

  // The inputs with the first step, h = 1/8.
  template <class T>
  static std::string order_inputs(const Case<T>& c, const std::string& steps) {
    return manakov_inputs(c, T(T(1) / T(8))) + "    " + steps + "\n";
  }

  // |M_ij| <= 1, n = 4: the scale d * roundoff_factor8 (sums of d = 6 terms).
  template <class T>
  static T poisson_scale() {
    return T(T(6) * deriv::roundoff_factor8<T>());
  }

  template <class T, class States, class Judge>
  static void explaining(const Integrator<T>& in, const Case<T>& c, States&& states, const std::vector<double>&,
                         Judge&& judge) {
    stepfield::explaining_manakov_step(in, c.A, std::forward<States>(states), std::forward<Judge>(judge));
  }

  // The local order: n in [3, 4] drawn by gen::uniform (the regimes' own draw, not draw_case's: a
  // verdict is reproduced from its seed only if the calls do not move), A = diag(a) (the oracle's
  // body), |M_ij| <= 1: the time scale 1, steps h themselves, the error relative to max(1, |M|),
  // the floor of one step times n (entries of products summed over n terms).
  template <class T>
  static Case<T> draw_local_case() {
    Case<T> m;
    m.n = dyn::pick<T>(gen::uniform(3, 5), "n");
    m.a = dyn::draw_generic_manakov_a<T>(m.n);
    m.A = dyn::diag_of(m.a);
    m.x0 = ManakovState<T>{dyn::draw_generic_skew<T>(m.n), dyn::pick<T>(gen::rotation<T>(m.n))};
    return m;
  }

  template <class T>
  static T local_time_scale(const Case<T>&) {
    return T(1);
  }

  template <class T>
  static std::vector<State<T>> oracle_at(const Case<T>& c, const std::vector<T>& times) {
    return dyn::oracle_manakov(c.a, c.x0, times);
  }

  template <class T>
  static T local_size(const Case<T>& c) {
    return dyn::at_least_one(norm_inf(c.x0.M));
  }

  template <class T>
  static double local_h(const T& h, const T&) {
    return to_double(h);
  }

  template <class T>
  static double local_floor(double floor, const Case<T>& c) {
    return floor * c.n;
  }

  template <class T>
  static std::string local_where(const Case<T>& c) {
    return " on Manakov, n = " + std::to_string(c.n);
  }

  template <class T>
  static std::string local_inputs(const Case<T>& c, const T& factor, const T&) {
    return named("A", c.A) + named("M", c.x0.M) + named("O", c.x0.O) + "    h = c 2^-k, c = " + to_string_full(factor) +
           "\n";
  }

  // The 50-digit floor: the error relative to |M| (not at least 1); the step's precision is not
  // probed, so a failure names no cause and keeps the passing words in its first line.
  static constexpr bool probes_floor = false;

  template <class T>
  static T momentum_size(const Case<T>& c) {
    return norm_inf(c.x0.M);
  }

  template <class T>
  static std::string floor_bound_words(const T&) {
    return " and the bound is 2^-60 (cause not identified: the Manakov step's precision is not probed)";
  }

  template <class T>
  static std::string case_names(const Case<T>& c) {
    return named("A", c.A) + named("M", c.x0.M) + named("O", c.x0.O);
  }
};

}  // namespace gm::stepkind
