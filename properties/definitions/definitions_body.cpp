// Every slot of the rigid body itself checked on its own: Euler's equations in their
// four forms, the Lagrangian, the Legendre transform, the Hamiltonian, the system (3.16), Clebsch,
// reconstruction, the spatial momentum and the inertia of (2.3). Each property needs exactly one
// slot and compares it with the notes' formula written here from the definition. Inputs come
// from every regime (support/regimes.hpp): bodies that are symmetric or spherical tops or scaled
// by 2^s, momenta along or near a principal axis, with zero components, tiny or huge; attitudes
// that are the identity or quarter turns as well as generic rotations.
//
// Tolerances: exact (0) in rationals; in floats k eps * scale with scale the size of the
// formula's terms (|I| |Omega|^2, |Pi|^2 / min I, ...) and k the roundings on both sides.
#include "properties/registry.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_definitions_body {
namespace {

template <class T>
T min_moment(const Vec3<T>& I) {
  return I.minCoeff();
}

// dOmega/dt of (2.1) and (2.2): I^-1 ((I Omega) x Omega).
template <class T>
Vec3<T> omega_dot(const Vec3<T>& I, const Vec3<T>& W) {
  return truth::cross(Vec3<T>(I.cwiseProduct(W)), W).cwiseQuotient(I);
}

// dPi/dt of (3.7) and (3.8): Pi x I^-1 Pi.
template <class T>
Vec3<T> pi_dot(const Vec3<T>& I, const Vec3<T>& P) {
  return truth::cross(P, Vec3<T>(P.cwiseQuotient(I)));
}

template <class T>
T energy(const Vec3<T>& I, const Vec3<T>& P) {  // (3.4): Pi . I^-1 Pi / 2
  return P.dot(P.cwiseQuotient(I)) / T(2);
}

template <class T>
std::string body_inputs(const Vec3<T>& I, const char* name, const Vec3<T>& x) {
  return named("I", I) + named(name, x);
}

// (2.1), componentwise: I1 dOmega1/dt = (I2 - I3) Omega2 Omega3 and cyclically.
template <class T>
void definition_euler_2_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  showing_inputs([&] { return body_inputs(I, "Omega", W); },
                 [&] {
                   require_close("slot euler_2_1: dOmega/dt = I^-1 (I Omega x Omega), (2.1)", s.euler_2_1(I, W),
                                 omega_dot(I, W), T(norm_inf(I) * W.squaredNorm() / min_moment(I)), 12);
                 });
}

template <class T>
void definition_euler_2_2(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  showing_inputs([&] { return body_inputs(I, "Omega", W); },
                 [&] {
                   require_close("slot euler_2_2: I dOmega/dt = I Omega x Omega, (2.2)", s.euler_2_2(I, W),
                                 omega_dot(I, W), T(norm_inf(I) * W.squaredNorm() / min_moment(I)), 12);
                 });
}

template <class T>
void definition_euler_3_7(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return body_inputs(I, "Pi", P); },
                 [&] {
                   require_close("slot euler_3_7: dPi/dt = Pi x I^-1 Pi, componentwise (3.7)", s.euler_3_7(I, P),
                                 pi_dot(I, P), T(P.squaredNorm() / min_moment(I)), 12);
                 });
}

template <class T>
void definition_euler_3_8(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return body_inputs(I, "Pi", P); },
                 [&] {
                   require_close("slot euler_3_8: dPi/dt = Pi x I^-1 Pi, (3.8)", s.euler_3_8(I, P), pi_dot(I, P),
                                 T(P.squaredNorm() / min_moment(I)), 12);
                 });
}

// (2.12)/(2.20): dPi_hat/dt = -[Omega_hat, Pi_hat], i.e. the hat of Pi x Omega.
template <class T>
void definition_euler_matrix_2_12(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Mat3<T> P_hat = truth::skew_of(P);
  showing_inputs([&] { return named("I", I) + named("Pi_hat", P_hat); },
                 [&] {
                   require_close("slot euler_matrix_2_12: dPi/dt = -[Omega_hat, Pi_hat] = hat(Pi x Omega), (2.12)",
                                 s.euler_matrix_2_12(I, P_hat), truth::skew_of(pi_dot(I, P)),
                                 T(P.squaredNorm() / min_moment(I)), 24);
                 });
}

