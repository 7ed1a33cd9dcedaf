// Negative controls for two integrator checks that judge behaviour, not formulas: the domain check
// (properties/integrators/integrator_domain.cpp) and the long-time energy told apart by its trend
// (properties/integrators/support/long_time.hpp).
#include "impl/integrators.hpp"
#include "impl/reference_subject.hpp"
#include "tests/mutants/mutants.hpp"

#include <stdexcept>

namespace gm {
namespace mutants_verdict_claims {

// The implicit midpoint rule of an engine that refuses fast states: it raises for |Omega| >= 2^20
// (rigid body) or a state larger than 2^20 (Manakov), and declares no domain.
struct RaisesWhenFast {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      for (auto& i : s.integrators)
        if (i.name == "implicit_midpoint") {
          i.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
            if (max_abs(Vec3<T>(x.Pi.cwiseQuotient(I))) >= T(1 << 20))
              throw std::runtime_error("angular velocity out of range");
            return ref::implicit_midpoint_step<T>(I, x, h);
          };
          i.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
            if (max_abs(x.M) >= T(1 << 20)) throw std::runtime_error("state out of range");
            return ref::manakov_implicit_midpoint_step<T>(A, x, h);
          };
        }
    }
  }
};

GM_MUTANT(midpoint_raises_when_fast,
          "the implicit midpoint rule raising for fast states (|Omega| >= 2^20), as an engine that resets above a "
          "limit does, without declaring a domain",
          [](auto& s) { RaisesWhenFast{}(s); });

// Backward Euler, x' = x + h f(x') (a fixed-point iteration to round-off), added to the subject and
// claiming bounded long-time energy: it loses energy at every step (it is dissipative), however
// early the loss levels off.
struct AddBackwardEuler {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      Integrator<T> e;
      e.name = "backward_euler";
      e.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
        RigidBodyState<T> y = x;
        for (int it = 0; it < 400; ++it) {
          const RigidBodyState<T> d = ref::rigid_body_field<T>(I, y);
          const RigidBodyState<T> again{(x.Pi + h * d.Pi).eval(), (x.O + h * d.O).eval()};
          const T change = std::max(max_abs(Vec3<T>(again.Pi - y.Pi)), max_abs(Mat3<T>(again.O - y.O)));
          y = again;
          if (change <= T(8) * eps<T>() * std::max(T(1), max_abs(x.Pi))) break;
        }
        return y;
      };
      e.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) {
        ManakovState<T> y = x;
        for (int it = 0; it < 400; ++it) {
          const ManakovState<T> d = ref::manakov_field<T>(A, y);
          const ManakovState<T> again{(x.M + h * d.M).eval(), (x.O + h * d.O).eval()};
          const T change = std::max(max_abs(MatX<T>(again.M - y.M)), max_abs(MatX<T>(again.O - y.O)));
          y = again;
          if (change <= T(8) * eps<T>() * std::max(T(1), max_abs(x.M))) break;
        }
        return y;
      };
      s.integrators.push_back(std::move(e));
    }
  }
};

GM_MUTANT_SET(backward_euler_claims_bounded_energy,
              "backward Euler added to the subject, claiming bounded long-time energy (it loses energy at every step)",
              [](SubjectSet& s) {
                s = mutate(s, s.name, s.description, AddBackwardEuler{});
                s.claims.push_back({.integrator = "backward_euler", .bounded_energy = true});
              });

}  // namespace mutants_verdict_claims
}  // namespace gm
