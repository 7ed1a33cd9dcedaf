// The exercise after Theorem 3.1: "How is the R^3 bracket related to the canonical Poisson
// bracket? Hint: restrict to level surfaces of the function c(x)." The notes give the hint only.
// What is checked, for the rigid body's c = |x|^2/2, whose level surfaces are the
// spheres |x| = r:
//
//   on every sphere, away from the poles, the coordinates (q, p) = (x_3, theta), theta the azimuth,
//   x = (rho cos theta, rho sin theta, q), rho = sqrt(r^2 - q^2), are canonical for (3.13):
//     {q, p} = 1, and for any f, h, {f, h}(x) = df~/dq dh~/dp - df~/dp dh~/dq
//   with f~(q, p) = f(x(q, p)) the restriction; the motion (3.14) restricted to the sphere is
//   Hamilton's canonical equations dq/dt = dh~/dp, dp/dt = -dh~/dq.
//
// (Archimedes: the projection of the sphere onto its circumscribed cylinder keeps area, so
// dq ^ dp is the sphere's area form divided by r, oriented by the inward normal: e_q x e_p = -x,
// which is where the minus sign of (3.13) goes.)
// The bracket at x depends on f and h only through grad f(x) and grad h(x), and the chain rule
// gives df~/dq = grad f . e_q, df~/dp = grad f . e_p with e_q = dx/dq = (-q/rho cos, -q/rho sin, 1)
// and e_p = dx/dp = (-rho sin, rho cos, 0): the statement is checked for arbitrary gradients.
// Points with rational rho, q and (cos, sin) = +-((1 - t^2), 2 t) / (1 + t^2), t = tan(azimuth / 2)
// up to 4 (azimuths within 152 degrees of 0, or of 180 with the sign), make it exact in rationals.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_nambu_level_sets {
namespace {

// A point of a level sphere of c = |x|^2/2 in the coordinates (q, p), with the tangent vectors
// e_q = dx/dq and e_p = dx/dp there.
template <class T>
struct SpherePoint {
  T rho, q, cos, sin;
  Vec3<T> x, e_q, e_p;
};

template <class T>
SpherePoint<T> draw_sphere_point() {
  SpherePoint<T> s;
  s.rho = *gen::positive<T>().as("rho");
  s.q = *gen::scalar<T>().as("q");
  const T t = *gen::scalar<T>(64, 4).as("t");
  const T side = *rc::gen::element(1, -1).as("side") == 1 ? T(1) : T(-1);  // the other half of the circle
  s.cos = side * (T(1) - t * t) / (T(1) + t * t);
  s.sin = side * T(2) * t / (T(1) + t * t);
  s.x = Vec3<T>(s.rho * s.cos, s.rho * s.sin, s.q);
  s.e_q = Vec3<T>(-s.q / s.rho * s.cos, -s.q / s.rho * s.sin, T(1));
  s.e_p = Vec3<T>(-s.rho * s.sin, s.rho * s.cos, T(0));
  return s;
}

// {f, h} of (3.13) with grad c = x equals the canonical bracket of the restrictions in (q, p).
// Round-off: the triple product x . a x b (k = 12 on |x| |a| |b|) against two products of
// directional derivatives, each of size |a| |b| (|q| + rho) <= 3 |a| |b| |x|_inf: k = 32 in all.
template <class T>
void nambu_level_sphere_bracket_is_canonical(const Subject<T>& s) {
  const SpherePoint<T> P = draw_sphere_point<T>();
  const Vec3<T> a = *gen::vec3<T>().as("grad f(x)"), b = *gen::vec3<T>().as("grad h(x)");
  const T canonical = a.dot(P.e_q) * b.dot(P.e_p) - a.dot(P.e_p) * b.dot(P.e_q);
  // The coordinate functions themselves: grad q = e_3, grad p = grad azimuth = (-x_2, x_1, 0) / rho^2.
  const Vec3<T> grad_q(T(0), T(0), T(1));
  const Vec3<T> grad_p(-P.x(1) / (P.rho * P.rho), P.x(0) / (P.rho * P.rho), T(0));
  showing_inputs(
      [&] {
        return named("x (grad c = x)", P.x) + named("x_3", P.q) + named("rho", P.rho) + named("grad f", a) +
               named("grad h", b);
      },
      [&] {
        require_close(
            "with c = |x|^2/2, on the sphere through x: {f, h} of (3.13) equals the canonical bracket "
            "df~/dq dh~/dp - df~/dp dh~/dq in (q, p) = (x_3, azimuth)",
            s.nambu_3_13(P.x, a, b), canonical, T(norm_inf(P.x) * norm_inf(a) * norm_inf(b)), 32);
        require_close("with c = |x|^2/2: {x_3, azimuth} = 1 (q = x_3 and p = azimuth are canonical)",
                      s.nambu_3_13(P.x, grad_q, grad_p), T(1), T(1), 16);
      });
}

// The motion (3.14) with c = |x|^2/2 stays on the sphere and is Hamilton's equations in (q, p):
// dq/dt = dx_3/dt = grad h . e_p, dp/dt = (x_1 dx_2/dt - x_2 dx_1/dt) / rho^2 = -grad h . e_q.
// Round-off: dx/dt ~ |x| |grad h| (k = 4); x . dx/dt (k = 8 on |x|^2 |grad h|); dp/dt rounds to
// eps |grad h| (1 + |x| / rho) on both sides (k = 32).
template <class T>
void nambu_level_sphere_motion_is_canonical(const Subject<T>& s) {
  const SpherePoint<T> P = draw_sphere_point<T>();
  const Vec3<T> dh = *gen::vec3<T>().as("grad h");
  const Vec3<T> v = s.nambu_motion_3_14(P.x, dh);
  const T size_x = norm_inf(P.x), size_h = norm_inf(dh);
  const T dp_dt = (P.x(0) * v(1) - P.x(1) * v(0)) / (P.rho * P.rho);
  showing_inputs([&] { return named("x (grad c = x)", P.x) + named("grad h", dh) + named("dx/dt", v); },
                 [&] {
                   require_close("with c = |x|^2/2, (3.14) is tangent to the sphere: x . dx/dt = 0", T(P.x.dot(v)),
                                 T(0), T(size_x * size_x * size_h), 8);
                   require_close("with c = |x|^2/2, (3.14) on the sphere is Hamilton's dq/dt = dh~/dp (q = x_3)", v(2),
                                 T(dh.dot(P.e_p)), T(size_x * size_h), 8);
                   require_close("with c = |x|^2/2, (3.14) on the sphere is Hamilton's dp/dt = -dh~/dq (p = azimuth)",
                                 dp_dt, T(-dh.dot(P.e_q)), T(size_h * (T(1) + size_x / P.rho)), 32);
                 });
}

}  // namespace

GM_PROPERTY(nambu_level_sphere_bracket_is_canonical, all_scalars,
            {.spec = "s3.nambu-level-sets",
             .title = "exercise after Theorem 3.1: on the level spheres of c = |x|^2/2, (3.13) is the canonical "
                      "bracket in (q, p) = (x_3, azimuth)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_sign_flipped", "nambu_3_13_cyclic_index_slip"}});

GM_PROPERTY(nambu_level_sphere_motion_is_canonical, all_scalars,
            {.spec = "s3.nambu-level-sets",
             .title = "exercise after Theorem 3.1: (3.14) with c = |x|^2/2 stays on the sphere and is Hamilton's "
                      "canonical equations in (q, p) = (x_3, azimuth)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_motion_3_14"},
             .negative_controls = {"nambu_motion_3_14_reversed", "nambu_motion_3_14_half_cross"}});

}  // namespace properties_nambu_level_sets
}  // namespace gm