// (2.5): l = I Omega . Omega / 2.
template <class T>
void definition_lagrangian_2_5(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  showing_inputs([&] { return body_inputs(I, "Omega", W); },
                 [&] {
                   require_close("slot lagrangian_2_5: l = I Omega . Omega / 2, (2.5)", s.lagrangian_2_5(I, W),
                                 T(W.dot(I.cwiseProduct(W)) / T(2)), T(norm_inf(I) * W.squaredNorm()), 8);
                 });
}

// (2.13): l = <I Omega_hat, Omega_hat> / 2, the same number as (2.5).
template <class T>
void definition_lagrangian_2_13(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  const Mat3<T> W_hat = truth::skew_of(W);
  showing_inputs([&] { return named("I", I) + named("Omega_hat", W_hat); },
                 [&] {
                   require_close("slot lagrangian_2_13: l = <I Omega_hat, Omega_hat>/2 = I Omega . Omega / 2, (2.13)",
                                 s.lagrangian_2_13(I, W_hat), T(W.dot(I.cwiseProduct(W)) / T(2)),
                                 T(norm_inf(I) * W.squaredNorm()), 16);
                 });
}

// (3.1): Pi = dl/dOmega = I Omega.
template <class T>
void definition_legendre_3_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  showing_inputs([&] { return body_inputs(I, "Omega", W); },
                 [&] {
                   require_close("slot legendre_3_1: Pi = dl/dOmega = I Omega, (3.1)", s.legendre_3_1(I, W),
                                 Vec3<T>(I.cwiseProduct(W)), T(norm_inf(I) * norm_inf(W)), 2);
                 });
}

// (3.5): Omega = dh/dPi = I^-1 Pi.
template <class T>
void definition_omega_3_5(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return body_inputs(I, "Pi", P); },
                 [&] {
                   require_close("slot omega_3_5: Omega = dh/dPi = I^-1 Pi, (3.5)", s.omega_3_5(I, P),
                                 Vec3<T>(P.cwiseQuotient(I)), T(norm_inf(P) / min_moment(I)), 2);
                 });
}

// (3.3) and (3.4): h = Pi . Omega - l(Omega) = Pi . I^-1 Pi / 2.
template <class T>
void definition_hamiltonian_3_3(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return body_inputs(I, "Pi", P); },
                 [&] {
                   require_close("slot hamiltonian_3_3: h = Pi . Omega - l(Omega) = Pi . I^-1 Pi / 2, (3.3)",
                                 s.hamiltonian_3_3(I, P), energy(I, P), T(P.squaredNorm() / min_moment(I)), 16);
                 });
}

template <class T>
void definition_hamiltonian_3_4(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return body_inputs(I, "Pi", P); },
                 [&] {
                   require_close("slot hamiltonian_3_4: h = Pi . I^-1 Pi / 2, (3.4)", s.hamiltonian_3_4(I, P),
                                 energy(I, P), T(P.squaredNorm() / min_moment(I)), 8);
                 });
}

// (2.21): h = <Pi, Omega_hat> - l, the same number as (3.4).
template <class T>
void definition_hamiltonian_2_21(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Mat3<T> P_hat = truth::skew_of(P);
  showing_inputs([&] { return named("I", I) + named("Pi_hat", P_hat); },
                 [&] {
                   require_close("slot hamiltonian_2_21: h = <Pi, Omega_hat> - l = Pi . I^-1 Pi / 2, (2.21)",
                                 s.hamiltonian_2_21(I, P_hat), energy(I, P), T(P.squaredNorm() / min_moment(I)), 32);
                 });
}

