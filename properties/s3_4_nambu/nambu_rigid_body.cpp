// The rigid body as a Nambu motion: (2.27) with c = |Pi|^2 / 2; the motion on the intersections
// of angular-momentum spheres and energy ellipsoids (section 3.4, erratum: the energy is
// (1/2) x . I^-1 x of (3.4), not x . I x); the hyperbolic cylinders for I = diag(1, 1/2, 1/3); the
// system (3.16) and its Nambu form (erratum: the printed answer exchanges a1 and a2).
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_nambu_rigid_body {
namespace {

inline constexpr int kGradientOfH = 16;  // central-difference gradient of h (see lie_poisson.cpp)

// c = |x|^2 / 2 as a polynomial (its gradient is x, computed from its coefficients).
template <class T>
Polynomial<T> half_square_norm() {
  Polynomial<T> c(3);
  for (int i = 0; i < 3; ++i)
    c = c + (Polynomial<T>::coordinate(3, i) * Polynomial<T>::coordinate(3, i)).scaled(T(1) / T(2));
  return c;
}

// (2.27): with c(Pi) = |Pi|^2 / 2, the Lie-Poisson bracket (2.25) is the Nambu bracket
// -grad c . grad f x grad h, the triple scalar product of gradients.
template <class T>
void lie_poisson_is_nambu_2_27(const Subject<T>& s) {
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const Vec3<T> df = *gen::vec3<T>().as("grad f");
  const Vec3<T> dh = *gen::vec3<T>().as("grad h");
  const Vec3<T> dc(half_square_norm<T>().gradient(VecX<T>(P)));
  const T scale = T(6) * norm_inf(P) * norm_inf(df) * norm_inf(dh);
  const T nambu = s.nambu_3_13(dc, df, dh);
  require_close("(2.27): {c, f, h} = -grad c . grad f x grad h", nambu, T(-dc.dot(truth::cross(df, dh))), scale, 10);
  require_close("(2.27): the Nambu bracket with c = |Pi|^2/2 is the Lie-Poisson bracket (2.25)", nambu,
                s.lie_poisson_3_6(P, df, dh), scale, 10);
}

// Section 3.4: for the rigid body (x = Pi), dx/dt = grad c x grad h with c = |x|^2/2 and h the
// Hamiltonian (3.4), and the motion lies on the sphere c = const and on the energy ellipsoid
// h = const (grad c . dx/dt = 0 = grad h . dx/dt). The printed text calls the ellipsoids
// h = x . I x, which is not conserved (literal variant: energy_ellipsoid_x_I_x).
// Sizes: |dx/dt| <= 2 |x|^2 / min I <= 2 |x| Hs, Hs = (|x| + 1)^2 / min I; k = the gradient of h
// (twice: it enters a cross product) + the cross product and a dot product + (3.8) itself.
template <class T>
void rigid_body_sphere_energy_ellipsoid(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> x = *gen::vec3<T>().as("x");
  const Vec3<T> dc(half_square_norm<T>().gradient(VecX<T>(x)));
  const Vec3<T> dh = truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return s.hamiltonian_3_4(I, y); }, x);
  const Vec3<T> x_dot = s.euler_3_8(I, x);
  const T Hs = (norm_inf(x) + T(1)) * (norm_inf(x) + T(1)) / I.minCoeff();
  const T scale = T(6) * (norm_inf(x) + T(1)) * Hs;
  const int k = 2 * kGradientOfH + 4 + 16;
  require_close("section 3.4: (3.8) is the Nambu motion grad c x grad h, c = |x|^2/2, h = (3.4)", x_dot,
                s.nambu_motion_3_14(dc, dh), scale, k);
  require_close("the motion stays on the sphere: grad c . dx/dt = 0", T(dc.dot(x_dot)), T(0),
                T(scale * (norm_inf(x) + T(1))), k + 3);
  require_close("the motion stays on the energy ellipsoid h = const: grad h . dx/dt = 0", T(dh.dot(x_dot)), T(0),
                T(scale * Hs), k + 3);
}

