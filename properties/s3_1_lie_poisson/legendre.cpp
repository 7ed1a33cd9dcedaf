// Lagrangian, Legendre transform and Hamiltonian: (2.5), (2.13), (2.21), (3.1), (3.3)-(3.5).
//
// Derivatives are taken by central differences with unit steps, which are exact for the
// quadratic functions of the notes (truth::gradient_of_quadratic). Rounding in floats is a few
// eps of the function values, of size |I| (|Omega| + 1)^2 or (|Pi| + 1)^2 / min I.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_legendre {
namespace {

template <class T>
T kinetic_energy_2_5(const Vec3<T>& I, const Vec3<T>& W) {
  return (I(0) * W(0) * W(0) + I(1) * W(1) * W(1) + I(2) * W(2) * W(2)) / T(2);
}

template <class T>
T min_entry(const Vec3<T>& v) {
  return v.minCoeff();
}

// (2.5): l(Omega) = (1/2)(I1 Omega1^2 + I2 Omega2^2 + I3 Omega3^2).
template <class T>
void lagrangian_2_5_is_kinetic_energy(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  require_close("lagrangian_2_5(I, Omega) = (1/2) sum I_i Omega_i^2", s.lagrangian_2_5(I, W), kinetic_energy_2_5(I, W),
                T(norm_inf(I) * norm_inf(W) * norm_inf(W)), 8);
}

// (2.13): l = (1/2) <I Omega_hat, Omega_hat> is the same number.
template <class T>
void lagrangian_2_13_is_kinetic_energy(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  require_close("lagrangian_2_13(I, hat(Omega)) = (1/2) sum I_i Omega_i^2", s.lagrangian_2_13(I, truth::skew_of(W)),
                kinetic_energy_2_5(I, W), T(norm_inf(I) * norm_inf(W) * norm_inf(W)), 16);
}

// (3.1): Pi = dl/dOmega = I Omega (the fibre derivative of Definition 3.1).
template <class T>
void fibre_derivative_3_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const T scale = norm_inf(I) * (norm_inf(W) + T(1)) * (norm_inf(W) + T(1));
  const Vec3<T> dl = truth::gradient_of_quadratic<T>([&](const Vec3<T>& x) { return s.lagrangian_2_5(I, x); }, W);
  const Vec3<T> Pi = s.legendre_3_1(I, W);
  require_close("legendre_3_1(I, Omega) = I Omega", Pi, I.cwiseProduct(W).eval(), scale, 1);
  require_close("dl/dOmega = legendre_3_1(I, Omega)", dl, Pi, scale, 16);
}

// (3.3) and (3.4): h = Pi . Omega - l(Omega) = sum Pi_i^2 / (2 I_i).
template <class T>
void hamiltonian_3_3_is_3_4(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const T scale = (norm_inf(P) + T(1)) * (norm_inf(P) + T(1)) / min_entry(I);
  T expected(0);
  for (int i = 0; i < 3; ++i) expected += P(i) * P(i) / (T(2) * I(i));
  require_close("hamiltonian_3_4(I, Pi) = sum Pi_i^2 / (2 I_i)", s.hamiltonian_3_4(I, P), expected, scale, 8);
  require_close("hamiltonian_3_3(I, Pi) = sum Pi_i^2 / (2 I_i)", s.hamiltonian_3_3(I, P), expected, scale, 16);
}

// (3.5): dh/dPi = I^-1 Pi = Omega.
template <class T>
void hamiltonian_gradient_3_5(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const T scale = (norm_inf(P) + T(1)) * (norm_inf(P) + T(1)) / min_entry(I);
  const Vec3<T> dh = truth::gradient_of_quadratic<T>([&](const Vec3<T>& x) { return s.hamiltonian_3_4(I, x); }, P);
  const Vec3<T> W = s.omega_3_5(I, P);
  require_close("omega_3_5(I, Pi) = I^-1 Pi", W, P.cwiseQuotient(I).eval(), T(norm_inf(P) / min_entry(I)), 1);
  require_close("dh/dPi = omega_3_5(I, Pi)", dh, W, scale, 16);
}

