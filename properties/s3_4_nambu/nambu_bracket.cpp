// Nambu's R^3 bracket (3.13)/(3.15), {f, h} = -grad c . grad f x grad h, for an arbitrary
// polynomial c (degree <= 4), not only for quadratic forms: Theorem 3.1 (Jacobi), the answer to
// the "general conditions on c" exercise (bilinear, skew, Leibniz, divergence-free motion), the
// Casimirs (functions of c), the motion (3.14) and its invariance under unimodular recombination.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_nambu_bracket {
namespace {

// The Nambu bracket of the subject for the function c: its coefficients are grad c, a polynomial of
// degree deg c - 1 whose evaluation adds c's rounding chain.
template <class T>
PointBracket<T> nambu(const Subject<T>& s, const Polynomial<T>& c) {
  PointBracket<T> B;
  B.name = "nambu_3_13";
  B.at = [&s, c](const VecX<T>& x, const VecX<T>& dF, const VecX<T>& dG) {
    return s.nambu_3_13(Vec3<T>(c.gradient(x)), Vec3<T>(dF), Vec3<T>(dG));
  };
  B.structure_degree = std::max(c.degree() - 1, 0);
  B.bound = [c](const T& R, const T& a, const T& b) { return triple_product_bound(c.gradient_bound(R), a, b); };
  B.ops = kTripleProductOps + c.eval_ops();
  return B;
}

template <class T>
void nambu_3_13_bilinear(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  check_bilinear_drawn(nambu(s, c), 3);
}

template <class T>
void nambu_3_13_skew(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_skew(nambu(s, c), F, G, x);
}

template <class T>
void nambu_3_13_leibniz(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_leibniz(nambu(s, c), F, G, H, x);
}

// Theorem 3.1: Jacobi for an arbitrary c (here any polynomial of degree <= 4).
template <class T>
void nambu_jacobi_theorem_3_1(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_jacobi(nambu(s, c), F, G, H, x);
}

// Exercise (3.15): Jacobi for c = x^T C x / 2 with C a random symmetric matrix.
template <class T>
void nambu_jacobi_quadratic_3_15(const Subject<T>& s) {
  const MatX<T> C = *gen::symmetric<T>(3, 8, 2).as("C");
  Polynomial<T> c(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Exponents e{};
      ++e[static_cast<std::size_t>(i)];
      ++e[static_cast<std::size_t>(j)];
      c.add(T(C(i, j) / T(2)), e);
    }
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  require_close("c = x^T C x / 2 has gradient C x", c.gradient(x), (C * x).eval(), T(T(3) * norm_inf(C) * norm_inf(x)),
                6);
  check_jacobi(nambu(s, c), F, G, H, x);
}

// Answer to the exercise on general c: div(grad c x grad h) = 0. Each component of the subject's
// motion (3.14) is differentiated along its own axis by certified interpolation
// (support/line_derivative.hpp); the component is a polynomial of degree (deg c - 1) + (deg h - 1).
// Its size on the nodes' box is <= 2 |grad c| |grad h| (two products), rounded 2 + eval times.
template <class T>
void nambu_motion_divergence_free(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto h = *gen::polynomial<T>(3).as("h");
  const VecX<T> x = *gen::point<T>(3).as("x");
  const int D = std::max(c.degree() - 1, 0) + std::max(h.degree() - 1, 0);
  const CentralNodes<T> nodes = central_nodes<T>(D);
  const T R = norm_inf(x) + nodes.radius();
  const T Phi = T(2) * c.gradient_bound(R) * h.gradient_bound(R);
  const int k_phi = 2 + std::max(c.eval_ops(), h.eval_ops());
  T div(0);
  for (int i = 0; i < 3; ++i) {
    VecX<T> e = VecX<T>::Zero(3);
    e(i) = T(1);
    const auto component = [&](const VecX<T>& y) {
      return s.nambu_motion_3_14(Vec3<T>(c.gradient(y)), Vec3<T>(h.gradient(y)))(i);
    };
    div += line_derivative("nambu_motion_3_14, component " + std::to_string(i + 1), component, x, e, nodes, Phi, k_phi);
  }
  require_close("div(grad c x grad h) = 0", div, T(0), T(T(3) * nodes.W * Phi), k_phi + nodes.ops() + 2);
}

// The proof of Theorem 3.1: X_H = {., H} is the vector field grad c x grad H of (3.14), and the Lie
// bracket of such fields is [X_G, X_H] = -X_{G,H}, with [X, Y]^i = X^j d_j Y^i - Y^j d_j X^i (so that
// [X, Y] f = X(Y f) - Y(X f)). The Jacobians of the subject's motion (3.14) and the gradient of the
// subject's bracket {G, H} are taken by certified interpolation (support/line_derivative.hpp).
// Sizes: on the nodes' box the fields are <= Phi = 2 |grad c| |grad G|, their derivatives <= W Phi,
// {G, H} <= 6 |grad c| |grad G| |grad H|.
template <class T>
void nambu_vector_fields_theorem_3_1(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  auto field = [&s, &c](const Polynomial<T>& F) {
    return [&s, &c, F](const VecX<T>& y) {
      return Vec3<T>(s.nambu_motion_3_14(Vec3<T>(c.gradient(y)), Vec3<T>(F.gradient(y))));
    };
  };
  const auto X_G = field(G), X_H = field(H);
  const int dc = std::max(c.degree() - 1, 0);
  const CentralNodes<T> nodes = central_nodes<T>(dc + std::max(std::max(G.degree(), H.degree()) - 1, 0));
  const T R = norm_inf(x) + nodes.radius(), r = norm_inf(x);
  const int k_field = 2 + std::max({c.eval_ops(), G.eval_ops(), H.eval_ops()});
  auto jacobian = [&](const auto& X, const T& Phi, const std::string& name) {
    Mat3<T> D;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        VecX<T> e = VecX<T>::Zero(3);
        e(j) = T(1);
        D(i, j) = line_derivative(
            name + ", component " + std::to_string(i + 1), [&X, i](const VecX<T>& y) { return X(y)(i); }, x, e, nodes,
            Phi, k_field);
      }
    return D;
  };
  const T Phi_G = T(2) * c.gradient_bound(R) * G.gradient_bound(R),
          Phi_H = T(2) * c.gradient_bound(R) * H.gradient_bound(R);
  const Mat3<T> DX_G = jacobian(X_G, Phi_G, "X_G"), DX_H = jacobian(X_H, Phi_H, "X_H");
  const Vec3<T> lie_bracket = (DX_H * X_G(x) - DX_G * X_H(x)).eval();
  const auto B = nambu(s, c);
  const CentralNodes<T> gh_nodes = central_nodes<T>(dc + std::max(G.degree() - 1, 0) + std::max(H.degree() - 1, 0));
  const T R_gh = r + gh_nodes.radius();
  const T Phi_GH = B.bound_of(G, H, R_gh);
  const VecX<T> dGH = line_gradient(
      B.name + ": {G, H}", [&](const VecX<T>& y) { return B(G, H, y); }, x, gh_nodes, Phi_GH, B.ops_of(G, H));
  const Vec3<T> X_GH = s.nambu_motion_3_14(Vec3<T>(c.gradient(x)), Vec3<T>(dGH));
  const T scale = T(3) * nodes.W *
                      (Phi_H * T(2) * c.gradient_bound(r) * G.gradient_bound(r) +
                       Phi_G * T(2) * c.gradient_bound(r) * H.gradient_bound(r)) +
                  T(2) * c.gradient_bound(r) * gh_nodes.W * Phi_GH;
  const int k = std::max(k_field + nodes.ops() + 3, B.ops_of(G, H) + gh_nodes.ops() + 2 + c.eval_ops()) + 2;
  require_close("proof of Theorem 3.1: [X_G, X_H] = -X_{G,H}, X_H = grad c x grad H", lie_bracket, (-X_GH).eval(),
                scale, k);
}

