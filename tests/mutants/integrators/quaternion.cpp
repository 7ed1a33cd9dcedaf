// Negative controls for an integrator that keeps its attitude as a quaternion (core/state_form.hpp,
// properties/integrators/integrator_quaternion.cpp).
#include "core/declared_step.hpp"
#include "impl/integrators.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_quaternion {

// Explicit Euler as engines first write it, in "quaternion_wxyz Omega": Omega <- Omega + h I^-1 (I
// Omega x Omega) (2.2), q <- q + (h/2) q (0, Omega) (the body-side rate), and no renormalisation:
// each step multiplies |q|^2 by 1 + h^2 |Omega|^2 / 4, so the quaternion's norm grows. Its author
// claims unit_quaternion, having read that unit quaternions represent rotations.
struct AddQuaternionEuler {
  template <class S>
  void operator()(S& s) const {
    using T = scalar_of<S>;
    if constexpr (!is_exact_v<T>) {
      Integrator<T> e;
      e.name = "quaternion_euler";
      e.form = parse_state_form("quaternion_wxyz Omega");
      e.declared_step = [](const Vec3<T>& I, const EngineState<T>& x, const T& h) {
        EngineState<T> y = x;
        const Vec3<T> L = I.cwiseProduct(x.Omega);
        y.Omega = x.Omega + h * Vec3<T>(L.cross(x.Omega).cwiseQuotient(I));
        const Vec4<T> rate = ref::quaternion_product<T>(x.q, Vec4<T>(T(0), x.Omega(0), x.Omega(1), x.Omega(2)));
        y.q = x.q + (h / T(2)) * rate;
        return y;
      };
      adapt_declared_step(e);
      s.integrators.push_back(std::move(e));
    }
  }
};

GM_MUTANT_SET(quaternion_euler_claims_unit_norm,
              "explicit Euler keeping a quaternion (w, x, y, z) and the body Omega, never renormalised, claiming "
              "unit_quaternion",
              [](SubjectSet& s) {
                s = mutate(s, s.name, s.description, AddQuaternionEuler{});
                IntegratorClaims c;
                c.integrator = "quaternion_euler";
                c.order = 1;
                c.unit_quaternion = true;
                s.claims.push_back(c);
              });

}  // namespace mutants_quaternion
}  // namespace gm
