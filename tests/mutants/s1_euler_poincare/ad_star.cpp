// Negative controls for ad* in coordinates (section 1) and the so(4) = R^6 slots.
#include "impl/lie_algebras.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_ad_star {

GM_MUTANT(ad_star_is_ad, "ad*_xi mu computed as ad_xi mu = [xi, mu] (coadjoint confused with adjoint)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
    return ref::lie_bracket<T>(g, xi, mu);
  };
});

// Right for so(3) and so(4) in orthonormal coordinates (an ad-invariant inner product), wrong for
// the non-compact sl(2, R).
GM_MUTANT(ad_star_minus_ad, "ad*_xi mu computed as -[xi, mu] (true only for compact algebras, not sl(2,R))",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
              return -ref::lie_bracket<T>(g, xi, mu);
            };
          });

GM_MUTANT(ad_star_transposed_structure_constants, "(ad*_xi mu)_k = xi^j mu_i c^i_kj (lower indices swapped)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
              const int d = ref::lie_dim(g);
              const auto c = ref::structure_constants<T>(g);
              VecX<T> out = VecX<T>::Zero(d);
              for (int k = 0; k < d; ++k)
                for (int j = 0; j < d; ++j)
                  for (int i = 0; i < d; ++i) out(k) += xi(j) * mu(i) * c[i][k][j];
              return out;
            };
          });

GM_MUTANT(ad_star_so4_R6_sign_slip, "so(4) ad* in R^6 with mu_u x xi_v - mu_v x xi_u in the second half", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.ad_star_so4_R6 = [](const Vec6<T>& xi, const Vec6<T>& mu) -> Vec6<T> {
    Vec6<T> out = ref::ad_star_so4_R6<T>(xi, mu);
    const Vec3<T> xu = xi.template head<3>(), xv = xi.template tail<3>();
    const Vec3<T> mu_u = mu.template head<3>(), mu_v = mu.template tail<3>();
    out.template tail<3>() = ref::cross<T>(mu_u, xv) - ref::cross<T>(mu_v, xu);
    return out;
  };
});

GM_MUTANT(so4_bracket_R6_sign_slip, "so(4) bracket in R^6 with u1 x v2 + u2 x v1 in the second half", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.so4_bracket_R6 = [](const Vec6<T>& a, const Vec6<T>& b) -> Vec6<T> {
    Vec6<T> out = ref::so4_bracket_R6<T>(a, b);
    const Vec3<T> u1 = a.template head<3>(), v1 = a.template tail<3>();
    const Vec3<T> u2 = b.template head<3>(), v2 = b.template tail<3>();
    out.template tail<3>() = ref::cross<T>(u1, v2) + ref::cross<T>(u2, v1);
    return out;
  };
});

}  // namespace mutants_ad_star
}  // namespace gm

namespace gm {
namespace mutants_ad_star {

// sl(2, R) read with b and c exchanged: [[a, c], [b, -a]] (a transposed convention); right on
// so(3) and so(4), wrong only on the third algebra.
GM_MUTANT(lie_hat_sl2_transposed, "lie_hat for sl(2, R) building [[a, c], [b, -a]] (transposed)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lie_hat = [](LieAlgebraId g, const VecX<T>& x) -> MatX<T> {
    const MatX<T> m = ref::lie_hat<T>(g, x);
    return g == LieAlgebraId::sl2 ? MatX<T>(m.transpose()) : m;
  };
});

// sl(2, R) with the sign of the last diagonal entry lost: [[a, b], [c, a]] is not traceless, so
// not in sl(2, R) whatever the basis (the basis itself is the student's choice, and the
// transposed one above is a basis; it fails only beside a lie_vee that reads the documented one).
GM_MUTANT(lie_hat_sl2_not_traceless, "lie_hat for sl(2, R) building [[a, b], [c, a]] (not traceless)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lie_hat = [](LieAlgebraId g, const VecX<T>& x) -> MatX<T> {
    MatX<T> m = ref::lie_hat<T>(g, x);
    if (g == LieAlgebraId::sl2) m(1, 1) = -m(1, 1);
    return m;
  };
});

GM_MUTANT(lie_vee_sl2_transposed, "lie_vee for sl(2, R) reading (m00, m10, m01) (transposed)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lie_vee = [](LieAlgebraId g, const MatX<T>& m) -> VecX<T> {
    return g == LieAlgebraId::sl2 ? ref::lie_vee<T>(g, MatX<T>(m.transpose())) : ref::lie_vee<T>(g, m);
  };
});

// Remark 3.2 needs the bracket of a Lie algebra: ad* built from constants that are skew in their
// lower indices but break the Jacobi identity: [e_0, e_1] gains an extra e_0 component
// (c^0_01 = 1, c^0_10 = -1). On so(3): [e_1, [e_2, e_3]] + ... = [e_3, e_1] = e_2 != 0 in the
// notes' numbering. The Lie-Poisson bracket (3.10) built from it is still bilinear, skew and
// Leibniz, and fails only Jacobi (3.2).
GM_MUTANT(ad_star_not_a_lie_algebra,
          "ad* from structure constants with an extra c^0_01 = 1 (skew, but no Jacobi identity)", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.ad_star = [](LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) -> VecX<T> {
              VecX<T> out = ref::ad_star<T>(g, xi, mu);
              out(1) += xi(0) * mu(0);  // c^0_01 = 1: k = 1, j = 0, i = 0
              out(0) -= xi(1) * mu(0);  // c^0_10 = -1: k = 0, j = 1, i = 0
              return out;
            };
          });

}  // namespace mutants_ad_star
}  // namespace gm