// Exercise (Casimirs of the R^3 bracket): {Phi(c), h} = 0 for every h, for Phi(c) = a0 + a1 c +
// a2 c^2 (a polynomial of c, formed symbolically), and {c, h} = 0.
template <class T>
void nambu_casimirs_are_functions_of_c(const Subject<T>& s) {
  const auto c = *gen::polynomial<T>(3).as("c");
  const auto h = *gen::polynomial<T>(3).as("h");
  const T a0 = *gen::scalar<T>(8, 2).as("a0");
  const T a1 = *gen::scalar<T>(8, 2).as("a1");
  const T a2 = *gen::scalar<T>(8, 2).as("a2");
  const VecX<T> x = *gen::point<T>(3).as("x");
  const Polynomial<T> Phi_c = Polynomial<T>::constant(3, a0) + c.scaled(a1) + (c * c).scaled(a2);
  const auto B = nambu(s, c);
  check_casimir(B, "{c, h} = 0", c, h, x);
  check_casimir(B, "{a0 + a1 c + a2 c^2, h} = 0", Phi_c, h, x);
}

// (3.13), (3.14): the bracket generates dx/dt = {x, h} = grad c x grad h, which is tangent to the
// level sets of c and of h (grad c . dx/dt = 0 = grad h . dx/dt). The statement is pointwise in
// the gradients, which can be any vectors. Sizes: 6 |dc|^2 |dh| and 6 |dc| |dh|^2.
template <class T>
void nambu_motion_3_14_tangent(const Subject<T>& s) {
  const Vec3<T> dc = *gen::vec3<T>().as("grad c");
  const Vec3<T> dh = *gen::vec3<T>().as("grad h");
  const Vec3<T> x_dot = s.nambu_motion_3_14(dc, dh);
  const T scale = T(6) * norm_inf(dc) * norm_inf(dh) * (norm_inf(dc) + norm_inf(dh));
  for (int i = 0; i < 3; ++i) {
    Vec3<T> e = Vec3<T>::Zero();
    e(i) = T(1);
    require_close("(3.14): dx_" + std::to_string(i + 1) + "/dt = {x_" + std::to_string(i + 1) + ", h}", x_dot(i),
                  s.nambu_3_13(dc, e, dh), T(T(6) * norm_inf(dc) * norm_inf(dh)), 2 * kTripleProductOps);
  }
  require_close("(3.14): dx/dt = grad c x grad h", x_dot, truth::cross(dc, dh), T(T(2) * norm_inf(dc) * norm_inf(dh)),
                4);
  require_close("grad c . dx/dt = 0 (motion on the level sets of c)", T(dc.dot(x_dot)), T(0), scale, 5);
  require_close("grad h . dx/dt = 0 (motion on the level sets of h)", T(dh.dot(x_dot)), T(0), scale, 5);
}

