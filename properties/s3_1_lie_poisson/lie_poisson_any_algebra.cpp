// Remark 3.2: "The Lie-Poisson bracket in the form (3.10) would apply to any Lie algebra."
// Checked as: for a Lie algebra g with coordinates x in R^d (a basis e_1..e_d) and the dual
// coordinates mu of g*, the bracket
//     {F, G}(mu) = -<mu, [dF/dmu, dG/dmu]>                                           (3.10)
// is a Poisson bracket (Definition 3.3: bilinear, skew-symmetric, Leibniz, Jacobi (3.2)) on
// polynomial functions of mu, for
//   - so(3), so(4) and the non-compact sl(2, R), through the subject's ad*:
//     <mu, [xi, eta]> = <ad*_xi mu, eta>, so {F, G}(mu) = -dG . ad*_{dF} mu (section 1);
// (so(n) for n = 5, 6 through hat_n / vee_n is not checked: support/polynomial.hpp handles at
// most 6 variables, and dim so(5) = 10.)
// The pairing of mu with the algebra is the coordinate pairing of a basis with its dual basis
// (any non-degenerate pairing gives the same bracket up to a linear change of coordinates of
// g*, so the axioms do not depend on it; the notes' (2.15) is this pairing on so(n) in the
// coordinates of hat_n). The generic checks and their rounding bounds are support/poisson_axioms.hpp.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/tolerance.hpp"

#include <string>

namespace gm {
namespace properties_lie_poisson_any_algebra {
namespace {

// Bound on the structure constants |c^i_jk| in the subject's documented coordinates: so(n) in the
// coordinates of hat_n has constants 0, +-1; sl(2, R) with x -> [[x0, x1], [x2, -x0]] has
// [h, e] = 2 e, [h, f] = -2 f, [e, f] = h: constants 0, +-1, +-2.
inline int structure_constant_bound(LieAlgebraId g) { return g == LieAlgebraId::sl2 ? 2 : 1; }
inline int algebra_dim(LieAlgebraId g) { return g == LieAlgebraId::so4 ? 6 : 3; }

// (3.10) through ad*: {F, G}(mu) = -dG . ad*_{dF} mu, (ad*_xi mu)_k = xi^j mu_i c^i_jk.
// Majorant: each component of ad* is a sum of d^2 products |xi_j| |mu_i| |c^i_jk| <= C a R, and the
// dot product sums d of them against |dG| <= b: d^3 C R a b (the formula in absolute values).
// Rounding chain: ad* as a sum of d^2 double products (d^2 + 1), then the dot product (d + 1).
template <class T>
PointBracket<T> lie_poisson_ad_star(const Subject<T>& s, LieAlgebraId g) {
  const int d = algebra_dim(g);
  PointBracket<T> B;
  B.name = std::string("(3.10) on ") + lie_algebra_name(g) + " via ad*";
  B.at = [&s, g](const VecX<T>& mu, const VecX<T>& dF, const VecX<T>& dG) { return T(-dG.dot(s.ad_star(g, dF, mu))); };
  B.structure_degree = 1;
  const int C = structure_constant_bound(g);
  B.bound = [d, C](const T& R, const T& a, const T& b) { return T(T(d * d * d * C) * R * a * b); };
  B.ops = d * d + d + 2;
  return B;
}

// The four axioms of Definition 3.3 for one bracket on R^d, at one random point, for random
// polynomials of degree <= 4 in d variables.
template <class T>
void all_axioms(const PointBracket<T>& B, int d) {
  const auto F = *gen::polynomial<T>(d).as("F");
  const auto G = *gen::polynomial<T>(d).as("G");
  const auto H = *gen::polynomial<T>(d).as("H");
  const T a = *gen::scalar<T>(8, 2).as("a");
  const T b = *gen::scalar<T>(8, 2).as("b");
  const VecX<T> x = *gen::point<T>(d).as("x");
  check_bilinear(B, F, H, G, a, b, x);
  check_skew(B, F, G, x);
  check_leibniz(B, F, G, H, x);
  check_jacobi(B, F, G, H, x);
}

template <class T>
void lie_poisson_any_algebra_ad_star(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::sl2, LieAlgebraId::so4})
    all_axioms(lie_poisson_ad_star(s, g), algebra_dim(g));
}

}  // namespace

GM_PROPERTY(lie_poisson_any_algebra_ad_star, all_scalars,
            {.spec = "s3.lie-poisson-any-algebra",
             .title = "(3.10) -<mu, [dF, dG]> = -dG . ad*_dF mu is a Poisson bracket on so(3)*, sl(2,R)* and so(4)*",
             .tolerance = ToleranceClass::Exact,
             .needs = {"ad_star"},
             .negative_controls = {"ad_star_is_ad", "ad_star_not_a_lie_algebra"},
             .cases = {.d = 100, .mp = 10, .q = 10}});

}  // namespace properties_lie_poisson_any_algebra
}  // namespace gm
