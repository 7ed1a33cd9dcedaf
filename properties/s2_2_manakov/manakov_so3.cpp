// Manakov's equations (2.34) for n = 3: with A = diag(a1, a2, a3), M = A Omega + Omega A is
// hat(I Omega) with I1 = a2 + a3, I2 = a3 + a1, I3 = a1 + a2; dM/dt = [M, Omega] is Euler's equation
// (3.8) read through the hat map; and l = -(1/2) tr(Omega A Omega) is the kinetic energy (2.5).
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_manakov_so3 {
namespace {

// Sizes: |a| |Omega| for M (2 roundings); |a| |Omega|^2 for dM/dt and l (Omega recovered from M by a
// division, then a commutator: ~8; (3.8): ~5) with small constant factors from the sums.
template <class T>
void manakov_so3_is_euler(const Subject<T>& s) {
  const Vec3<T> a = *gen::inertia<T>().as("a");  // positive entries
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const MatX<T> A = MatX<T>(a.asDiagonal());
  const MatX<T> W_hat = truth::skew_of(W);
  const Vec3<T> I(a(1) + a(2), a(2) + a(0), a(0) + a(1));
  const Vec3<T> Pi = I.cwiseProduct(W);
  const T scale = T(8) * norm_inf(a) * (norm_inf(W) + T(1)) * (norm_inf(W) + T(1));
  const MatX<T> M = s.manakov_M(A, W_hat);
  require_close("n = 3: M = A Omega + Omega A = hat(I Omega), I1 = a2 + a3 (cyclically)", M,
                MatX<T>(truth::skew_of(Pi)), scale, 4);
  const MatX<T> M_dot = s.manakov_2_34(A, M);
  require_close("n = 3: dM/dt = [M, Omega] is hat(Pi x Omega)", M_dot, MatX<T>(truth::skew_of(truth::cross(Pi, W))),
                scale, 16);
  require_close("n = 3: dM/dt = [M, Omega] is Euler's equation (3.8)", M_dot,
                MatX<T>(truth::skew_of(s.euler_3_8(I, Pi))), scale, 24);
  const T l = s.manakov_lagrangian(A, W_hat);
  require_close("n = 3: -(1/2) tr(Omega A Omega) = (1/2) sum I_i Omega_i^2", l,
                T((I(0) * W(0) * W(0) + I(1) * W(1) * W(1) + I(2) * W(2) * W(2)) / T(2)), scale, 16);
  require_close("n = 3: -(1/2) tr(Omega A Omega) is the Lagrangian (2.5)", l, s.lagrangian_2_5(I, W), scale, 16);
}

}  // namespace

GM_PROPERTY(
    manakov_so3_is_euler, all_scalars,
    {.spec = "s2.manakov-so3",
     .title = "(2.34) for n = 3: M = hat(I Omega) with I1 = a2 + a3 etc., dM/dt = [M, Omega] is (3.8), l is (2.5)",
     .tolerance = ToleranceClass::Exact,
     .needs = {"manakov_M", "manakov_2_34", "manakov_lagrangian", "euler_3_8", "lagrangian_2_5"},
     .negative_controls = {"manakov_2_34_commutator_reversed", "manakov_lagrangian_sign_flipped",
                           "manakov_M_one_sided"}});

}  // namespace properties_manakov_so3
}  // namespace gm