// Exercise (Geometric interpretation), first part: (c, h) -> (alpha c + beta h, gamma c + delta h)
// with alpha delta - beta gamma = 1 leaves the motion unchanged (the gradients recombine the same
// way); in general the motion is multiplied by the determinant. The unimodular matrix is a product
// of three shears with dyadic entries, so it is exact in every scalar and det = 1 exactly.
template <class T>
void nambu_motion_recombination(const Subject<T>& s) {
  const Vec3<T> dc = *gen::vec3<T>().as("grad c");
  const Vec3<T> dh = *gen::vec3<T>().as("grad h");
  const T t1 = *gen::scalar<T>(8, 2).as("t1"), t2 = *gen::scalar<T>(8, 2).as("t2"), t3 = *gen::scalar<T>(8, 2).as("t3");
  const T scale_row = *gen::scalar<T>(8, 2).as("scale_row");
  Eigen::Matrix<T, 2, 2> S1, S2, S3;
  S1 << T(1), t1, T(0), T(1);
  S2 << T(1), T(0), t2, T(1);
  S3 << T(1), t3, T(0), T(1);
  const Eigen::Matrix<T, 2, 2> U = S1 * S2 * S3;  // entries <= 3 * 2^3 in size, exact
  const T det = U(0, 0) * U(1, 1) - U(0, 1) * U(1, 0);
  require_close("the recombination is unimodular", det, T(1), T(0), 0);
  const T u = norm_inf(Eigen::Matrix<T, 2, 2>(U));
  const T d = norm_inf(dc) + norm_inf(dh);
  const Vec3<T> motion = s.nambu_motion_3_14(dc, dh);
  const Vec3<T> dc2 = U(0, 0) * dc + U(0, 1) * dh, dh2 = U(1, 0) * dc + U(1, 1) * dh;
  require_close("grad(alpha c + beta h) x grad(gamma c + delta h) = grad c x grad h (alpha delta - beta gamma = 1)",
                s.nambu_motion_3_14(dc2, dh2), motion, T(T(2) * u * u * d * d), 8);
  // A recombination of determinant `scale_row` (its first row scaled): the motion scales with it.
  const Vec3<T> dc3 = scale_row * dc2;
  require_close("a recombination of determinant D multiplies the motion by D", s.nambu_motion_3_14(dc3, dh2),
                T(scale_row) * motion, T(T(2) * abs_value(scale_row) * u * u * d * d), 10);
}

}  // namespace

