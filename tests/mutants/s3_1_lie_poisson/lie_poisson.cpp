// Negative controls for the Lie-Poisson bracket in its R^3 form (3.6) and its matrix form
// (2.23)/(3.10): sign and index slips, a wrong product, and brackets that are still bilinear-looking
// but fail one axiom of Definition 3.3.
#include "impl/brackets.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_lie_poisson {

GM_MUTANT(lie_poisson_3_6_sign_flipped, "(3.6) written {f, h} = +Pi . df x dh", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lie_poisson_3_6 = [](const Vec3<T>& P, const Vec3<T>& df, const Vec3<T>& dh) -> T {
    return -ref::lie_poisson_3_6<T>(P, df, dh);
  };
});

// Pi read with a cyclic index slip, (Pi2, Pi3, Pi1): the bracket -(M Pi) . df x dh with M a cyclic
// permutation, which is not symmetric; a linear bracket of this form is Poisson only when
// (M + M^T) a = 0 for the axis a of M - M^T, which fails here. Still bilinear, skew and Leibniz.
GM_MUTANT(lie_poisson_3_6_cyclic_index_slip, "(3.6) evaluated with Pi read as (Pi2, Pi3, Pi1) (an index slip)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_3_6 = [](const Vec3<T>& P, const Vec3<T>& df, const Vec3<T>& dh) -> T {
              return ref::lie_poisson_3_6<T>(Vec3<T>(P(1), P(2), P(0)), df, dh);
            };
          });

GM_MUTANT(lie_poisson_3_6_affine_in_df,
          "(3.6) with a term that does not involve f, {f, h} = -Pi . df x dh + Pi . dh (not linear in f)", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_3_6 = [](const Vec3<T>& P, const Vec3<T>& df, const Vec3<T>& dh) -> T {
              return ref::lie_poisson_3_6<T>(P, df, dh) + P.dot(dh);
            };
          });

GM_MUTANT(lie_poisson_3_6_with_symmetric_part,
          "(3.6) plus a symmetric (metriplectic-like) term df . dh: bilinear and Leibniz, not skew", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_3_6 = [](const Vec3<T>& P, const Vec3<T>& df, const Vec3<T>& dh) -> T {
              return ref::lie_poisson_3_6<T>(P, df, dh) + df.dot(dh);
            };
          });

GM_MUTANT(lie_poisson_2_23_one_sided_product,
          "(2.23) with the product df dh in place of the commutator [df, dh] (half of the bracket survives)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_2_23 = [](const Mat3<T>& P, const Mat3<T>& df, const Mat3<T>& dh) -> T {
              return -ref::pairing3<T>(P, (df * dh).eval());
            };
          });

GM_MUTANT(lie_poisson_2_23_cyclic_index_slip,
          "(2.23) evaluated at C Pi_hat C^T, C the cyclic permutation (Pi read as (Pi2, Pi3, Pi1))", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_2_23 = [](const Mat3<T>& P, const Mat3<T>& df, const Mat3<T>& dh) -> T {
              Mat3<T> C = Mat3<T>::Zero();
              C(0, 1) = T(1);
              C(1, 2) = T(1);
              C(2, 0) = T(1);
              return ref::lie_poisson_2_23<T>((C * P * C.transpose()).eval(), df, dh);
            };
          });

GM_MUTANT(lie_poisson_2_23_affine_in_df,
          "(2.23) with a term that does not involve f, -<Pi, [df, dh]> + <Pi, dh> (not linear in f)", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_2_23 = [](const Mat3<T>& P, const Mat3<T>& df, const Mat3<T>& dh) -> T {
              return ref::lie_poisson_2_23<T>(P, df, dh) + ref::pairing3<T>(P, dh);
            };
          });

GM_MUTANT(lie_poisson_2_23_with_symmetric_part, "(2.23) plus a symmetric term <df, dh>: bilinear and Leibniz, not skew",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lie_poisson_2_23 = [](const Mat3<T>& P, const Mat3<T>& df, const Mat3<T>& dh) -> T {
              return ref::lie_poisson_2_23<T>(P, df, dh) + ref::pairing3<T>(df, dh);
            };
          });

}  // namespace mutants_lie_poisson
}  // namespace gm

namespace gm {
namespace mutants_lie_poisson {

// Minus a Poisson bracket is a Poisson bracket: bilinearity, skew-symmetry, Leibniz and Jacobi
// all hold for it, so only the comparison with (2.23) itself (definition_lie_poisson_2_23) sees it.
GM_MUTANT(lie_poisson_2_23_sign_flipped, "(2.23) written {f, h} = +<Pi, [df, dh]>", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lie_poisson_2_23 = [](const Mat3<T>& P, const Mat3<T>& F, const Mat3<T>& H) -> T {
    return -ref::lie_poisson_2_23<T>(P, F, H);
  };
});

}  // namespace mutants_lie_poisson
}  // namespace gm