// (3.16): dx1/dt = -a1 a3 x2 x3, dx2/dt = -a2 a3 x3 x1, dx3/dt = a1 a2 x1 x2.
template <class T>
void definition_nambu_3_16(const Subject<T>& s) {
  const Vec3<T> a = *gen::regime_vec3<T>().as("a");
  const Vec3<T> x = *gen::regime_vec3<T>().as("x");
  const Vec3<T> expected(-a(0) * a(2) * x(1) * x(2), -a(1) * a(2) * x(2) * x(0), a(0) * a(1) * x(0) * x(1));
  const Vec3<T> got = s.nambu_3_16(a, x);
  // The printed answer of the exercise: grad(a1 x1^2 + a3 x3^2) x grad(a2 x2^2 + a3 x3^2) / 4.
  const Vec3<T> dA(T(2) * a(0) * x(0), T(0), T(2) * a(2) * x(2)), dB(T(0), T(2) * a(1) * x(1), T(2) * a(2) * x(2));
  const Vec3<T> printed = truth::cross(dA, dB) / T(4);
  const T scale = T(a.squaredNorm() * x.squaredNorm());
  recognising_erratum(
      [&] { return printed != expected && (got - printed).cwiseAbs().maxCoeff() <= T(8) * eps<T>() * scale; },
      "s3.nambu-3.16", "the answer grad(a1 x1^2 + a3 x3^2) x grad(a2 x2^2 + a3 x3^2) / 4",
      [&] {
        showing_inputs([&] { return named("a", a) + named("x", x); },
                       [&] { require_close("slot nambu_3_16: the system (3.16)", got, expected, scale, 6); });
      });
}

// (3.21): with Pi = P x Q and Omega = I^-1 Pi, dQ/dt = Q x Omega and dP/dt = P x Omega.
template <class T>
void definition_clebsch_3_21(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> Q = *gen::regime_vec3<T>().as("Q");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Vec3<T> W = truth::cross(P, Q).cwiseQuotient(I);
  const auto [dQ, dP] = s.clebsch_3_21(I, Q, P);
  const T scale = norm_inf(P) * norm_inf(Q) / min_moment(I);
  showing_inputs([&] { return named("I", I) + named("Q", Q) + named("P", P); },
                 [&] {
                   require_close("slot clebsch_3_21: dQ/dt = Q x Omega, Omega = I^-1 (P x Q), (3.21)", dQ,
                                 truth::cross(Q, W), T(scale * norm_inf(Q)), 16);
                   require_close("slot clebsch_3_21: dP/dt = P x Omega, Omega = I^-1 (P x Q), (3.21)", dP,
                                 truth::cross(P, W), T(scale * norm_inf(P)), 16);
                 });
}

// (2.10): dO/dt = O Omega_hat (Omega_hat = O^-1 dO/dt, left-invariant).
template <class T>
void definition_reconstruction_2_10(const Subject<T>& s) {
  const Mat3<T> O = *gen::regime_rotation3<T>().as("O");
  const Vec3<T> W = *gen::regime_vec3<T>().as("Omega");
  showing_inputs([&] { return named("O", O) + named("Omega", W); },
                 [&] {
                   require_close("slot reconstruction_2_10: dO/dt = O Omega_hat, (2.10)", s.reconstruction_2_10(O, W),
                                 Mat3<T>(O * truth::skew_of(W)), norm_inf(W), 8);
                 });
}

// Theorem 2.2 with the erratum of (2.30): pi = Ad*_{O^-1} Pi = O Pi.
template <class T>
void definition_spatial_momentum(const Subject<T>& s) {
  const Mat3<T> O = *gen::regime_rotation3<T>().as("O");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Vec3<T> pi = s.spatial_momentum(O, P);
  recognising_erratum([&] { return (pi - O.transpose() * P).cwiseAbs().maxCoeff() <= T(8) * eps<T>() * norm_inf(P); },
                      "s2.noether", "(2.30) pi = O^-1 Pi O, i.e. O^T Pi",
                      [&] {
                        showing_inputs(
                            [&] { return named("O", O) + named("Pi", P); },
                            [&] {
                              require_close(
                                  "slot spatial_momentum: pi = O Pi (Theorem 2.2; (2.30) as printed is an erratum)", pi,
                                  Vec3<T>(O * P), norm_inf(P), 6);
                            });
                      });
}

