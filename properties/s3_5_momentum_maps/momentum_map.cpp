// The cotangent-lift momentum map of SO(3) acting on R^3 (closing section): J(q, p) = p x q; its
// Hamiltonian J^xi = <J, xi> generates the cotangent lift q' = -xi x q, p' = -xi x p; J is
// infinitesimally equivariant, J' = -xi x J = ad*_xi J, and equivariant, J(R q, R p) = R J(q, p)
// for R in SO(3) (exactly, for the rational rotations of gen::rotation3).
#include "properties/registry.hpp"
#include "properties/support/coordinates.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_momentum_map {
namespace {

// J^xi is bilinear in (q, p), so its gradients in q and in p are exact central differences with unit
// steps (truth::gradient_of_quadratic); q_i' = {q_i, J^xi} and p_i' = {p_i, J^xi} with the subject's
// canonical bracket. Sizes: J^xi values 6 |xi| (|q| + 1) (|p| + 1); a central difference and the
// bracket (which only selects components) add a few roundings: k = 8.
template <class T>
void momentum_map_generates_rotations(const Subject<T>& s) {
  const Vec3<T> q = *gen::vec3<T>().as("q");
  const Vec3<T> p = *gen::vec3<T>().as("p");
  const Vec3<T> xi = *gen::vec3<T>().as("xi");
  const T scale = T(6) * norm_inf(xi) * (norm_inf(q) + T(1)) * (norm_inf(p) + T(1));
  require_close("J(q, p) = p x q", s.momentum_map(q, p), truth::cross(p, q), T(T(2) * norm_inf(q) * norm_inf(p)), 2);
  const Vec3<T> dJ_dq =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return T(xi.dot(s.momentum_map(y, p))); }, q);
  const Vec3<T> dJ_dp =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return T(xi.dot(s.momentum_map(q, y))); }, p);
  const Vec3<T> zero = Vec3<T>::Zero();
  Vec3<T> q_dot, p_dot;
  for (int i = 0; i < 3; ++i) {
    Vec3<T> e = zero;
    e(i) = T(1);
    q_dot(i) = s.canonical_bracket(e, zero, dJ_dq, dJ_dp);
    p_dot(i) = s.canonical_bracket(zero, e, dJ_dq, dJ_dp);
  }
  require_close("q' = {q, J^xi} = -xi x q", q_dot, (-truth::cross(xi, q)).eval(), scale, 8);
  require_close("p' = {p, J^xi} = -xi x p", p_dot, (-truth::cross(xi, p)).eval(), scale, 8);
}

// Along q' = -xi x q, p' = -xi x p: J' = J(q', p) + J(q, p') (J bilinear; the first line of the
// notes' proof) = -xi x J = ad*_xi J. Sizes: 8 |xi| |q| |p|; k = the velocities (2), J (2), the sum
// (1), and ad* (two nonzero products per component, 4).
template <class T>
void momentum_map_infinitesimal_equivariance(const Subject<T>& s) {
  const Vec3<T> q = *gen::vec3<T>().as("q");
  const Vec3<T> p = *gen::vec3<T>().as("p");
  const Vec3<T> xi = *gen::vec3<T>().as("xi");
  const Vec3<T> q_dot = -truth::cross(xi, q), p_dot = -truth::cross(xi, p);
  const Vec3<T> J = s.momentum_map(q, p);
  const Vec3<T> J_dot = (s.momentum_map(q_dot, p) + s.momentum_map(q, p_dot)).eval();
  const T scale = T(8) * norm_inf(xi) * norm_inf(q) * norm_inf(p);
  require_close("J' = -xi x J", J_dot, (-truth::cross(xi, J)).eval(), scale, 10);
  require_close("-xi x J = ad*_xi J (so(3))", (-truth::cross(xi, J)).eval(),
                coords::ad_star_so3_in_hat_coordinates(s, xi, J), scale, 10);
}

// J(R q, R p) = R J(q, p) for R in SO(3). For an improper orthogonal R' = -R (det -1) the map picks
// up the determinant, J(R' q, R' p) = -R' J(q, p): J is a pseudovector, equivariant under SO(3)
// only. R is an exact rational rotation (rounded once in floats); |R q|_inf <= 3 |q|_inf.
template <class T>
void momentum_map_equivariance(const Subject<T>& s) {
  const Mat3<T> R = *gen::rotation3<T>().as("R");
  const Vec3<T> q = *gen::vec3<T>().as("q");
  const Vec3<T> p = *gen::vec3<T>().as("p");
  const Vec3<T> J = s.momentum_map(q, p);
  const T scale = T(18) * norm_inf(q) * norm_inf(p);
  require_close("J(R q, R p) = R J(q, p), R in SO(3)", s.momentum_map((R * q).eval(), (R * p).eval()), (R * J).eval(),
                scale, 8);
  const Mat3<T> R_improper = -R;
  require_close("J(R' q, R' p) = det(R') R' J(q, p) = -R' J(q, p) for det R' = -1",
                s.momentum_map((R_improper * q).eval(), (R_improper * p).eval()), (-(R_improper * J)).eval(), scale, 8);
}

}  // namespace

GM_PROPERTY(momentum_map_generates_rotations, all_scalars,
            {.spec = "mm.hamiltonian-action",
             .title = "J = p x q; J^xi generates q' = {q, J^xi} = -xi x q, p' = {p, J^xi} = -xi x p",
             .tolerance = ToleranceClass::Exact,
             .needs = {"momentum_map", "canonical_bracket"},
             .negative_controls = {"momentum_map_reversed", "canonical_bracket_sign_flipped"}});

GM_PROPERTY(momentum_map_infinitesimal_equivariance, all_scalars,
            {.spec = "mm.infinitesimal-equivariance",
             .title = "along q' = -xi x q, p' = -xi x p: J' = -xi x J = ad*_xi J",
             .tolerance = ToleranceClass::Exact,
             .needs = {"momentum_map", "ad_star"},
             .negative_controls = {"momentum_map_sign_slip", "ad_star_is_ad"}});

GM_PROPERTY(momentum_map_equivariance, all_scalars,
            {.spec = "mm.equivariance",
             .title = "J(R q, R p) = R J(q, p) for rational R in SO(3); -R' J for improper R'",
             .tolerance = ToleranceClass::Exact,
             .needs = {"momentum_map"},
             .negative_controls = {"momentum_map_sign_slip"}});

}  // namespace properties_momentum_map
}  // namespace gm
