// Remark 2.3: the symmetric part of Pi does not contribute to the pairing (2.15) with a skew
// Omega_hat, and under dPi/dt = -[Omega_hat, Pi] a symmetric part that is zero stays zero (the
// vector field maps skew matrices to skew matrices, so the skew matrices are invariant).
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_symmetric_part {
namespace {

// For any 3 x 3 Pi and skew Omega_hat: <Pi_sym, Omega_hat> = 0 and <Pi, Omega_hat> =
// <Pi_skew, Omega_hat> = vee(Pi_skew) . Omega. Sizes: 9 products of |Pi| |Omega|, summed; k = 12.
template <class T>
void symmetric_part_does_not_pair(const Subject<T>& s) {
  const Mat3<T> Pi = *gen::mat3<T>().as("Pi");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const Mat3<T> W_hat = truth::skew_of(W);
  const Mat3<T> sym = ((Pi + Pi.transpose()) / T(2)).eval(), skew = ((Pi - Pi.transpose()) / T(2)).eval();
  const T scale = T(9) * norm_inf(Pi) * norm_inf(W);
  require_close("Remark 2.3: <Pi_sym, Omega_hat> = 0", s.pairing(MatX<T>(sym), MatX<T>(W_hat)), T(0), scale, 12);
  const T full = s.pairing(MatX<T>(Pi), MatX<T>(W_hat));
  require_close("Remark 2.3: <Pi, Omega_hat> = <Pi_skew, Omega_hat>", full, s.pairing(MatX<T>(skew), MatX<T>(W_hat)),
                scale, 12);
  require_close("<Pi_skew, Omega_hat> = vee(Pi_skew) . Omega", full,
                T(Vec3<T>(skew(2, 1), skew(0, 2), skew(1, 0)).dot(W)), scale, 12);
}

// The subject's matrix Euler vector field (2.12) on a skew Pi = hat(Pi) is skew: the symmetric
// part, zero initially, has zero rate. Sizes: |dPi/dt| <= 4 |Pi|^2 / min I; k: Omega (1) and the
// commutator (4), on both entries compared.
template <class T>
void matrix_euler_keeps_pi_skew(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const Mat3<T> F = s.euler_matrix_2_12(I, truth::skew_of(P));
  require_close("Remark 2.3: (dPi/dt)_sym = 0 when Pi is skew, so the symmetric part stays zero",
                ((F + F.transpose()) / T(2)).eval(), Mat3<T>::Zero().eval(),
                T(T(4) * norm_inf(P) * norm_inf(P) / I.minCoeff()), 10);
}

}  // namespace

GM_PROPERTY(symmetric_part_does_not_pair, all_scalars,
            {.spec = "s2.symmetric-part",
             .title = "Remark 2.3: the symmetric part of Pi does not contribute to <Pi, Omega_hat>",
             .tolerance = ToleranceClass::Exact,
             .needs = {"pairing"},
             .negative_controls = {"pairing_upper_triangle", "pairing_without_half"}});

GM_PROPERTY(matrix_euler_keeps_pi_skew, all_scalars,
            {.spec = "s2.symmetric-part",
             .title = "Remark 2.3: dPi/dt = -[Omega_hat, Pi] is skew for skew Pi, so a zero symmetric part stays zero",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_matrix_2_12"},
             .negative_controls = {"euler_matrix_anticommutator", "euler_matrix_one_sided"}});

}  // namespace properties_symmetric_part
}  // namespace gm
