// Remark 2.1 and its hint: with omega = O Omega and I_space = O I O^-1, l(Omega) = l_space(omega)
// = (1/2) omega . I_space omega; and for a variation O(s) with xi = delta O O^-1 (right-invariant),
// delta I_space = [xi, I_space].
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/line_derivative.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_space_inertia {
namespace {

// l(Omega) = (1/2) omega . I_space omega with omega = O Omega, O an exact rational rotation (rounded
// once in floats). Sizes: |I_space_ij| <= |I| (rows of O are unit vectors), sum_i |omega_i| <= 6
// |Omega|, so the quadratic form is <= 36 |I| |Omega|^2; k: O (1), omega (3), I_space (6), the form (5).
template <class T>
void space_lagrangian_remark_2_1(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Mat3<T> O = *gen::rotation3<T>().as("O");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const Vec3<T> omega = O * W;
  const Mat3<T> I_space = s.inertia_space(O, I);
  require_close("Remark 2.1: l(Omega) = (1/2) omega . I_space omega, I_space = O I O^-1",
                T(omega.dot(I_space * omega) / T(2)), s.lagrangian_2_5(I, W),
                T(T(36) * norm_inf(I) * norm_inf(W) * norm_inf(W)), 16);
}

// The hint: delta I_space = [xi, I_space], xi = delta O O^-1. The variation is the rational curve
// O(s) = O0 R(s) with R(s) the Cayley transform of s S (S skew, dyadic): R(s) = P(s) / d(s) with
// P of degree 2 and d(s) = 1 + s^2 |S|^2, so d(s)^2 I_space(O(s)) is a matrix polynomial of degree
// 4 in s, differentiated exactly at s = 0 by interpolation (support/line_derivative.hpp; d(0) = 1
// and d'(0) = 0, so this is delta I_space), with the degree certified at one more node. Every O(s)
// is computed exactly in Rational and rounded once in floats. delta O = O0 R'(0) = 2 O0 S, so
// xi = 2 O0 S O0^T.
// Sizes: entries of d^2 I_space <= d_max^2 |I| on the nodes (rows of O are unit vectors), the
// derivative <= W d_max^2 |I|; [xi, I_space] <= 2 * 3 |xi| |I|. k: O (1), I_space (6), the
// product with d^2 (1), the weighted sum (nodes.ops()), the commutator (4).
template <class T>
void space_inertia_variation_hint(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const MatX<Rational> O0 = *gen::rotation<Rational>(3).as("O0");
  const MatX<Rational> S = *gen::skew<Rational>(3, 8, 2).as("S");
  const Rational S2 = S(2, 1) * S(2, 1) + S(0, 2) * S(0, 2) + S(1, 0) * S(1, 0);
  const CentralNodes<Rational> qnodes = central_nodes<Rational>(4);
  const CentralNodes<T> nodes = central_nodes<T>(4);
  auto value_at = [&](const Rational& t) {
    const MatX<Rational> R = gen::cayley_rational(MatX<Rational>(t * S));
    const Rational d = Rational(1) + t * t * S2;
    const Mat3<T> O = convert_matrix<T>(MatX<Rational>(O0 * R));
    return Mat3<T>(convert<T>(Rational(d * d)) * s.inertia_space(O, I));
  };
  Mat3<T> derivative = Mat3<T>::Zero(), predicted = Mat3<T>::Zero();
  for (std::size_t k = 0; k < qnodes.s.size(); ++k) {
    const Mat3<T> V = value_at(qnodes.s[k]);
    derivative += nodes.w[k] * V;
    predicted += nodes.l[k] * V;
  }
  const Rational d_check = Rational(1) + qnodes.s_check * qnodes.s_check * S2;
  const T d_max2 = convert<T>(Rational(d_check * d_check));  // d grows with |s|: the largest on the nodes
  const T Phi = d_max2 * T(3) * norm_inf(I);
  require_close("d(s)^2 I_space(O(s)) is a polynomial of degree <= 4 in s (interpolant predicts the next node)",
                predicted, value_at(qnodes.s_check), T((nodes.L + T(1)) * Phi), 8 + nodes.ops());
  const Mat3<T> I_space = s.inertia_space(convert_matrix<T>(O0), I);
  const Mat3<T> xi = convert_matrix<T>(MatX<Rational>(Rational(2) * O0 * S * O0.transpose()));
  require_close("hint to the exercise after Remark 2.1: delta I_space = [xi, I_space], xi = delta O O^-1", derivative,
                (xi * I_space - I_space * xi).eval(), T(nodes.W * Phi + T(6) * norm_inf(xi) * T(3) * norm_inf(I)),
                8 + nodes.ops() + 4);
}

}  // namespace

GM_PROPERTY(space_lagrangian_remark_2_1, all_scalars,
            {.spec = "s2.space-lagrangian",
             .title = "Remark 2.1: l(Omega) = l_space(omega) = (1/2) omega . I_space omega, I_space = O I O^-1",
             .tolerance = ToleranceClass::Exact,
             .needs = {"inertia_space", "lagrangian_2_5"},
             .negative_controls = {"inertia_space_inverted"}});

GM_PROPERTY(space_inertia_variation_hint, all_scalars,
            {.spec = "s2.space-lagrangian",
             .title = "hint after Remark 2.1: delta I_space = [xi, I_space] with xi = delta O O^-1",
             .tolerance = ToleranceClass::Exact,
             .needs = {"inertia_space"},
             .negative_controls = {"inertia_space_inverted"}});

}  // namespace properties_space_inertia
}  // namespace gm
