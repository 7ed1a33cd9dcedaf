// Negative controls for the hat map, the trace pairing and Euler's equations: the mistakes people
// actually make with conventions, signs and factors.
#include "impl/energy.hpp"
#include "impl/euler.hpp"
#include "impl/so3.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_so3_and_euler {

GM_MUTANT(hat_transposed, "hat map with the transposed convention, hat(v) w = w x v", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hat = [](const Vec3<T>& v) -> Mat3<T> { return ref::hat<T>(v).transpose(); };
});

GM_MUTANT(hat_scaled, "hat map with a stray factor 2 (hat(v) w = 2 v x w)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hat = [](const Vec3<T>& v) -> Mat3<T> { return (T(2) * ref::hat<T>(v)).eval(); };
});

GM_MUTANT(vee_reads_upper_triangle, "vee reading the entries above the diagonal (a sign error)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.vee = [](const Mat3<T>& m) -> Vec3<T> { return Vec3<T>(m(1, 2), m(2, 0), m(0, 1)); };
});

GM_MUTANT(pairing_without_half, "trace pairing without the factor 1/2 of (2.15)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.pairing = [](const MatX<T>& a, const MatX<T>& b) -> T { return (a.transpose() * b).trace(); };
});

GM_MUTANT(euler_2_1_sign_error, "(2.1) with (I3 - I2) in the first component", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_2_1 = [](const Vec3<T>& I, const Vec3<T>& W) -> Vec3<T> {
    Vec3<T> r = ref::euler_2_1<T>(I, W);
    r(0) = -r(0);
    return r;
  };
});

GM_MUTANT(euler_2_1_missing_division, "(2.1) returning I dOmega/dt instead of dOmega/dt", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_2_1 = [](const Vec3<T>& I, const Vec3<T>& W) -> Vec3<T> { return ref::euler_2_1<T>(I, W).cwiseProduct(I); };
});

GM_MUTANT(euler_2_2_cross_reversed, "(2.2) written I dOmega/dt = Omega x I Omega", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_2_2 = [](const Vec3<T>& I, const Vec3<T>& W) -> Vec3<T> { return (-ref::euler_2_2<T>(I, W)).eval(); };
});

GM_MUTANT(euler_3_7_index_slip, "(3.7) with 1/I1 - 1/I2 in the second component", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_7 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> {
    Vec3<T> r = ref::euler_3_7<T>(I, P);
    r(1) = (T(1) / I(0) - T(1) / I(1)) * P(2) * P(0);
    return r;
  };
});

GM_MUTANT(euler_3_8_cross_reversed, "(3.8) written dPi/dt = I^-1 Pi x Pi", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_8 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> { return ref::cross<T>(P.cwiseQuotient(I), P); };
});

GM_MUTANT(euler_3_8_I_not_inverted, "(3.8) written dPi/dt = Pi x I Pi", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_8 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> { return ref::cross<T>(P, I.cwiseProduct(P)); };
});

GM_MUTANT(euler_matrix_commutator_sign, "(2.12) written dPi/dt = +[Omega_hat, Pi]", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_matrix_2_12 = [](const Vec3<T>& I, const Mat3<T>& Pi) -> Mat3<T> {
    return (-ref::euler_matrix_2_12<T>(I, Pi)).eval();
  };
});

GM_MUTANT(lagrangian_missing_half, "kinetic energy without the factor 1/2: l = I Omega . Omega", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.lagrangian_2_5 = [](const Vec3<T>& I, const Vec3<T>& W) -> T { return T(2) * ref::lagrangian_2_5<T>(I, W); };
});

GM_MUTANT(lagrangian_2_13_pairing_without_half, "(2.13) evaluated with trace(A^T B), dropping the 1/2 of (2.15)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.lagrangian_2_13 = [](const Vec3<T>& I, const Mat3<T>& W) -> T {
              return T(2) * ref::lagrangian_2_13<T>(I, W);
            };
          });

GM_MUTANT(legendre_3_1_inverted, "Legendre transform written Pi = I^-1 Omega", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.legendre_3_1 = [](const Vec3<T>& I, const Vec3<T>& W) -> Vec3<T> { return W.cwiseQuotient(I); };
});

GM_MUTANT(hamiltonian_with_I, "Hamiltonian written h = (1/2) Pi . I Pi (I instead of I^-1)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hamiltonian_3_4 = [](const Vec3<T>& I, const Vec3<T>& P) -> T { return P.dot(I.cwiseProduct(P)) / T(2); };
});

GM_MUTANT(hamiltonian_3_3_plus_l, "(3.3) written h = Pi . Omega + l(Omega)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hamiltonian_3_3 = [](const Vec3<T>& I, const Vec3<T>& P) -> T {
    const Vec3<T> W = P.cwiseQuotient(I);
    return P.dot(W) + ref::lagrangian_2_5<T>(I, W);
  };
});

GM_MUTANT(omega_3_5_not_inverted, "(3.5) written Omega = I Pi", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.omega_3_5 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> { return I.cwiseProduct(P); };
});

GM_MUTANT(hamiltonian_2_21_sign_flipped, "(2.21) written h = l(Omega_hat) - <Pi, Omega_hat>", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hamiltonian_2_21 = [](const Vec3<T>& I, const Mat3<T>& P) -> T { return -ref::hamiltonian_2_21<T>(I, P); };
});

}  // namespace mutants_so3_and_euler
}  // namespace gm

namespace gm {
namespace mutants_so3_and_euler {

GM_MUTANT(casimir_without_half, "the Casimir written |Pi|^2 without the 1/2 of (2.27)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.casimir = [](const Vec3<T>& P) -> T { return P.dot(P); };
});

// The energy of the notes' body I = diag(1, 1/2, 1/3) in place of the Casimir: conserved by that
// body's motion, but not a Casimir (it does not commute with every function).
GM_MUTANT(casimir_weighted, "the Casimir written (Pi1^2 + 2 Pi2^2 + 3 Pi3^2)/2 (an energy, not a Casimir)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.casimir = [](const Vec3<T>& P) -> T {
              return (P(0) * P(0) + T(2) * P(1) * P(1) + T(3) * P(2) * P(2)) / T(2);
            };
          });

}  // namespace mutants_so3_and_euler
}  // namespace gm