// Remark 2.1: I_space = O I O^-1 = O diag(I) O^T.
template <class T>
void definition_inertia_space(const Subject<T>& s) {
  const Mat3<T> O = *gen::regime_rotation3<T>().as("O");
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  showing_inputs([&] { return named("O", O) + named("I", I); },
                 [&] {
                   require_close("slot inertia_space: I_space = O I O^-1, Remark 2.1", s.inertia_space(O, I),
                                 Mat3<T>(O * I.asDiagonal() * O.transpose()), norm_inf(I), 12);
                 });
}

// (2.3) for N = 1..5 point masses m_k at the columns X_k of X.
template <class T>
void draw_masses(VecX<T>& m, MatX<T>& X) {
  const int N = *gen::uniform(1, 6).as("N");
  const int e = *gen::uniform(-20, 21).as("e (a scale 2^e)");
  const int em = *gen::uniform(-30, 31).as("em (a scale 2^em)");  // masses in every binade, tiny ones included
  const bool thirds = *gen::uniform(0, 4).as("X in thirds (3: yes)") == 3;
  m = *gen::vec<T>(N, 64, 2).as("m");
  for (int k = 0; k < N; ++k) m(k) = (abs_value(m(k)) + T(1)) * gen::pow2<T>(em);
  X = (*gen::mat<T>(3, N).as("X / 2^e (before the thirds)") * gen::pow2<T>(e)).eval();
  if (thirds) X = (X / T(3)).eval();
}

template <class T>
void definition_inertia_tensor_2_3(const Subject<T>& s) {
  VecX<T> m;
  MatX<T> X;
  draw_masses(m, X);
  Mat3<T> expected = Mat3<T>::Zero();
  for (Eigen::Index k = 0; k < m.size(); ++k) {
    const Vec3<T> x = X.col(k);
    expected += m(k) * (x.squaredNorm() * Mat3<T>::Identity() - x * x.transpose());
  }
  const T scale = T(m.size()) * norm_inf(m) * norm_inf(X) * norm_inf(X);
  showing_inputs([&] { return named("m", m) + named("X (columns X_k)", X); },
                 [&] {
                   require_close("slot inertia_tensor_2_3: I = sum m_k (|X_k|^2 Id - X_k X_k^T), (2.3)",
                                 s.inertia_tensor_2_3(m, X), expected, scale, 8.0 * static_cast<double>(m.size()));
                 });
}

template <class T>
void definition_inertia_bilinear_2_3(const Subject<T>& s) {
  VecX<T> m;
  MatX<T> X;
  draw_masses(m, X);
  const Vec3<T> a = *gen::regime_vec3<T>().as("a");
  const Vec3<T> b = *gen::regime_vec3<T>().as("b");
  T expected(0);
  for (Eigen::Index k = 0; k < m.size(); ++k) {
    const Vec3<T> x = X.col(k);
    expected += m(k) * truth::cross(a, x).dot(truth::cross(b, x));
  }
  const T scale = T(m.size()) * norm_inf(m) * norm_inf(X) * norm_inf(X) * norm_inf(a) * norm_inf(b);
  showing_inputs([&] { return named("m", m) + named("X (columns X_k)", X) + named("a", a) + named("b", b); },
                 [&] {
                   require_close("slot inertia_bilinear_2_3: (a, b) = sum m_k (a x X_k) . (b x X_k), (2.3)",
                                 s.inertia_bilinear_2_3(m, X, a, b), expected, scale,
                                 24.0 * static_cast<double>(m.size()));
                 });
}

}  // namespace

