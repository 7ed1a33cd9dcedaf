// Negative controls for the dynamic and variational properties and for the integrator claims:
// the mistakes people make with the direction of a conjugation, the side of a multiplication, the
// sign of a commutator, the identification of g* with g, and claims an integrator does not keep.
#include "impl/integrators.hpp"
#include "impl/lie_algebras.hpp"
#include "impl/manakov.hpp"
#include "impl/momentum_map.hpp"
#include "impl/reconstruction.hpp"
#include "impl/reference_subject.hpp"
#include "tests/mutants/mutants.hpp"

#include <Eigen/LU>

namespace gm {
namespace mutants_dynamics {
namespace {

template <class T>
Integrator<T>* find_integrator(Subject<T>& s, const char* name) {
  for (auto& i : s.integrators)
    if (i.name == name) return &i;
  return nullptr;
}

// ad*_xi mu on sl(2, R) as a student reads Theorem 2.3 with the pairing (2.15): represent mu by
// the matrix M with <M, X> = (1/2) tr(M^T X) = mu . vee(X), take [M, hat(xi)], and read the
// result back as a covector through the same pairing.
template <class T>
VecX<T> ad_star_sl2_through_transpose_pairing(const VecX<T>& xi, const VecX<T>& mu) {
  const LieAlgebraId g = LieAlgebraId::sl2;
  MatX<T> G(3, 3);
  std::vector<MatX<T>> E;
  for (int k = 0; k < 3; ++k) {
    VecX<T> e = VecX<T>::Zero(3);
    e(k) = T(1);
    E.push_back(ref::lie_hat<T>(g, e));
  }
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) G(k, l) = (E[k].transpose() * E[l]).trace() / T(2);
  const VecX<T> m = G.fullPivLu().solve(mu);
  MatX<T> M = MatX<T>::Zero(2, 2);
  for (int k = 0; k < 3; ++k) M += m(k) * E[k];
  const MatX<T> R = ref::commutator(M, ref::lie_hat<T>(g, xi));
  VecX<T> out(3);
  for (int l = 0; l < 3; ++l) out(l) = (R.transpose() * E[l]).trace() / T(2);
  return out;
}

}  // namespace

GM_MUTANT(euler_3_8_second_component_sign, "(3.8) with the sign of the second component flipped", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_8 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> {
    Vec3<T> r = ref::euler_3_8<T>(I, P);
    r(1) = -r(1);
    return r;
  };
});

// The erratum of (2.30): the printed formula pi = O^-1 Pi O (as matrices) is hat(O^T Pi).
GM_MUTANT(spatial_momentum_as_printed_2_30,
          "spatial angular momentum as printed in (2.30), pi = O^-1 Pi O, i.e. pi = O^T Pi", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.spatial_momentum = [](const Mat3<T>& O, const Vec3<T>& Pi) -> Vec3<T> { return O.transpose() * Pi; };
          });

// inertia_space_inverted (I_space = O^-1 I O) is defined with the inertia mutants (inertia.cpp).

GM_MUTANT(reconstruction_hat_not_skew, "(2.10) with a sign slip in one entry of the hat matrix (not skew)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.reconstruction_2_10 = [](const Mat3<T>& O, const Vec3<T>& W) -> Mat3<T> {
              Mat3<T> H = ref::hat<T>(W);
              H(0, 1) = W(2);  // should be -W3
              return O * H;
            };
          });

GM_MUTANT(reconstruction_right_multiplied, "(2.10) written dO/dt = hat(Omega) O (body velocity used as spatial)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.reconstruction_2_10 = [](const Mat3<T>& O, const Vec3<T>& W) -> Mat3<T> { return ref::hat<T>(W) * O; };
          });

GM_MUTANT(ad_star_sign_flipped, "ad* with the opposite sign (the right-invariant sign of (1.1))", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
    return (-ref::ad_star<T>(g, xi, mu)).eval();
  };
});

// The literal reading of Theorem 2.3 / Remark 2.8 with the trace pairing (2.15): for sl(2, R)
// the transpose pairing is not ad-invariant, and this ad* is not the coadjoint action.
GM_MUTANT(ad_star_sl2_transpose_pairing,
          "ad* of sl(2,R) taken as [M, Omega] with M identified through the transpose pairing (2.15)", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
              if (g == LieAlgebraId::sl2) return ad_star_sl2_through_transpose_pairing<T>(xi, mu);
              return ref::ad_star<T>(g, xi, mu);
            };
          });

GM_MUTANT(clebsch_3_21_Q_sign, "(3.21) with dQ/dt = +Omega x Q", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.clebsch_3_21 = [](const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) -> Vec3Pair<T> {
    auto r = ref::clebsch_3_21<T>(I, Q, P);
    r.first = -r.first;
    return r;
  };
});

GM_MUTANT(manakov_2_34_one_sided, "(2.34) written dM/dt = M Omega (the -Omega M of the commutator lost)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_2_34 = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> {
    return (M * ref::manakov_Omega<T>(A, M)).eval();
  };
});

GM_MUTANT(manakov_commutator_reversed, "(2.34) written dM/dt = [Omega, M]", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_2_34 = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> { return (-ref::manakov_2_34<T>(A, M)).eval(); };
});