// Exercise (Geometric interpretation), second part: for I = diag(1, 1/2, 1/3), (3.7) keeps
// x1^2 - x3^2 and |x|^2 constant: the motion is on spheres and hyperbolic cylinders. Indeed
// h - 2c = (x3^2 - x1^2)/2 =: k (a recombination of (c, h) of determinant 1), so the motion is also
// grad c x grad k. I3 = 1/3 is rounded in floats; sizes are |x|^3 times the largest 1/I_i = 3.
template <class T>
void rigid_body_hyperbolic_cylinders(const Subject<T>& s) {
  const Vec3<T> I(T(1), T(1) / T(2), T(1) / T(3));
  const Vec3<T> x = *gen::vec3<T>().as("x");
  const T n = norm_inf(x);
  const T scale = T(12) * n * n * n;
  const Vec3<T> x_dot_7 = s.euler_3_7(I, x);
  const Vec3<T> x_dot_8 = s.euler_3_8(I, x);
  for (const auto& [form, x_dot] : {std::pair{"(3.7)", x_dot_7}, std::pair{"(3.8)", x_dot_8}}) {
    require_close(std::string(form) + ": d/dt (x1^2 - x3^2) = 2 (x1 dx1/dt - x3 dx3/dt) = 0",
                  T(T(2) * (x(0) * x_dot(0) - x(2) * x_dot(2))), T(0), scale, 12);
    require_close(std::string(form) + ": d/dt |x|^2 = 2 x . dx/dt = 0", T(T(2) * x.dot(x_dot)), T(0), scale, 12);
  }
  const Vec3<T> dk(-x(0), T(0), x(2));
  require_close("the motion is grad c x grad k, k = (x3^2 - x1^2)/2: sphere meets hyperbolic cylinder", x_dot_8,
                s.nambu_motion_3_14(x, dk), scale, 12);
  const T k_value = (x(2) * x(2) - x(0) * x(0)) / T(2);
  require_close("k = h - 2c with h of (3.4) and c = |x|^2/2", T(s.hamiltonian_3_4(I, x) - x.squaredNorm()), k_value,
                T(T(3) * (n + T(1)) * (n + T(1))), 12);
}

// a1, a2 nonzero on the grid 1/4, a1 + a2 != 0, and a3 from 1/a1 + 1/a2 = 1/a3, in Rational (then
// converted: a3 is rounded in floats).
inline Vec3<Rational> constrained_a(int k1, int k2) {
  if (k1 == 0) k1 = 1;
  if (k2 == 0) k2 = 1;
  if (k1 + k2 == 0) k2 += 1;
  if (k2 == 0) k2 = 2;
  const Rational a1 = Rational(k1) / 4, a2 = Rational(k2) / 4;
  return Vec3<Rational>(a1, a2, Rational(a1 * a2 / (a1 + a2)));
}

template <class T>
Vec3<T> printed_3_16(const Vec3<T>& a, const Vec3<T>& x) {
  return Vec3<T>(-a(0) * a(2) * x(1) * x(2), -a(1) * a(2) * x(2) * x(0), a(0) * a(1) * x(0) * x(1));
}

