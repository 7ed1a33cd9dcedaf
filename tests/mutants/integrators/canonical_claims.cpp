// Negative controls for the claims of integrators in the canonical Clebsch variables
// (properties/integrators/integrator_canonical.cpp): symplecticity, order, symmetry, energy.
#include "impl/canonical_integrators.hpp"
#include "impl/reference_subject.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_canonical_claims {

// Stormer-Verlet written explicitly, as for a separable H = T(P) + V(Q):
//     P_half = P + (h/2) f_P(Q, P),   Q' = Q + h f_Q(Q, P_half),   P' = P_half + (h/2) f_P(Q', P_half),
// with (f_Q, f_P) = (dH/dP, -dH/dQ) the field (3.21) or (3.23). H = h(P x Q) is not separable, and
// for a non-separable H the first two stages of Stormer-Verlet are implicit (P_half appears on both
// sides): the explicit version keeps the textbook's claims (order 2, symmetric, symplectic) but is
// none of them.
template <class T, class Field>
MatX<T> explicit_verlet(const MatX<T>& Z, const T& h, const Field& f) {
  const auto k = Z.rows() / 2;
  const T half = h / T(2);
  MatX<T> Y = Z;
  Y.bottomRows(k) += half * f(Y).bottomRows(k);
  Y.topRows(k) += h * f(Y).topRows(k);
  Y.bottomRows(k) += half * f(Y).bottomRows(k);
  return Y;
}

struct ExplicitVerlet {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      for (auto& i : s.integrators)
        if (i.name == "clebsch_midpoint") {
          i.clebsch_step = [](const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
            return ref::unstack3<T>(
                explicit_verlet<T>(ref::stack<T>(z), h, [&](const MatX<T>& Z) { return ref::clebsch_field<T>(I, Z); }));
          };
          i.manakov_clebsch_step = [](const MatX<T>& A, const MatXPair<T>& z, const T& h) {
            return ref::unstack_n<T>(explicit_verlet<T>(
                ref::stack<T>(z), h, [&](const MatX<T>& Z) { return ref::manakov_clebsch_field<T>(A, Z); }));
          };
        }
    }
  }
};

GM_MUTANT(explicit_verlet_nonseparable,
          "Stormer-Verlet written explicitly for the non-separable Clebsch Hamiltonian (as if H = T(P) + V(Q)), "
          "keeping the midpoint rule's claims: order 2, symmetric, symplectic",
          ExplicitVerlet{});

// The implicit midpoint rule with its fixed-point iteration stopped at an absolute change of
// 1e-10, a tolerance written for double: the step is then a fixed number of iterations away from
// the midpoint rule, neither symplectic nor symmetric beyond about 1e-11, which the 50-digit run
// shows by thirty orders of magnitude. In double that defect is at the resolution of the
// symplecticity check (measured 21 eps * scale against an allowance of 16 in (3.21)): the control is
// asserted in 50 digits only, where the mistake is unambiguous.
struct LooseMidpoint {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      auto solve = [](const MatX<T>& Z0, const T& h, auto f) {
        const T half = h / T(2);
        MatX<T> mid = Z0 + half * f(Z0);
        for (int it = 0; it < 200; ++it) {
          const MatX<T> next = Z0 + half * f(mid);
          const T change = max_abs(MatX<T>(next - mid));
          mid = next;
          if (change < T(1e-10)) break;
        }
        return MatX<T>(T(2) * mid - Z0);
      };
      for (auto& i : s.integrators)
        if (i.name == "clebsch_midpoint") {
          i.clebsch_step = [solve](const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
            return ref::unstack3<T>(
                solve(ref::stack<T>(z), h, [&](const MatX<T>& Z) { return ref::clebsch_field<T>(I, Z); }));
          };
          i.manakov_clebsch_step = [solve](const MatX<T>& A, const MatXPair<T>& z, const T& h) {
            return ref::unstack_n<T>(
                solve(ref::stack<T>(z), h, [&](const MatX<T>& Z) { return ref::manakov_clebsch_field<T>(A, Z); }));
          };
        }
    }
  }
};

GM_MUTANT(clebsch_midpoint_loose_solve,
          "the Clebsch midpoint rule solved by fixed-point iteration only to an absolute change of 1e-10, "
          "still claiming symplectic and symmetric",
          LooseMidpoint{});
GM_MUTANT_WRONG_ONLY_IN(clebsch_midpoint_loose_solve, ScalarKind::MP50);

// Negative controls for the Clebsch steps' own fields, against the notes'. (3.23) written with the
// notes' printed momentum M = (P^T Q - Q^T P)/2 (erratum mm.manakov-clebsch): Omega is linear in M,
// so the field is -1/2 of (3.23)'s and the step is the midpoint rule with -h/2. (3.21) with the
// sign of both equations reversed (dQ/dt = Omega x Q): the midpoint rule with -h. Both stay
// symplectic and symmetric; their order claims are false, and the failures must name the equation
// followed (tests/step_field_tests.cpp).
GM_MUTANT(manakov_clebsch_midpoint_printed_M,
          "the Clebsch midpoint rule for (3.23) with the notes' printed M = (P^T Q - Q^T P)/2 (erratum "
          "mm.manakov-clebsch), still claiming order 2",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& i : s.integrators)
                if (i.name == "clebsch_midpoint")
                  i.manakov_clebsch_step = [](const MatX<T>& A, const MatXPair<T>& z, const T& h) {
                    return ref::manakov_clebsch_midpoint_step<T>(A, z, T(-h / T(2)));
                  };
            }
          });

GM_MUTANT(clebsch_midpoint_sign_flipped,
          "the Clebsch midpoint rule for (3.21) with dQ/dt = Omega x Q, dP/dt = Omega x P (both signs "
          "reversed), still claiming order 2",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& i : s.integrators)
                if (i.name == "clebsch_midpoint")
                  i.clebsch_step = [](const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
                    return ref::clebsch_midpoint_step<T>(I, z, T(-h));
                  };
            }
          });

// Classical RK4 on (Q, P) claiming symplecticity: it is not symplectic (no explicit Runge-Kutta
// method is).
GM_MUTANT_SET(rk4_claims_symplectic, "classical RK4 on the Clebsch variables claiming to be symplectic",
              [](SubjectSet& s) {
                for (auto& c : s.claims)
                  if (c.integrator == "rk4") c.symplectic = true;
              });

// The midpoint rule keeps quadratic invariants; its author concludes it keeps the energy, as it
// does for h(Pi) of the rigid body. In the Clebsch variables H is of degree 4: not kept.
GM_MUTANT_SET(clebsch_midpoint_claims_energy,
              "the Clebsch midpoint rule claiming to keep the energy (H is quartic in (Q, P), not quadratic)",
              [](SubjectSet& s) {
                for (auto& c : s.claims)
                  if (c.integrator == "clebsch_midpoint") c.energy = true;
              });

}  // namespace mutants_canonical_claims
}  // namespace gm
