// Negative controls for Nambu's R^3 bracket (3.13), its motion (3.14), the system (3.16) and the
// rigid body's level sets (section 3.4), including the two literal variants of printed errata.
#include "impl/brackets.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_nambu {

GM_MUTANT(nambu_3_13_sign_flipped, "(3.13) written {f, h} = +grad c . grad f x grad h", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.nambu_3_13 = [](const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) -> T {
    return -ref::nambu_3_13<T>(dc, df, dh);
  };
});

// -(C grad c) . df x dh with C a cyclic permutation: a bracket -w . df x dh is Poisson only when
// w . curl w = 0, and w = C grad c is not a gradient (curl w != 0 for generic c).
GM_MUTANT(nambu_3_13_cyclic_index_slip, "(3.13) with grad c read as (c_2, c_3, c_1) (an index slip)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.nambu_3_13 = [](const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) -> T {
    return ref::nambu_3_13<T>(Vec3<T>(dc(1), dc(2), dc(0)), df, dh);
  };
});

GM_MUTANT(nambu_3_13_affine_in_df, "(3.13) plus a term without f, grad c . grad h (not linear in f)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.nambu_3_13 = [](const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) -> T {
    return ref::nambu_3_13<T>(dc, df, dh) + dc.dot(dh);
  };
});

GM_MUTANT(nambu_3_13_with_symmetric_part, "(3.13) plus a symmetric term grad f . grad h: not skew", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.nambu_3_13 = [](const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) -> T {
    return ref::nambu_3_13<T>(dc, df, dh) + df.dot(dh);
  };
});

GM_MUTANT(nambu_motion_3_14_reversed, "(3.14) written dx/dt = grad h x grad c", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.nambu_motion_3_14 = [](const Vec3<T>& dc, const Vec3<T>& dh) -> Vec3<T> {
    return ref::nambu_motion_3_14<T>(dh, dc);
  };
});

GM_MUTANT(nambu_motion_3_14_half_cross,
          "(3.14) with only the first product of each component of grad c x grad h (a typo in the cross product)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.nambu_motion_3_14 = [](const Vec3<T>& a, const Vec3<T>& b) -> Vec3<T> {
              return Vec3<T>(a(1) * b(2), a(2) * b(0), a(0) * b(1));
            };
          });

// Literal variant of the answer to the (3.16) exercise: the motion the printed answer produces,
// (1/4) grad(a1 x1^2 + a3 x3^2) x grad(a2 x2^2 + a3 x3^2) = (-a2 a3 x2 x3, -a1 a3 x3 x1, a1 a2 x1 x2).
GM_MUTANT(nambu_3_16_as_printed_answer,
          "(3.16) taken from its printed answer (1/4) grad(a1 x1^2 + a3 x3^2) x grad(a2 x2^2 + a3 x3^2)", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.nambu_3_16 = [](const Vec3<T>& a, const Vec3<T>& x) -> Vec3<T> {
              const Vec3<T> dA(T(2) * a(0) * x(0), T(0), T(2) * a(2) * x(2));
              const Vec3<T> dB(T(0), T(2) * a(1) * x(1), T(2) * a(2) * x(2));
              return (ref::cross<T>(dA, dB) / T(4)).eval();
            };
          });

// Literal variant of section 3.4: "energy ellipsoids h = x . I x".
GM_MUTANT(energy_ellipsoid_x_I_x, "the rigid-body energy taken as h = x . I x, as printed in section 3.4", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hamiltonian_3_4 = [](const Vec3<T>& I, const Vec3<T>& x) -> T { return x.dot(I.cwiseProduct(x)); };
});

}  // namespace mutants_nambu
}  // namespace gm
