// The canonical Poisson bracket on T*R^3 (section 3.5, Remark 3.1): {Q_i, P_j} = delta_ij,
// {Q_i, Q_j} = 0 = {P_i, P_j}, and the axioms of Definition 3.3 for polynomial functions of
// (q, p) in R^6.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_canonical_bracket {
namespace {

// {F, G} = dF/dq . dG/dp - dF/dp . dG/dq: constant coefficients (structure degree 0).
// Majorant: two dot products of three terms, 6 |dF| |dG|; rounding chain: a product, a sum of
// three (3), a difference: 4.
template <class T>
PointBracket<T> canonical(const Subject<T>& s) {
  PointBracket<T> B;
  B.name = "canonical_bracket";
  B.at = [&s](const VecX<T>&, const VecX<T>& dF, const VecX<T>& dG) {
    return s.canonical_bracket(Vec3<T>(dF.head(3)), Vec3<T>(dF.tail(3)), Vec3<T>(dG.head(3)), Vec3<T>(dG.tail(3)));
  };
  B.structure_degree = 0;
  B.bound = [](const T&, const T& a, const T& b) { return T(T(6) * a * b); };
  B.ops = 4;
  return B;
}

// The brackets of the coordinates, as given in the exercise after Remark 3.5.
template <class T>
void canonical_bracket_coordinates(const Subject<T>& s) {
  const Vec3<T> zero = Vec3<T>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Vec3<T> ei = zero, ej = zero;
      ei(i) = T(1);
      ej(j) = T(1);
      const std::string ij = std::to_string(i + 1) + ", " + std::to_string(j + 1);
      require_close("{Q_i, P_j} = delta_ij for i, j = " + ij, s.canonical_bracket(ei, zero, zero, ej),
                    T(i == j ? 1 : 0), T(6), 4);
      require_close("{P_i, Q_j} = -delta_ij for i, j = " + ij, s.canonical_bracket(zero, ei, ej, zero),
                    T(i == j ? -1 : 0), T(6), 4);
      require_close("{Q_i, Q_j} = 0 for i, j = " + ij, s.canonical_bracket(ei, zero, ej, zero), T(0), T(6), 4);
      require_close("{P_i, P_j} = 0 for i, j = " + ij, s.canonical_bracket(zero, ei, zero, ej), T(0), T(6), 4);
    }
}

template <class T>
void canonical_bracket_bilinear(const Subject<T>& s) {
  check_bilinear_drawn(canonical(s), 6);
}

template <class T>
void canonical_bracket_skew(const Subject<T>& s) {
  const auto F = *gen::polynomial<T>(6).as("F");
  const auto G = *gen::polynomial<T>(6).as("G");
  const VecX<T> x = *gen::point<T>(6).as("x");
  check_skew(canonical(s), F, G, x);
}

template <class T>
void canonical_bracket_leibniz(const Subject<T>& s) {
  const auto F = *gen::polynomial<T>(6).as("F");
  const auto G = *gen::polynomial<T>(6).as("G");
  const auto H = *gen::polynomial<T>(6).as("H");
  const VecX<T> x = *gen::point<T>(6).as("x");
  check_leibniz(canonical(s), F, G, H, x);
}

template <class T>
void canonical_bracket_jacobi(const Subject<T>& s) {
  const auto F = *gen::polynomial<T>(6).as("F");
  const auto G = *gen::polynomial<T>(6).as("G");
  const auto H = *gen::polynomial<T>(6).as("H");
  const VecX<T> x = *gen::point<T>(6).as("x");
  check_jacobi(canonical(s), F, G, H, x);
}

}  // namespace

GM_PROPERTY(canonical_bracket_coordinates, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "canonical brackets: {Q_i, P_j} = delta_ij = -{P_j, Q_i}, {Q_i, Q_j} = 0 = {P_i, P_j}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"canonical_bracket"},
             .negative_controls = {"canonical_bracket_sign_flipped", "canonical_bracket_symmetric"}});

GM_PROPERTY(canonical_bracket_bilinear, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "the canonical bracket is bilinear (polynomials on R^6)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"canonical_bracket"},
             .negative_controls = {"canonical_bracket_affine_in_df"}});

GM_PROPERTY(canonical_bracket_skew, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "the canonical bracket is skew-symmetric",
             .tolerance = ToleranceClass::Exact,
             .needs = {"canonical_bracket"},
             .negative_controls = {"canonical_bracket_symmetric"}});

GM_PROPERTY(canonical_bracket_leibniz, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "the canonical bracket satisfies the Leibniz rule",
             .tolerance = ToleranceClass::Exact,
             .needs = {"canonical_bracket"},
             .negative_controls = {"canonical_bracket_affine_in_df"}});

GM_PROPERTY(canonical_bracket_jacobi, all_scalars,
            {.spec = "s3.poisson-bracket-axioms",
             .title = "the canonical bracket satisfies the Jacobi identity (3.2) (polynomials of degree <= 4 on R^6)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"canonical_bracket"},
             .negative_controls = {"canonical_bracket_symmetric"}});

}  // namespace properties_canonical_bracket
}  // namespace gm
