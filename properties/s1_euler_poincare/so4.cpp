// Exercise [Motion on SO(4)]: the analogue of the hat map identifies so(4) with R^6 as Lie
// algebras, with the pairing (2.15) becoming the dot product; and the Euler-Poincare equation of
// the free SO(4) rigid body in R^6 vector form, dmu/dt = ad*_Omega mu, is the matrix form
// dM/dt = [M, Omega] (Manakov's M = A Omega + Omega A, (2.34)) read through that hat map.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_so4 {
namespace {

// hat([a, b]_R6) = [hat(a), hat(b)], vee inverts hat, hat(a) is skew, <hat(a), hat(b)> = a . b.
// Sizes: commutator entries are sums of 8 products of |a| |b| (k = 8 with the right-hand side's own
// cross products); the pairing sums 16 products (k = 18).
template <class T>
void so4_hat_is_lie_algebra_isomorphism(const Subject<T>& s) {
  const VecX<T> a = *gen::vec<T>(6).as("a");
  const VecX<T> b = *gen::vec<T>(6).as("b");
  const MatX<T> A = s.hat_n(a, 4), B = s.hat_n(b, 4);
  const T ab = norm_inf(a) * norm_inf(b);
  require_close("so(4): hat(a) is skew", MatX<T>(A.transpose()), MatX<T>(-A), norm_inf(a), 0);
  require_close("so(4): vee(hat(a)) = a", s.vee_n(A), a, norm_inf(a), 0);
  require_close("so(4): [hat(a), hat(b)] = hat([a, b]_R6)", MatX<T>(A * B - B * A),
                s.hat_n(VecX<T>(s.so4_bracket_R6(Vec6<T>(a), Vec6<T>(b))), 4), T(T(8) * ab), 8);
  require_close("so(4): <hat(a), hat(b)> = a . b (the pairing (2.15) is the dot product of R^6)", s.pairing(A, B),
                T(a.dot(b)), T(T(16) * ab), 18);
}

// A = diag(a) with a > 0 (so Omega is recovered from M = A Omega + Omega A by division),
// Omega in R^6: dM/dt = [M, Omega] (the subject's Manakov right-hand side) read in R^6 is
// ad*_Omega mu with mu = vee(M). Sizes: |M| <= 2 |a| |Omega|, |[M, Omega]| <= 8 |M| |Omega|.
template <class T>
void so4_euler_poincare_R6(const Subject<T>& s) {
  const Vec3<T> a3 = *gen::inertia<T>().as("a3");
  const T a4 = *gen::positive<T>(64, 2).as("a4");
  VecX<T> a(4);
  a << a3(0), a3(1), a3(2), a4;
  const MatX<T> A = MatX<T>(a.asDiagonal());
  const VecX<T> W = *gen::vec<T>(6).as("Omega");
  const MatX<T> W_hat = s.hat_n(W, 4);
  const MatX<T> M = s.manakov_M(A, W_hat);
  const VecX<T> mu = s.vee_n(M);
  const MatX<T> M_dot = s.manakov_2_34(A, M);
  const T scale = T(16) * norm_inf(a) * norm_inf(W) * norm_inf(W);
  require_close("SO(4): the matrix Euler-Poincare equation dM/dt = [M, Omega]", M_dot, MatX<T>(M * W_hat - W_hat * M),
                scale, 16);
  require_close("SO(4): in R^6, dmu/dt = ad*_Omega mu with mu = vee(M)", s.vee_n(M_dot),
                VecX<T>(s.ad_star_so4_R6(Vec6<T>(W), Vec6<T>(mu))), scale, 16);
}

}  // namespace

GM_PROPERTY(so4_hat_is_lie_algebra_isomorphism, all_scalars,
            {.spec = "s1.so4-hat",
             .title = "so(4) = R^6: hat([a, b]) = [hat(a), hat(b)], vee inverts hat, (2.15) is the dot product",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hat_n", "vee_n", "so4_bracket_R6", "pairing"},
             .negative_controls = {"so4_bracket_R6_sign_slip"}});

GM_PROPERTY(so4_euler_poincare_R6, all_scalars,
            {.spec = "s1.so4-ep-r6",
             .title = "SO(4): dmu/dt = ad*_Omega mu in R^6 is dM/dt = [M, Omega], M = A Omega + Omega A",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hat_n", "vee_n", "manakov_M", "manakov_2_34", "ad_star_so4_R6"},
             .negative_controls = {"ad_star_so4_R6_sign_slip", "manakov_2_34_commutator_reversed"}});

}  // namespace properties_so4
}  // namespace gm