GM_PROPERTY(nambu_3_13_bilinear, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "(3.13) with any polynomial c is bilinear in f and in h",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_affine_in_df"}});

GM_PROPERTY(nambu_3_13_skew, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "(3.13) with any polynomial c is skew-symmetric",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_with_symmetric_part"}});

GM_PROPERTY(nambu_3_13_leibniz, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "(3.13) with any polynomial c satisfies the Leibniz rule",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_affine_in_df"}});

GM_PROPERTY(nambu_jacobi_theorem_3_1, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "Theorem 3.1: (3.13) satisfies Jacobi for any c (random polynomials c, F, G, H of degree <= 4)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_cyclic_index_slip", "nambu_3_13_with_symmetric_part"}});

GM_PROPERTY(nambu_jacobi_quadratic_3_15, all_scalars,
            {.spec = "s3.nambu-jacobi-quadratic",
             .title = "Exercise (3.15): Jacobi for c = x^T C x / 2, C symmetric",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_cyclic_index_slip"}});

GM_PROPERTY(nambu_motion_divergence_free, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "div(grad c x grad h) = 0 for polynomial c, h (the answer to the 'general c' exercise)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_motion_3_14"},
             .negative_controls = {"nambu_motion_3_14_half_cross"}});

GM_PROPERTY(nambu_vector_fields_theorem_3_1, all_scalars,
            {.spec = "s3.nambu-poisson",
             .title = "proof of Theorem 3.1: X_H = {., H} = grad c x grad H and [X_G, X_H] = -X_{G,H}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13", "nambu_motion_3_14"},
             .negative_controls = {"nambu_motion_3_14_reversed", "nambu_3_13_cyclic_index_slip"},
             .cases = {.d = 100, .mp = 25, .q = 15}});

GM_PROPERTY(nambu_casimirs_are_functions_of_c, all_scalars,
            {.spec = "s3.nambu-casimirs",
             .title = "{Phi(c), h} = 0 for Phi(c) = a0 + a1 c + a2 c^2 and every polynomial h",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13"},
             .negative_controls = {"nambu_3_13_cyclic_index_slip"}});

GM_PROPERTY(nambu_motion_3_14_tangent, all_scalars,
            {.spec = "s3.nambu-motion",
             .title = "(3.14): dx/dt = {x, h} = grad c x grad h, tangent to the level sets of c and h",
             .tolerance = ToleranceClass::Exact,
             .needs = {"nambu_3_13", "nambu_motion_3_14"},
             .negative_controls = {"nambu_motion_3_14_reversed", "nambu_motion_3_14_half_cross",
                                   "nambu_3_13_sign_flipped"}});

GM_PROPERTY(
    nambu_motion_recombination, all_scalars,
    {.spec = "s3.nambu-recombination",
     .title = "(3.14) is unchanged under (c, h) -> (alpha c + beta h, gamma c + delta h), alpha delta - beta gamma = 1",
     .tolerance = ToleranceClass::Exact,
     .needs = {"nambu_motion_3_14"},
     .negative_controls = {"nambu_motion_3_14_half_cross"}});

}  // namespace properties_nambu_bracket
}  // namespace gm
