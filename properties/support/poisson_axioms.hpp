// The defining properties of a Poisson bracket (Definition 3.3), checked for a bracket that the
// subject evaluates from gradients at a point: bilinearity, skew-symmetry, the Leibniz rule and
// the Jacobi identity (3.2), for random polynomial functions (support/polynomial.hpp).
//
// A PointBracket wraps one slot of the subject as {F, G}(x) = B(x; grad F(x), grad G(x)) and
// states what the property needs to know about the bracket of the notes it stands for:
//   - structure_degree: the degree in x of the bracket's coefficients (the Lie-Poisson bracket
//     (3.6) is linear in Pi: 1; the canonical bracket has constant coefficients: 0; the Nambu
//     bracket (3.13) has coefficients grad c: deg c - 1). Then {G, H} is a polynomial of degree
//     <= structure_degree + (deg G - 1) + (deg H - 1), which fixes the interpolation nodes of
//     the Jacobi check (support/line_derivative.hpp) and is certified there;
//   - bound(R, a, b): a majorant of |{F, G}(y)| for |y|_inf <= R, |grad F|_inf <= a,
//     |grad G|_inf <= b, that also bounds the rounding error of the bracket's formula divided by
//     gamma_ops (it is the formula evaluated in absolute values);
//   - ops: the length of the bracket's rounding chain, its coefficients (e.g. grad c) included.
//
// Tolerances (floats only; Rational is exact): every check is |lhs - rhs| <= k eps scale with
// scale the majorant of the terms combined and k the sum of the rounding chains that produced
// them (first-order error analysis: relative errors of a chain of n roundings add up to gamma_n).
#pragma once

#include "properties/support/line_derivative.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"

#include <functional>
#include <string>

namespace gm {

template <class T>
struct PointBracket {
  std::string name;  // how failure messages call it, e.g. "lie_poisson_3_6"
  std::function<T(const VecX<T>& x, const VecX<T>& dF, const VecX<T>& dG)> at;
  int structure_degree = 0;
  std::function<T(const T& R, const T& a, const T& b)> bound;
  int ops = 0;