// Exercise (2.21), matrix form: h(Pi) = <Pi, Omega_hat> - l(Omega_hat) is (3.4), and its answer
// Pi = dl/dOmega_hat, dh/dPi = Omega_hat, derivatives taken along the basis hat(e_k) of so(3)
// (orthonormal for (2.15), so the k-th directional derivative is the k-th coordinate).
template <class T>
void legendre_matrix_2_21(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const Vec3<T> P = I.cwiseProduct(W);
  const T scale = norm_inf(I) * (norm_inf(W) + T(1)) * (norm_inf(W) + T(1)) +
                  (norm_inf(P) + T(1)) * (norm_inf(P) + T(1)) / min_entry(I);
  require_close("hamiltonian_2_21(I, hat(Pi)) = (1/2) Pi . I^-1 Pi", s.hamiltonian_2_21(I, truth::skew_of(P)),
                kinetic_energy_2_5(I, W), scale, 16);
  const Vec3<T> dl =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& x) { return s.lagrangian_2_13(I, truth::skew_of(x)); }, W);
  const Vec3<T> dh =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& x) { return s.hamiltonian_2_21(I, truth::skew_of(x)); }, P);
  require_close("dl/dOmega_hat = Pi (fibre derivative, first equation of (2.20))", dl, P, scale, 32);
  require_close("dh/dPi = Omega_hat (answer to the exercise (2.21))", dh, W, scale, 32);
}

}  // namespace

GM_PROPERTY(lagrangian_2_5_is_kinetic_energy, all_scalars,
            {.spec = "s2.lagrangian",
             .title = "(2.5): l(Omega) = (1/2)(I1 Omega1^2 + I2 Omega2^2 + I3 Omega3^2)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lagrangian_2_5"},
             .negative_controls = {"lagrangian_missing_half"}});

GM_PROPERTY(lagrangian_2_13_is_kinetic_energy, all_scalars,
            {.spec = "s2.lagrangian",
             .title = "(2.13): (1/2) <I Omega_hat, Omega_hat> is the kinetic energy (2.5)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lagrangian_2_13"},
             .negative_controls = {"lagrangian_2_13_pairing_without_half"}});

GM_PROPERTY(fibre_derivative_3_1, all_scalars,
            {.spec = "s3.legendre",
             .title = "(3.1): Pi_i = I_i Omega_i = dl/dOmega_i",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lagrangian_2_5", "legendre_3_1"},
             .negative_controls = {"lagrangian_missing_half", "legendre_3_1_inverted"}});

GM_PROPERTY(hamiltonian_3_3_is_3_4, all_scalars,
            {.spec = "s3.hamiltonian",
             .title = "(3.3), (3.4): Pi . Omega - l(Omega) = sum Pi_i^2 / (2 I_i)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hamiltonian_3_3", "hamiltonian_3_4"},
             .negative_controls = {"hamiltonian_with_I", "hamiltonian_3_3_plus_l"}});

GM_PROPERTY(hamiltonian_gradient_3_5, all_scalars,
            {.spec = "s3.hamiltonian",
             .title = "(3.5): dh/dPi = I^-1 Pi = Omega",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hamiltonian_3_4", "omega_3_5"},
             .negative_controls = {"hamiltonian_with_I", "omega_3_5_not_inverted"}});

GM_PROPERTY(legendre_matrix_2_21, all_scalars,
            {.spec = "s2.legendre-hamiltonian",
             .title = "(2.21): h = <Pi, Omega_hat> - l(Omega_hat) is (3.4); Pi = dl/dOmega_hat, dh/dPi = Omega_hat",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lagrangian_2_13", "hamiltonian_2_21"},
             .negative_controls = {"lagrangian_2_13_pairing_without_half", "hamiltonian_2_21_sign_flipped"}});

}  // namespace properties_legendre
}  // namespace gm
