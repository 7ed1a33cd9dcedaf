// The two canonical (Clebsch) steps an integrator offers, clebsch_step on (Q, P) of (3.21) and
// manakov_clebsch_step on (Q, P) of (3.23), as one trait each, so that a claim about them is
// written once over the kind (properties/integrators/integrator_canonical.cpp), as
// support/step_kind.hpp does for rigid_body_step and manakov_step. Both steps are seen through one
// case type, the stacked state Z = [Q; P] with the system's step, energy and exact flow; a trait
// gives only what differs: the draws of a case (the generators' calls in their order: a verdict is
// reproduced from its seed only if they do not move), the steps of the order's run, the length of
// the energy's run, and the directions of the symplectic check.
#pragma once

#include "core/subject.hpp"
#include "impl/canonical_integrators.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/named_inputs.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gm::canonicalkind {

// One drawn case of either system, stepped through the integrator's slot on the stacked state
// Z = [Q; P] (impl/canonical_integrators.hpp).
template <class T>
struct CanonicalCase {
  std::string system;  // "(3.21)" or "(3.23), n = ..."
  int n = 3;
  std::function<MatX<T>(const MatX<T>&, const T&)> step;
  std::function<T(const MatX<T>&)> energy;
  MatX<T> Z0;
  T energy_scale;                          // a bound on the sum of |terms| of H at Z0 (H is of degree 4 in Z)
  std::function<MatX<T>(const T&)> exact;  // the exact flow at time t from Z0
  std::function<std::string()> body;       // the body's data (I or A) by the notes' names, for failures
  // The step's own vector field at Z against the system's (support/step_field_matrix.hpp).
  std::function<stepfield::Diagnosis(const MatX<T>&)> diagnose;

  // The case's inputs by the notes' names, with the step h.
  std::string inputs(const T& h) const {
    const auto k = Z0.rows() / 2;
    return "    system: " + system + "\n" + body() + named("Q", MatX<T>(Z0.topRows(k))) +
           named("P", MatX<T>(Z0.bottomRows(k))) + named("h", h);
  }
};

template <class T>
T at_least_one_abs(const MatX<T>& Z) {
  return dyn::at_least_one(max_abs(Z));
}

// The size of H's round-off at Z: H is a sum of positive terms (|H| bounds their sum), and an
// error of eps |Z| in each entry of Z moves H by at most eps |Z|_inf sum |dH/dz| to first order,
// where (dH/dP, -dH/dQ) is the field f(Z): scale |H| + |Z|_inf sum |f(Z)|.
template <class T>
T energy_scale(const T& H, const MatX<T>& Z, const MatX<T>& f) {
  return T(abs_value(H) + max_abs(Z) * f.cwiseAbs().sum());
}

template <class T>
CanonicalCase<T> clebsch_case(const Integrator<T>& in) {
  CanonicalCase<T> c;
  const Vec3<T> I = dyn::draw_generic_inertia<T>();
  c.system = "(3.21)";
  c.body = [I]() { return named("I", I); };
  c.step = [&in, I](const MatX<T>& Z, const T& h) { return ref::stack<T>(in.clebsch_step(I, ref::unstack3<T>(Z), h)); };
  c.energy = [I](const MatX<T>& Z) {
    const auto [Q, P] = ref::unstack3<T>(Z);
    return dyn::energy(I, ref::cross<T>(P, Q));
  };
  c.diagnose = [step = c.step, I](const MatX<T>& Z) {
    return stepfield::diagnose_clebsch<T>(stepfield::canonical_field<T>(step, Z), I, Z);
  };
  c.Z0 = ref::stack<T>(Vec3Pair<T>{dyn::draw_generic_momentum<T>(), dyn::draw_generic_momentum<T>()});
  c.energy_scale = energy_scale<T>(c.energy(c.Z0), c.Z0, ref::clebsch_field<T>(I, c.Z0));
  const MatX<T> Z0 = c.Z0;
  c.exact = [I, Z0](const T& t) {
    const auto [Q, P] = ref::unstack3<T>(Z0);
    const RigidBodyState<T> x =
        dyn::oracle_rigid_body(I, RigidBodyState<T>{ref::cross<T>(P, Q), Mat3<T>::Identity()}, {t}).front();
    return ref::stack<T>(Vec3Pair<T>{Vec3<T>(x.O.transpose() * Q), Vec3<T>(x.O.transpose() * P)});
  };
  return c;
}

template <class T>
MatX<T> draw_generic_matrix(int n) {
  MatX<T> X(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) X(i, j) = dyn::generic_entry<T>();
  return X;
}