  // {F, G}(x).
  T operator()(const Polynomial<T>& F, const Polynomial<T>& G, const VecX<T>& x) const {
    return at(x, F.gradient(x), G.gradient(x));
  }
  // Majorant of {F, G} on the box |y|_inf <= R, and the length of its rounding chain.
  T bound_of(const Polynomial<T>& F, const Polynomial<T>& G, const T& R) const {
    return bound(R, F.gradient_bound(R), G.gradient_bound(R));
  }
  int ops_of(const Polynomial<T>& F, const Polynomial<T>& G) const {
    return ops + std::max(F.eval_ops(), G.eval_ops());
  }
};

// |x|_inf as T.
template <class T>
T box_radius(const VecX<T>& x) {
  return norm_inf(x);
}

// Bilinearity in each argument: {a F1 + b F2, G} = a {F1, G} + b {F2, G} and
// {G, a F1 + b F2} = a {G, F1} + b {G, F2}, with a F1 + b F2 formed symbolically.
template <class T>
void check_bilinear(const PointBracket<T>& B, const Polynomial<T>& F1, const Polynomial<T>& F2, const Polynomial<T>& G,
                    const T& a, const T& b, const VecX<T>& x) {
  const Polynomial<T> F = F1.scaled(a) + F2.scaled(b);
  const T R = box_radius(x);
  const T scale = B.bound_of(F, G, R) + abs_value(a) * B.bound_of(F1, G, R) + abs_value(b) * B.bound_of(F2, G, R);
  const int k = std::max({B.ops_of(F, G), B.ops_of(F1, G), B.ops_of(F2, G)}) + 3;  // + a*, b*, +
  require_close(B.name + ": {a F1 + b F2, G} = a {F1, G} + b {F2, G}", B(F, G, x), T(a * B(F1, G, x) + b * B(F2, G, x)),
                scale, k);
  require_close(B.name + ": {G, a F1 + b F2} = a {G, F1} + b {G, F2}", B(G, F, x), T(a * B(G, F1, x) + b * B(G, F2, x)),
                scale, k);
}

// Bilinearity on drawn functions F1, F2, G of `dim` variables (degree <= 3), scalars a, b and a
// point x, each drawn with its name.
template <class T>
void check_bilinear_drawn(const PointBracket<T>& B, int dim) {
  const auto F1 = *gen::polynomial<T>(dim).as("F1");
  const auto F2 = *gen::polynomial<T>(dim).as("F2");
  const auto G = *gen::polynomial<T>(dim).as("G");
  const T a = *gen::scalar<T>(8, 2).as("a");
  const T b = *gen::scalar<T>(8, 2).as("b");
  const VecX<T> x = *gen::point<T>(dim).as("x");
  check_bilinear(B, F1, F2, G, a, b, x);
}

// Skew-symmetry: {F, G} = -{G, F}.
template <class T>
void check_skew(const PointBracket<T>& B, const Polynomial<T>& F, const Polynomial<T>& G, const VecX<T>& x) {
  const T R = box_radius(x);
  require_close(B.name + ": {F, G} = -{G, F}", B(F, G, x), T(-B(G, F, x)), T(T(2) * B.bound_of(F, G, R)),
                B.ops_of(F, G));
}

// Leibniz rule: {F G, H} = {F, H} G + F {G, H}, with the product F G formed symbolically (so its
// gradient comes from its own coefficients, not from the product rule).
template <class T>
void check_leibniz(const PointBracket<T>& B, const Polynomial<T>& F, const Polynomial<T>& G, const Polynomial<T>& H,
                   const VecX<T>& x) {
  const Polynomial<T> FG = F * G;
  const T R = box_radius(x);
  const T scale = B.bound_of(FG, H, R) + B.bound_of(F, H, R) * G.bound(R) + F.bound(R) * B.bound_of(G, H, R);
  const int k = std::max({B.ops_of(FG, H), B.ops_of(F, H) + G.eval_ops(), B.ops_of(G, H) + F.eval_ops()}) + 2;
  require_close(B.name + ": {F G, H} = {F, H} G + F {G, H}", B(FG, H, x), T(B(F, H, x) * G(x) + F(x) * B(G, H, x)),
                scale, k);
}

// Jacobi identity (3.2): {F, {G, H}} + {G, {H, F}} + {H, {F, G}} = 0.
// The inner bracket {G, H} is a black box of x; its gradient is taken by certified interpolation
// along the coordinate axes (support/line_derivative.hpp).
template <class T>
T jacobi_term(const PointBracket<T>& B, const Polynomial<T>& F, const Polynomial<T>& G, const Polynomial<T>& H,
              const VecX<T>& x, T& scale, int& k) {
  const int D = B.structure_degree + std::max(G.degree() - 1, 0) + std::max(H.degree() - 1, 0);
  const CentralNodes<T> nodes = central_nodes<T>(D);
  const T R = box_radius(x) + nodes.radius();
  const T Phi = B.bound_of(G, H, R);  // bounds {G, H} and its rounding on every node
  const int k_phi = B.ops_of(G, H);
  const auto GH = [&](const VecX<T>& y) { return B(G, H, y); };
  const VecX<T> dGH = line_gradient(B.name + ": {G, H}", GH, x, nodes, Phi, k_phi);
  // |d{G, H}| <= W Phi, with error <= gamma_{k_phi + nodes.ops()} W Phi.
  const T r = box_radius(x);
  scale += B.bound(r, F.gradient_bound(r), T(nodes.W * Phi));
  k = std::max(k, B.ops + F.eval_ops() + k_phi + nodes.ops());
  return B.at(x, F.gradient(x), dGH);
}

template <class T>
void check_jacobi(const PointBracket<T>& B, const Polynomial<T>& F, const Polynomial<T>& G, const Polynomial<T>& H,
                  const VecX<T>& x) {
  T scale(0);
  int k = 0;
  const T jacobiator = jacobi_term(B, F, G, H, x, scale, k) + jacobi_term(B, G, H, F, x, scale, k) +
                       jacobi_term(B, H, F, G, x, scale, k);
  require_close(B.name + ": Jacobi identity (3.2), {F, {G, H}} + {G, {H, F}} + {H, {F, G}} = 0", jacobiator, T(0),
                scale, k + 2);
}

// A Casimir C: {C, F} = 0 for every F (section 3.4).
template <class T>
void check_casimir(const PointBracket<T>& B, std::string_view what, const Polynomial<T>& C, const Polynomial<T>& F,
                   const VecX<T>& x) {
  require_close(std::string(what), B(C, F, x), T(0), B.bound_of(C, F, box_radius(x)), B.ops_of(C, F));
}

// The triple-product majorant: |a . (b x c)| and its rounding error / gamma_5 are at most
// sum over the six nonzero eps_ijk of |a_i| |b_j| |c_k| <= 6 |a|_inf |b|_inf |c|_inf.
// (a_i (b_j c_k - b_k c_j): a product, a difference, a product, then a sum of three: 5 roundings.)
inline constexpr int kTripleProductOps = 5;
template <class T>
T triple_product_bound(const T& a, const T& b, const T& c) {
  return T(6) * a * b * c;
}

}  // namespace gm