#define GM_BODY_DEFINITION(slot, entry, statement, ...)     \
  GM_PROPERTY(definition_##slot, all_scalars,               \
              {.spec = entry,                               \
               .title = "slot " #slot " alone: " statement, \
               .tolerance = ToleranceClass::Exact,          \
               .needs = {#slot},                            \
               .negative_controls = {__VA_ARGS__},          \
               .cases = {.d = 200, .mp = 100, .q = 50}})

GM_BODY_DEFINITION(euler_2_1, "s2.euler-equations", "(2.1) on symmetric and spherical tops, axes, tiny and huge Omega",
                   "euler_2_1_sign_error", "euler_2_1_missing_division", "euler_2_1_symmetric_top_branch");
GM_BODY_DEFINITION(euler_2_2, "s2.euler-equations", "I dOmega/dt = I Omega x Omega, (2.2)", "euler_2_2_cross_reversed");
GM_BODY_DEFINITION(euler_3_7, "s3.euler-momentum-form", "(3.7) componentwise, on and near principal axes",
                   "euler_3_7_index_slip", "euler_3_7_axis_fast_path");
GM_BODY_DEFINITION(euler_3_8, "s3.euler-momentum-form", "dPi/dt = Pi x I^-1 Pi, (3.8), for tiny and huge Pi",
                   "euler_3_8_cross_reversed", "euler_3_8_small_momentum_guard");
GM_BODY_DEFINITION(euler_matrix_2_12, "s2.matrix-euler", "dPi/dt = -[Omega_hat, Pi_hat], (2.12)",
                   "euler_matrix_commutator_sign");
GM_BODY_DEFINITION(lagrangian_2_5, "s2.lagrangian", "l = I Omega . Omega / 2, (2.5)", "lagrangian_missing_half");
GM_BODY_DEFINITION(lagrangian_2_13, "s2.lagrangian", "l = <I Omega_hat, Omega_hat>/2, (2.13)",
                   "lagrangian_2_13_pairing_without_half");
GM_BODY_DEFINITION(legendre_3_1, "s3.legendre", "Pi = I Omega, (3.1)", "legendre_3_1_inverted");
GM_BODY_DEFINITION(omega_3_5, "s3.hamiltonian", "Omega = I^-1 Pi, (3.5), to the last digit in 50 digits",
                   "omega_3_5_not_inverted", "omega_3_5_through_double");
GM_BODY_DEFINITION(hamiltonian_3_3, "s3.hamiltonian", "h = Pi . Omega - l = Pi . I^-1 Pi / 2, (3.3)",
                   "hamiltonian_3_3_plus_l");
GM_BODY_DEFINITION(hamiltonian_3_4, "s3.hamiltonian", "h = Pi . I^-1 Pi / 2, (3.4), to the last digit in 50 digits",
                   "hamiltonian_with_I", "hamiltonian_3_4_double_constant");
GM_BODY_DEFINITION(hamiltonian_2_21, "s2.legendre-hamiltonian", "h = <Pi, Omega_hat> - l, (2.21)",
                   "hamiltonian_2_21_sign_flipped");
GM_BODY_DEFINITION(nambu_3_16, "s3.nambu-3.16", "the system (3.16) as printed", "nambu_3_16_as_printed_answer");
GM_BODY_DEFINITION(clebsch_3_21, "s3.clebsch-euler", "dQ/dt = Q x Omega, dP/dt = P x Omega, Pi = P x Q, (3.21)",
                   "clebsch_3_21_sign_flipped", "clebsch_3_21_Pi_for_Omega");
GM_BODY_DEFINITION(reconstruction_2_10, "s2.reconstruction", "dO/dt = O Omega_hat, (2.10)",
                   "reconstruction_right_multiplied");
GM_BODY_DEFINITION(spatial_momentum, "s2.noether", "pi = O Pi (Theorem 2.2, (2.30) corrected)",
                   "spatial_momentum_as_printed_2_30");
GM_BODY_DEFINITION(inertia_space, "s2.space-lagrangian", "I_space = O I O^-1, Remark 2.1", "inertia_space_inverted");
GM_BODY_DEFINITION(inertia_tensor_2_3, "s2.inertia", "I = sum m (|X|^2 Id - X X^T), (2.3), 1 to 5 masses",
                   "inertia_tensor_missing_identity");
GM_BODY_DEFINITION(inertia_bilinear_2_3, "s2.inertia", "(a, b) = sum m (a x X).(b x X), (2.3), 1 to 5 masses",
                   "inertia_bilinear_dot_for_cross");

#undef GM_BODY_DEFINITION
}  // namespace properties_definitions_body
}  // namespace gm
