// Negative controls for the momentum map J = p x q and the Clebsch equations (3.21).
#include "impl/momentum_map.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_momentum_map {

GM_MUTANT(momentum_map_reversed, "momentum map written J = q x p", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.momentum_map = [](const Vec3<T>& q, const Vec3<T>& p) -> Vec3<T> { return ref::cross<T>(q, p); };
});

GM_MUTANT(momentum_map_sign_slip, "J = p x q with a sign slip in its third component (not equivariant)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.momentum_map = [](const Vec3<T>& q, const Vec3<T>& p) -> Vec3<T> {
    Vec3<T> J = ref::momentum_map<T>(q, p);
    J(2) = -J(2);
    return J;
  };
});

GM_MUTANT(clebsch_3_21_sign_flipped, "(3.21) written dQ/dt = +Omega x Q, dP/dt = +Omega x P", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.clebsch_3_21 = [](const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) -> Vec3Pair<T> {
    const auto [dQ, dP] = ref::clebsch_3_21<T>(I, Q, P);
    return {(-dQ).eval(), (-dP).eval()};
  };
});

GM_MUTANT(clebsch_3_21_Pi_for_Omega, "(3.21) with Omega replaced by Pi = P x Q (I^-1 forgotten)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.clebsch_3_21 = [](const Vec3<T>&, const Vec3<T>& Q, const Vec3<T>& P) -> Vec3Pair<T> {
    const Vec3<T> Pi = ref::cross<T>(P, Q);
    return {(-ref::cross<T>(Pi, Q)).eval(), (-ref::cross<T>(Pi, P)).eval()};
  };
});

}  // namespace mutants_momentum_map
}  // namespace gm