// n from lo to hi. Entries of Q and P of size in [1/16, 1/2]: M = Q^T P - P^T Q then has entries of
// size about sqrt(2n)/4 (at most n/2), Omega about as large as in the (3.21) case, and the
// fixed-point solve of an implicit step of h = 1/4 contracts.
template <class T>
CanonicalCase<T> manakov_clebsch_case(const Integrator<T>& in, int lo, int hi) {
  CanonicalCase<T> c;
  c.n = dyn::pick<T>(rc::gen::inRange(lo, hi + 1), "n");
  const int n = c.n;
  const std::vector<T> a = dyn::draw_generic_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  c.system = "(3.23), n = " + std::to_string(n);
  c.body = [A]() { return named("A", A); };
  c.step = [&in, A](const MatX<T>& Z, const T& h) {
    return ref::stack<T>(in.manakov_clebsch_step(A, ref::unstack_n<T>(Z), h));
  };
  c.diagnose = [step = c.step, A](const MatX<T>& Z) {
    return stepfield::diagnose_manakov_clebsch<T>(stepfield::canonical_field<T>(step, Z), A, Z);
  };
  c.energy = [a](const MatX<T>& Z) {
    const auto [Q, P] = ref::unstack_n<T>(Z);
    return dyn::manakov_energy(a, ref::manakov_clebsch_M<T>(Q, P));
  };
  const T shrink = T(1) / T(2);
  c.Z0 = ref::stack<T>(
      MatXPair<T>{MatX<T>(shrink * draw_generic_matrix<T>(n)), MatX<T>(shrink * draw_generic_matrix<T>(n))});
  c.energy_scale = energy_scale<T>(c.energy(c.Z0), c.Z0, ref::manakov_clebsch_field<T>(A, c.Z0));
  const MatX<T> Z0 = c.Z0;
  c.exact = [a, Z0](const T& t) {
    const auto [Q, P] = ref::unstack_n<T>(Z0);
    const auto k = Q.rows();
    const ManakovState<T> x =
        dyn::oracle_manakov(a, ManakovState<T>{ref::manakov_clebsch_M<T>(Q, P), MatX<T>::Identity(k, k)}, {t}).front();
    return ref::stack<T>(MatXPair<T>{MatX<T>(Q * x.O), MatX<T>(P * x.O)});
  };
  return c;
}

// ---------------------------------------------------------------------------------------------
// The traits.

// (3.21): Q, P in R^3, the case's n = 3.
struct ClebschKind {
  // Order: h = 1/8 halved down to 1/128, t = 1 (as integrator_order).
  static std::vector<int> order_steps() { return {8, 16, 32, 64, 128}; }
  // Energy: 64 steps of h = 1/8 (as integrator_energy).
  static constexpr int energy_steps = 64;

  // lo and hi bound the n of (3.23); (3.21) has none. The draws: I, then Q, then P.
  template <class T>
  static CanonicalCase<T> draw_case(const Integrator<T>& in, int = 3, int = 6) {
    return clebsch_case<T>(in);
  }

  // Symplecticity along the six unit vectors of R^6: all of D Phi^T J D Phi - J is compared, and
  // nothing is drawn.
  template <class T>
  static std::vector<MatX<T>> directions(const CanonicalCase<T>&) {
    std::vector<MatX<T>> u;
    for (int i = 0; i < 6; ++i) u.push_back(MatX<T>(VecX<T>::Unit(6, i)));
    return u;
  }
};

// (3.23): Q, P in R^{n x n}, n in [lo, hi].
struct ManakovClebschKind {
  // Order: h = 1/8 halved down to 1/64, t = 1 (as manakov_integrator_order).
  static std::vector<int> order_steps() { return {8, 16, 32, 64}; }
  // Energy: 32 steps of h = 1/8 (as manakov_integrator_energy).
  static constexpr int energy_steps = 32;

  // n in [lo, hi]; [3, 6] by default. The draws: n, a, then Q, then P.
  template <class T>
  static CanonicalCase<T> draw_case(const Integrator<T>& in, int lo = 3, int hi = 6) {
    return manakov_clebsch_case<T>(in, lo, hi);
  }

  // Symplecticity along six random dyadic directions in R^{2 n^2}, entries in [-1, 1] by 1/8, drawn
  // row by row: the fifteen pairs are compared (a skew matrix S != 0 has u^T S v != 0 for almost
  // every pair).
  template <class T>
  static std::vector<MatX<T>> directions(const CanonicalCase<T>& c) {
    const auto rows = c.Z0.rows(), cols = c.Z0.cols();
    std::vector<MatX<T>> u;
    for (int i = 0; i < 6; ++i) {
      MatX<T> d(rows, cols);
      for (Eigen::Index r = 0; r < rows; ++r)
        for (Eigen::Index q = 0; q < cols; ++q) d(r, q) = T(dyn::pick<T>(rc::gen::inRange(-8, 9), "8 d_rq")) / T(8);
      u.push_back(d);
    }
    return u;
  }
};

}  // namespace gm::canonicalkind
