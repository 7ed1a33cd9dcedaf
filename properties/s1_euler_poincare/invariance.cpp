// Left invariance (Definition 1.1) of the rigid body and the sign of the Euler-Poincare equation
// for right-invariant systems (Remark 1.1, (1.1)).
#include "properties/registry.hpp"
#include "properties/support/coordinates.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_invariance {
namespace {

template <class T>
Vec3<T> vee_of(const Mat3<T>& m) {
  return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
}

// Definition 1.1 and L(g, g') = l(g^-1 g'): with O' = O Omega_hat from the subject's reconstruction
// (2.10), L(O, O') = l(O^-1 O') = l(Omega); left translation (O, O') -> (R O, R O') gives the same
// body velocity, so L is unchanged, and the reconstruction equation is itself left-invariant:
// reconstruction(R O, Omega) = R reconstruction(O, Omega). Right translation (O R, O' R) gives the body
// velocity hat(R^T Omega), so L becomes l(R^T Omega), which differs in general (shown on a witness).
// O, R are exact rational rotations (rounded once in floats, so O^T is O^-1 up to rounding).
// Sizes: l <= (3/2) |I| (3 |Omega|)^2 after rotations; k counts the products of three rotations
// (3 x 5) and the Lagrangian (2.13) (8).
template <class T>
void left_invariance_definition_1_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Mat3<T> O = *gen::rotation3<T>().as("O");
  const Mat3<T> R = *gen::rotation3<T>().as("R");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const T scale = T(14) * norm_inf(I) * norm_inf(W) * norm_inf(W);
  const Mat3<T> O_dot = s.reconstruction_2_10(O, W);
  require_close("(2.10): dO/dt = O Omega_hat", O_dot, (O * truth::skew_of(W)).eval(), T(T(6) * norm_inf(W)), 6);
  const T l = s.lagrangian_2_5(I, W);
  const Mat3<T> RO = R * O, RO_dot = R * O_dot;
  require_close("L(O, dO/dt) = l(O^-1 dO/dt) = l(Omega)", s.lagrangian_2_13(I, (O.transpose() * O_dot).eval()), l,
                scale, 24);
  require_close("left translation: reconstruction(R O, Omega) = R reconstruction(O, Omega)",
                s.reconstruction_2_10(RO, W), RO_dot, T(T(18) * norm_inf(W)), 12);
  require_close("Definition 1.1: L(R O, R dO/dt) = L(O, dO/dt)", s.lagrangian_2_13(I, (RO.transpose() * RO_dot).eval()),
                l, scale, 24);
  const Mat3<T> OR = O * R, OR_dot = O_dot * R;
  require_close("right translation: L(O R, dO/dt R) = l(R^T Omega)",
                s.lagrangian_2_13(I, (OR.transpose() * OR_dot).eval()), s.lagrangian_2_5(I, (R.transpose() * W).eval()),
                scale, 24);
  // Witness that L is not right-invariant: I = (1, 2, 3), Omega = e1, R = rotation by pi/2 about e3:
  // l(R^T e1) = l(-e2) = 1 while l(e1) = 1/2.
  Mat3<T> Rz;
  Rz << T(0), T(-1), T(0), T(1), T(0), T(0), T(0), T(0), T(1);
  const Vec3<T> I_w(T(1), T(2), T(3)), e1(T(1), T(0), T(0));
  const Mat3<T> Od = s.reconstruction_2_10(Mat3<T>::Identity(), e1);
  require("L is not right-invariant (witness I = (1, 2, 3), Omega = e1, R = quarter turn about e3)",
          s.lagrangian_2_13(I_w, (Rz.transpose() * Od * Rz).eval()) != s.lagrangian_2_13(I_w, Od));
}