// The erratum of the closing exercise: Omega determined by the printed M = (P^T Q - Q^T P)/2.
GM_MUTANT(manakov_clebsch_M_as_printed, "closing exercise as printed: Omega from A Omega + Omega A = (P^T Q - Q^T P)/2",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.manakov_clebsch_3_23 = [](const MatX<T>& A, const MatX<T>& Q, const MatX<T>& P) -> MatXPair<T> {
              const MatX<T> W = ref::manakov_Omega<T>(A, ((P.transpose() * Q - Q.transpose() * P) / T(2)).eval());
              return {(Q * W).eval(), (P * W).eval()};
            };
          });

GM_MUTANT(manakov_clebsch_P_left_multiplied, "(3.23) with dP/dt = Omega P", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_clebsch_3_23 = [](const MatX<T>& A, const MatX<T>& Q, const MatX<T>& P) -> MatXPair<T> {
    auto r = ref::manakov_clebsch_3_23<T>(A, Q, P);
    const MatX<T> W = Q.transpose() * r.first;  // Omega = Q^-1 dQ/dt
    r.second = W * P;
    return r;
  };
});

// ---------------------------------------------------------------------------------------------
// Integrators that do not keep what they claim.

GM_MUTANT(splitting_lie_trotter,
          "Lie-Poisson splitting composed Lie-Trotter style, Phi1(h) Phi2(h) Phi3(h), still claiming order 2 and "
          "symmetry",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              if (auto* i = find_integrator(s, "lie_poisson_splitting"))
                i->rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
                  RigidBodyState<T> y = x;
                  for (int k = 0; k < 3; ++k) ref::axis_flow<T>(I, k, h, y);
                  return y;
                };
            }
          });

GM_MUTANT(
    midpoint_one_iteration,
    "implicit midpoint whose nonlinear solve stops after one fixed-point iteration (that is explicit "
    "Euler), still claiming the midpoint rule's order, symmetry and invariants",
    [](auto& s) {
      using T = scalar_of<decltype(s)>;
      if constexpr (!is_exact_v<T>) {
        if (auto* i = find_integrator(s, "implicit_midpoint")) {
          i->rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
            const Vec3<T> P = x.Pi + h / T(2) * ref::cross<T>(x.Pi, x.Pi.cwiseQuotient(I));
            return RigidBodyState<T>{(T(2) * P - x.Pi).eval(),
                                     (x.O * ref::cayley3<T>((h / T(2) * P.cwiseQuotient(I)).eval())).eval()};
          };
          i->manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
            const MatX<T> Mmid = x.M + h / T(2) * ref::commutator(x.M, ref::manakov_Omega<T>(A, x.M));
            const MatX<T> W = ref::manakov_Omega<T>(A, Mmid);
            return ManakovState<T>{(T(2) * Mmid - x.M).eval(), (x.O * ref::cayley_half<T>((h * W).eval())).eval()};
          };
        }
      }
    });

GM_MUTANT(manakov_isospectral_explicit,
          "isospectral Cayley step with U = cay(h Omega(M_n)) (explicit, order 1), still claiming order 2, symmetry "
          "and energy",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              if (auto* i = find_integrator(s, "isospectral_cayley"))
                i->manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
                  const MatX<T> U = ref::cayley_half<T>((h * ref::manakov_Omega<T>(A, x.M)).eval());
                  const MatX<T> N = U.transpose() * x.M * U;
                  return ManakovState<T>{((N - N.transpose()) / T(2)).eval(), (x.O * U).eval()};
                };
            }
          });

// The negative control for the Manakov step's own equation: the implicit midpoint rule of
// dM/dt = [Omega, M], the commutator of (2.36) reversed (its M is the reference step's taken with
// -h), the attitude still turned by dO/dt = O Omega. A midpoint rule, so it keeps tr(M^2), the
// energy and O^T O; of the midpoint's claims only the order is false, and the failure must say why:
// "your step follows dM/dt = [Omega, M] ... (2.36) is [M, Omega]" (tests/step_field_tests.cpp).
GM_MUTANT(manakov_midpoint_commutator_reversed,
          "a Manakov midpoint step whose own right-hand side has the commutator of (2.36) reversed, "
          "dM/dt = [Omega, M], still claiming order 2",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              if (auto* i = find_integrator(s, "implicit_midpoint"))
                i->manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
                  return ManakovState<T>{ref::manakov_implicit_midpoint_step<T>(A, x, T(-h)).M,
                                         ref::manakov_implicit_midpoint_step<T>(A, x, h).O};
                };
            }
          });

GM_MUTANT_SET(rk4_claims_everything,
              "classical RK4 claiming symmetry, the Casimir, the energy, orthogonality, the spectrum and the Poisson "
              "property",
              [](SubjectSet& s) {
                for (auto& c : s.claims)
                  if (c.integrator == "rk4") {
                    c.symmetric = c.casimir = c.energy = c.orthogonality = c.spectrum = c.poisson = true;
                  }
              });

}  // namespace mutants_dynamics
}  // namespace gm
