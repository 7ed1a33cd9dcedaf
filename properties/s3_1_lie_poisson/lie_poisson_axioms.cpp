// The Lie-Poisson bracket is a Poisson bracket (Definition 3.3): bilinear, skew-symmetric,
// Leibniz and Jacobi (3.2), for polynomial functions of Pi, in its R^3 form (3.6) (= (2.25)) and in
// its matrix form (2.23)/(3.10), evaluated through the hat map.
//
// The generic checks and their rounding bounds are in support/poisson_axioms.hpp; this file says
// what the two forms are: their slot, the degree of their coefficients in Pi (1: both forms are
// linear in Pi), and a majorant of the formula in absolute values.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_lie_poisson_axioms {
namespace {

// (3.6): {F, G}(Pi) = -Pi . dF x dG. Majorant: the triple product, 6 |Pi| |dF| |dG|.
template <class T>
PointBracket<T> lie_poisson_r3(const Subject<T>& s) {
  PointBracket<T> B;
  B.name = "lie_poisson_3_6";
  B.at = [&s](const VecX<T>& x, const VecX<T>& dF, const VecX<T>& dG) {
    return s.lie_poisson_3_6(Vec3<T>(x), Vec3<T>(dF), Vec3<T>(dG));
  };
  B.structure_degree = 1;
  B.bound = [](const T& R, const T& a, const T& b) { return triple_product_bound(R, a, b); };
  B.ops = kTripleProductOps;
  return B;
}

// (2.23)/(3.10): {F, G}(Pi) = -<Pi_hat, [dF_hat, dG_hat]>, the gradients as skew matrices through
// the hat map (their entries are the vectors' components, so the inputs are exact).
// Majorant: an entry of [A, B] is a sum of 6 products, each <= |a| |b|; the pairing (2.15) sums 9
// products with entries of Pi_hat (<= |Pi|) and halves: (1/2) 9 |Pi| 6 |a| |b| = 27 |Pi| |a| |b|.
// Rounding chain: a commutator entry (two sums of 3 products and a difference: 4) then the pairing
// (a product and a sum of 9 terms: 9; the halving is exact): 13.
template <class T>
PointBracket<T> lie_poisson_matrix(const Subject<T>& s) {
  PointBracket<T> B;
  B.name = "lie_poisson_2_23";
  B.at = [&s](const VecX<T>& x, const VecX<T>& dF, const VecX<T>& dG) {
    return s.lie_poisson_2_23(truth::skew_of<T>(Vec3<T>(x)), truth::skew_of<T>(Vec3<T>(dF)),
                              truth::skew_of<T>(Vec3<T>(dG)));
  };
  B.structure_degree = 1;
  B.bound = [](const T& R, const T& a, const T& b) { return T(T(27) * R * a * b); };
  B.ops = 13;
  return B;
}

template <class T, class MakeBracket>
void bilinear_body(const Subject<T>& s, MakeBracket make) {
  check_bilinear_drawn(make(s), 3);
}

template <class T, class MakeBracket>
void skew_body(const Subject<T>& s, MakeBracket make) {
  const auto B = make(s);
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_skew(B, F, G, x);
}

template <class T, class MakeBracket>
void leibniz_body(const Subject<T>& s, MakeBracket make) {
  const auto B = make(s);
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_leibniz(B, F, G, H, x);
}

template <class T, class MakeBracket>
void jacobi_body(const Subject<T>& s, MakeBracket make) {
  const auto B = make(s);
  const auto F = *gen::polynomial<T>(3).as("F");
  const auto G = *gen::polynomial<T>(3).as("G");
  const auto H = *gen::polynomial<T>(3).as("H");
  const VecX<T> x = *gen::point<T>(3).as("x");
  check_jacobi(B, F, G, H, x);
}

template <class T>
void lie_poisson_3_6_bilinear(const Subject<T>& s) {
  bilinear_body(s, lie_poisson_r3<T>);
}
template <class T>
void lie_poisson_3_6_skew(const Subject<T>& s) {
  skew_body(s, lie_poisson_r3<T>);
}
template <class T>
void lie_poisson_3_6_leibniz(const Subject<T>& s) {
  leibniz_body(s, lie_poisson_r3<T>);
}
template <class T>
void lie_poisson_3_6_jacobi(const Subject<T>& s) {
  jacobi_body(s, lie_poisson_r3<T>);
}

template <class T>
void lie_poisson_2_23_bilinear(const Subject<T>& s) {
  bilinear_body(s, lie_poisson_matrix<T>);
}
template <class T>
void lie_poisson_2_23_skew(const Subject<T>& s) {
  skew_body(s, lie_poisson_matrix<T>);
}
template <class T>
void lie_poisson_2_23_leibniz(const Subject<T>& s) {
  leibniz_body(s, lie_poisson_matrix<T>);
}
template <class T>
void lie_poisson_2_23_jacobi(const Subject<T>& s) {
  jacobi_body(s, lie_poisson_matrix<T>);
}

}  // namespace

GM_PROPERTY(lie_poisson_3_6_bilinear, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "(3.6) is bilinear: {a F1 + b F2, G} = a {F1, G} + b {F2, G}, and in G",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6"},
             .negative_controls = {"lie_poisson_3_6_affine_in_df"}});

GM_PROPERTY(lie_poisson_3_6_skew, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "(3.6) is skew-symmetric: {F, G} = -{G, F}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6"},
             .negative_controls = {"lie_poisson_3_6_with_symmetric_part", "lie_poisson_3_6_affine_in_df"}});

GM_PROPERTY(lie_poisson_3_6_leibniz, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "(3.6) satisfies the Leibniz rule {F G, H} = {F, H} G + F {G, H}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6"},
             .negative_controls = {"lie_poisson_3_6_affine_in_df"}});

GM_PROPERTY(lie_poisson_3_6_jacobi, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "(3.6) satisfies the Jacobi identity (3.2) for polynomial F, G, H of degree <= 4",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6"},
             .negative_controls = {"lie_poisson_3_6_cyclic_index_slip", "lie_poisson_3_6_with_symmetric_part"}});

GM_PROPERTY(lie_poisson_2_23_bilinear, all_scalars,
            {.spec = "s3.lie-poisson-matrix-r3",
             .title = "(3.10) is bilinear in F and in G",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_2_23_affine_in_df"}});

GM_PROPERTY(lie_poisson_2_23_skew, all_scalars,
            {.spec = "s3.lie-poisson-matrix-r3",
             .title = "(3.10) is skew-symmetric: {F, G} = -{G, F}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_2_23_with_symmetric_part"}});

GM_PROPERTY(lie_poisson_2_23_leibniz, all_scalars,
            {.spec = "s3.lie-poisson-matrix-r3",
             .title = "(3.10) satisfies the Leibniz rule {F G, H} = {F, H} G + F {G, H}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_2_23_affine_in_df"}});

GM_PROPERTY(lie_poisson_2_23_jacobi, all_scalars,
            {.spec = "s3.lie-poisson-matrix-r3",
             .title = "(3.10) satisfies the Jacobi identity (3.2) for polynomial F, G, H of degree <= 4",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_2_23_cyclic_index_slip"}});

}  // namespace properties_lie_poisson_axioms
}  // namespace gm