// Remark 1.1, (1.1): for a right-invariant system the Euler-Poincare equation has the opposite sign,
// d/dt dl/deta = -ad*_eta dl/deta with eta = h' h^-1. Executable form: the inverse h = O^-1 = O^T of
// a rigid-body motion O(t) (left-invariant, (2.10) and (3.8)) is right-invariant: its velocity
// eta = h' h^-1 = (O')^T O = -Omega; its Lagrangian L(h, h') = l(O^-1 O') = l(-eta) depends on eta
// only; mu = dl(-eta)/deta = -Pi; and along Euler's equation mu' = -Pi' = -ad*_eta mu, with the
// minus sign of (1.1) (the + sign of Theorem 1.1 (iv) fails, shown on a witness).
// Sizes: Hs = (|Pi| + 1)^2 / min I bounds Omega, the values of l near eta and its gradient; the
// equation compares quantities of size 2 |Pi| Hs.
template <class T>
void right_invariant_sign_1_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Mat3<T> O = *gen::rotation3<T>().as("O");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const T Hs = (norm_inf(P) + T(1)) * (norm_inf(P) + T(1)) / I.minCoeff();
  const Vec3<T> Omega = s.omega_3_5(I, P);
  const Mat3<T> O_dot = s.reconstruction_2_10(O, Omega);
  const Vec3<T> eta = vee_of<T>((O_dot.transpose() * O).eval());
  require_close("h = O^-1: eta = h' h^-1 = -Omega", eta, (-P.cwiseQuotient(I)).eval(), T(T(9) * Hs), 12);
  const Vec3<T> mu =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return s.lagrangian_2_5(I, (-y).eval()); }, eta);
  require_close("the right-invariant Lagrangian l(-eta) has dl/deta = -Pi", mu, (-P).eval(),
                T(norm_inf(I) * (norm_inf(eta) + T(1)) * (norm_inf(eta) + T(1))), 32);
  const Vec3<T> mu_dot = -s.euler_3_8(I, P);
  const T scale = T(2) * (norm_inf(P) + T(1)) * Hs * (norm_inf(I) + T(1)) * T(9);
  require_close("(1.1): d/dt dl/deta = -ad*_eta dl/deta", mu_dot,
                Vec3<T>(-coords::ad_star_so3_in_hat_coordinates(s, eta, mu)), scale, 48);
  // Witness that the left-invariant sign fails here: I = (1, 2, 3), O = Id, Pi = (1, 1, 0).
  const Vec3<T> I_w(T(1), T(2), T(3)), P_w(T(1), T(1), T(0));
  const Vec3<T> eta_w = -vee_of<T>((s.reconstruction_2_10(Mat3<T>::Identity(), s.omega_3_5(I_w, P_w))).eval());
  const Vec3<T> plus = coords::ad_star_so3_in_hat_coordinates(s, eta_w, Vec3<T>(-P_w));
  require("the left-invariant sign + ad*_eta mu does not hold for the right-invariant system (witness)",
          Vec3<T>(-s.euler_3_8(I_w, P_w)) != plus);
}

}  // namespace

GM_PROPERTY(left_invariance_definition_1_1, all_scalars,
            {.spec = "s1.left-invariance",
             .title = "Definition 1.1: L(O, O') = l(O^-1 O') is invariant under O -> R O, not under O -> O R",
             .tolerance = ToleranceClass::Exact,
             .needs = {"reconstruction_2_10", "lagrangian_2_5", "lagrangian_2_13"},
             .negative_controls = {"reconstruction_2_10_right_trivialized", "lagrangian_2_13_pairing_without_half"}});

GM_PROPERTY(right_invariant_sign_1_1, all_scalars,
            {.spec = "s1.right-invariant-sign",
             .title = "(1.1): for h = O^-1 (right-invariant), d/dt dl/deta = -ad*_eta dl/deta with eta = h' h^-1",
             .tolerance = ToleranceClass::Exact,
             .needs = {"omega_3_5", "reconstruction_2_10", "lagrangian_2_5", "euler_3_8", "ad_star"},
             .negative_controls = {"reconstruction_2_10_right_trivialized", "ad_star_is_ad",
                                   "euler_3_8_cross_reversed"}});

}  // namespace properties_invariance
}  // namespace gm
