// Negative controls for the structural claims of integrators (properties/integrators/integrator_structure.cpp):
// Noether, equivariance, bounded long-time energy.
#include "impl/integrators.hpp"
#include "impl/reference_subject.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_structure_claims {

// The implicit midpoint rule with the attitude updated on the wrong side: O_{n+1} = U O_n with
// U = cay((h/2) Omega_mid), the body angular velocity used as if it were the spatial one
// (dO/dt = hat(Omega) O instead of O hat(Omega), the mistake of reconstruction_right_multiplied in
// a step). It keeps O orthogonal and the Pi-part is untouched, but step(Pi, R O) = (Pi', U R O)
// is not R U O: the step no longer commutes with the left action, and O Pi is no longer kept.
// Its author keeps the midpoint rule's claims (equivariance included) and, having read that the
// midpoint rule keeps quadratic invariants, adds Noether.
struct SpaceFrameAttitude {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      for (auto& i : s.integrators)
        if (i.name == "implicit_midpoint") {
          i.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
            const RigidBodyState<T> y =
                ref::implicit_midpoint_step<T>(I, RigidBodyState<T>{x.Pi, Mat3<T>::Identity()}, h);
            return RigidBodyState<T>{y.Pi, (y.O * x.O).eval()};
          };
          i.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
            const auto n = x.O.rows();
            const ManakovState<T> y =
                ref::manakov_implicit_midpoint_step<T>(A, ManakovState<T>{x.M, MatX<T>::Identity(n, n)}, h);
            return ManakovState<T>{y.M, (y.O * x.O).eval()};
          };
        }
    }
  }
};

GM_MUTANT_SET(midpoint_space_frame_attitude,
              "implicit midpoint with the attitude updated from the left, O <- cay(h Omega_mid) O (body velocity used "
              "as spatial), still claiming equivariance, and Noether",
              [](SubjectSet& s) {
                s = mutate(s, s.name, s.description, SpaceFrameAttitude{});
                for (auto& c : s.claims)
                  if (c.integrator == "implicit_midpoint") c.noether = c.equivariant = true;
              });

// Classical RK4 claiming Noether: it keeps no quadratic invariant exactly, O Pi included.
GM_MUTANT_SET(rk4_claims_noether, "classical RK4 claiming Noether (the spatial momentum O Pi, O M O^T kept)",
              [](SubjectSet& s) {
                for (auto& c : s.claims)
                  if (c.integrator == "rk4") c.noether = true;
              });

// Explicit Euler, x <- x + h f(x), added to the subject and claiming bounded long-time energy.
// Each step multiplies |Pi|^2 by 1 + h^2 |Omega_perp|^2 > 1 (Pi x Omega is orthogonal to Pi), so
// the Casimir and with it the energy grow without bound. (RK4 is not used here: at h = 1/8 or 1/4 its
// energy drift on the rigid body can stay below 1e-11 over 10^5 steps for some states, too small
// to be told from an oscillation in every case and scalar; the report still classifies it.)
struct AddExplicitEuler {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      Integrator<T> e;
      e.name = "explicit_euler";
      e.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
        const RigidBodyState<T> d = ref::rigid_body_field<T>(I, x);
        return RigidBodyState<T>{(x.Pi + h * d.Pi).eval(), (x.O + h * d.O).eval()};
      };
      e.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
        const ManakovState<T> d = ref::manakov_field<T>(A, x);
        return ManakovState<T>{(x.M + h * d.M).eval(), (x.O + h * d.O).eval()};
      };
      s.integrators.push_back(std::move(e));
    }
  }
};

GM_MUTANT_SET(explicit_euler_claims_bounded_energy,
              "explicit Euler added to the subject, claiming bounded long-time energy (its energy grows without bound)",
              [](SubjectSet& s) {
                s = mutate(s, s.name, s.description, AddExplicitEuler{});
                s.claims.push_back({.integrator = "explicit_euler", .bounded_energy = true});
              });

}  // namespace mutants_structure_claims
}  // namespace gm