// Exercise (3.16): with 1/a1 + 1/a2 = 1/a3, the system conserves |x|^2 and is the rigid body
// (3.7) with 1/I1 = u1, 1/I2 = u1 + a1 a2, 1/I3 = u1 + a1 a2 - a1 a3 (u1 free).
// The converse needs a condition the exercise does not state. Write (3.7) as dx1/dt = c1 x2 x3 and
// cyclically, c = (u3 - u2, u1 - u3, u2 - u1), u = 1/I; (3.16) has c1 c2 c3 = (a1 a2 a3)^2 > 0. So
// (3.7) is a (3.16) with real a only if c1 c2 c3 > 0, i.e. I1, I2, I3 increase cyclically (such
// as I = (1, 2, 3)); otherwise one axis must be reversed first (x3 -> -x3 flips the sign of c1 c2 c3).
// The exercise's own example I = diag(1, 1/2, 1/3) has c = (1, -2, 1): checked here as a witness.
template <class T>
void system_3_16_is_rigid_body(const Subject<T>& s) {
  const Vec3<Rational> aq = constrained_a(*gen::signed_int(16).as("4 a1"), *gen::signed_int(16).as("4 a2"));
  const Vec3<T> a = convert_matrix<T>(aq);
  const Vec3<T> x = *gen::vec3<T>(64, 4).as("x");
  const T n = norm_inf(x), an = norm_inf(a);
  const Vec3<T> x_dot = s.nambu_3_16(a, x);
  require_close("nambu_3_16 is (3.16) as printed", x_dot, printed_3_16(a, x), T(an * an * n * n), 6);
  require_close("(3.16) with 1/a1 + 1/a2 = 1/a3 conserves |x|^2: x . dx/dt = 0", T(x.dot(x_dot)), T(0),
                T(T(3) * an * an * n * n * n), 10);
  // The rigid body with these moments (u1 shifted off the values that make some u_i zero).
  Rational u1(*gen::signed_int(8).as("u1"));
  Vec3<Rational> u;
  for (;;) {
    u = Vec3<Rational>(u1, Rational(u1 + aq(0) * aq(1)), Rational(u1 + aq(0) * aq(1) - aq(0) * aq(2)));
    if (u(0) != 0 && u(1) != 0 && u(2) != 0) break;
    u1 += 1;
  }
  require("the rigid body of (3.16) has c1 c2 c3 = (u3 - u2)(u1 - u3)(u2 - u1) > 0",
          (u(2) - u(1)) * (u(0) - u(2)) * (u(1) - u(0)) > 0);
  const Vec3<T> I = convert_matrix<T>(Vec3<Rational>(Rational(1) / u(0), Rational(1) / u(1), Rational(1) / u(2)));
  const T un = convert<T>(Rational(norm_inf(u)));
  require_close("(3.16) is (3.7) with 1/I = (u1, u1 + a1 a2, u1 + a1 a2 - a1 a3)", s.euler_3_7(I, x), x_dot,
                T(T(4) * (un + an * an) * n * n), 12);
  // The coefficients c of (3.16) and of (3.7) read off the subject at x = (1, 1, 1).
  const Vec3<T> ones(T(1), T(1), T(1));
  const Vec3<T> c_316 = s.nambu_3_16(a, ones);
  require("(3.16): c1 c2 c3 = (a1 a2 a3)^2 > 0", c_316(0) * c_316(1) * c_316(2) > T(0), "c = " + show_value(c_316));
  const Vec3<T> c_37 = s.euler_3_7(Vec3<T>(T(1), T(1) / T(2), T(1) / T(3)), ones);
  require("I = diag(1, 1/2, 1/3): (3.7) has c1 c2 c3 < 0, so it is not a (3.16) with real a unless an axis is reversed",
          c_37(0) * c_37(1) * c_37(2) < T(0), "c = " + show_value(c_37));
}

// The answer to (3.16), corrected: dx/dt = (1/4) grad(a2 x1^2 + a3 x3^2) x grad(a1 x2^2 + a3 x3^2),
// i.e. the motion is on the intersections of the orthogonal cylinders A = a2 x1^2 + a3 x3^2 and
// B = a1 x2^2 + a3 x3^2. The printed answer, grad(a1 x1^2 + a3 x3^2) x grad(a2 x2^2 + a3 x3^2) / 4,
// gives (3.16) with a1 and a2 exchanged in its first two equations (literal variant:
// nambu_3_16_as_printed_answer). (The corrected form holds for any a; the constraint only makes it
// a rigid body.)
template <class T>
void system_3_16_nambu_form(const Subject<T>& s) {
  const Vec3<T> a = convert_matrix<T>(constrained_a(*gen::signed_int(16).as("4 a1"), *gen::signed_int(16).as("4 a2")));
  const Vec3<T> x = *gen::vec3<T>(64, 4).as("x");
  const T n = norm_inf(x), an = norm_inf(a);
  const Vec3<T> x_dot = s.nambu_3_16(a, x);
  require_close("nambu_3_16 is (3.16) as printed in the exercise", x_dot, printed_3_16(a, x), T(an * an * n * n), 6);
  const Vec3<T> dA(T(2) * a(1) * x(0), T(0), T(2) * a(2) * x(2));
  const Vec3<T> dB(T(0), T(2) * a(0) * x(1), T(2) * a(2) * x(2));
  require_close("(3.16) = (1/4) grad(a2 x1^2 + a3 x3^2) x grad(a1 x2^2 + a3 x3^2)", x_dot,
                T(T(1) / T(4)) * s.nambu_motion_3_14(dA, dB), T(T(2) * an * an * n * n), 10);
  require_close("(3.16) is tangent to the cylinder a2 x1^2 + a3 x3^2", T(dA.dot(x_dot)), T(0),
                T(T(6) * an * an * an * n * n * n), 10);
  require_close("(3.16) is tangent to the cylinder a1 x2^2 + a3 x3^2", T(dB.dot(x_dot)), T(0),
                T(T(6) * an * an * an * n * n * n), 10);
}

}  // namespace

GM_PROPERTY(lie_poisson_is_nambu_2_27, all_scalars,
            {.spec = "s2.nambu-form",
             .title = "(2.27): with c = |Pi|^2/2 the Lie-Poisson bracket is -grad c . grad f x grad h",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13", "lie_poisson_3_6"},
             .negative_controls = {"nambu_3_13_sign_flipped", "lie_poisson_3_6_sign_flipped"}});

GM_PROPERTY(rigid_body_sphere_energy_ellipsoid, all_scalars,
            {.spec = "s3.nambu-rigid-body-level-sets",
             .title = "section 3.4: (3.8) is grad c x grad h, on spheres c = |x|^2/2 and ellipsoids h = x . I^-1 x / 2",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hamiltonian_3_4", "euler_3_8", "nambu_motion_3_14"},
             .negative_controls = {"energy_ellipsoid_x_I_x", "nambu_motion_3_14_reversed"}});

GM_PROPERTY(
    rigid_body_hyperbolic_cylinders, all_scalars,
    {.spec = "s3.nambu-hyperbolic-cylinders",
     .title = "I = diag(1, 1/2, 1/3): (3.7) keeps x1^2 - x3^2 and |x|^2; motion = grad c x grad (x3^2 - x1^2)/2",
     .tolerance = ToleranceClass::Exact,
     .needs = {"euler_3_7", "euler_3_8", "nambu_motion_3_14", "hamiltonian_3_4"},
     .negative_controls = {"euler_3_7_index_slip", "euler_3_8_I_not_inverted", "nambu_motion_3_14_reversed"}});

GM_PROPERTY(system_3_16_is_rigid_body, all_scalars,
            {.spec = "s3.nambu-3.16",
             .title = "(3.16) with 1/a1 + 1/a2 = 1/a3 conserves |x|^2 and is (3.7) for suitable I",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_16", "euler_3_7"},
             .negative_controls = {"nambu_3_16_as_printed_answer", "euler_3_7_index_slip"}});

GM_PROPERTY(system_3_16_nambu_form, all_scalars,
            {.spec = "s3.nambu-3.16",
             .title = "(3.16) = (1/4) grad(a2 x1^2 + a3 x3^2) x grad(a1 x2^2 + a3 x3^2) (the answer corrected)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_16", "nambu_motion_3_14"},
             .negative_controls = {"nambu_3_16_as_printed_answer", "nambu_motion_3_14_reversed"}});

}  // namespace properties_nambu_rigid_body
}  // namespace gm
