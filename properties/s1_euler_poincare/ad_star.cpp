// ad* (section 1): the definition <ad*_xi mu, eta> := <mu, [xi, eta]> (Theorem 1.1 (iv)) and its
// components (ad*_xi mu)_k = xi^j mu_i c^i_jk (exercise "Components of ad*_xi mu"), for so(3),
// so(4) (in the coordinates of lie_hat and in the R^6 slots) and the non-compact sl(2, R).
//
// The pairing of g* with g is that of a basis with its dual basis, <mu, xi> = mu_i xi^i, so in
// coordinates it is the dot product; the structure constants c^l_jk are read off the subject's own
// matrices: [hat(e_j), hat(e_k)] = c^l_jk hat(e_l).
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <array>
#include <vector>

namespace gm {
namespace properties_ad_star {
namespace {

inline constexpr std::array<LieAlgebraId, 3> kAlgebras{LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2};

// Coordinates in [-4, 4] on the grid 1/4: the identities are bilinear, so small inputs lose
// nothing, and a failing case shrinks in few steps (each step recomputes structure constants in
// Rational, the dominant cost of a negative control).
inline constexpr int kCoordMax = 16;
inline constexpr int kCoordBits = 2;

inline int dimension(LieAlgebraId g) { return g == LieAlgebraId::so4 ? 6 : 3; }

// c[l][j][k] = c^l_jk from a bracket on coordinates.
template <class T, class Bracket>
std::vector<std::vector<std::vector<T>>> structure_constants(int d, Bracket bracket) {
  std::vector<std::vector<std::vector<T>>> c(d, std::vector<std::vector<T>>(d, std::vector<T>(d, T(0))));
  for (int j = 0; j < d; ++j)
    for (int k = 0; k < d; ++k) {
      VecX<T> ej = VecX<T>::Zero(d), ek = VecX<T>::Zero(d);
      ej(j) = T(1);
      ek(k) = T(1);
      const VecX<T> b = bracket(ej, ek);
      for (int l = 0; l < d; ++l) c[l][j][k] = b(l);
    }
  return c;
}

// (ad*_xi mu)_k = xi^j mu_i c^i_jk, written from the exercise.
template <class T>
VecX<T> ad_star_components(const std::vector<std::vector<std::vector<T>>>& c, const VecX<T>& xi, const VecX<T>& mu) {
  const int d = static_cast<int>(xi.size());
  VecX<T> out = VecX<T>::Zero(d);
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < d; ++j)
      for (int i = 0; i < d; ++i) out(k) += xi(j) * mu(i) * c[i][j][k];
  return out;
}

template <class T>
auto matrix_bracket(const Subject<T>& s, LieAlgebraId g) {
  return [&s, g](const VecX<T>& x, const VecX<T>& y) {
    const MatX<T> X = s.lie_hat(g, x), Y = s.lie_hat(g, y);
    return s.lie_vee(g, MatX<T>(X * Y - Y * X));
  };
}

// The R^6 slots are checked first (cheap, so a failure there shrinks fast), then each algebra.
// Sizes: structure constants of these bases are at most 2 in size and each component sums at most
// d^2 products: scale 2 d^2 |xi| |mu|, k = d^2 + 2 (the sum, the two products).
template <class T>
void ad_star_components_exercise(const Subject<T>& s) {
  {
    const VecX<T> xi = *gen::vec<T>(6, kCoordMax, kCoordBits).as("xi");
    const VecX<T> mu = *gen::vec<T>(6, kCoordMax, kCoordBits).as("mu");
    const auto c = structure_constants<T>(
        6, [&s](const VecX<T>& x, const VecX<T>& y) { return VecX<T>(s.so4_bracket_R6(Vec6<T>(x), Vec6<T>(y))); });
    require_close("so(4) = R^6: (ad*_xi mu)_k = xi^j mu_i c^i_jk with c from so4_bracket_R6",
                  VecX<T>(s.ad_star_so4_R6(Vec6<T>(xi), Vec6<T>(mu))), ad_star_components(c, xi, mu),
                  T(T(72) * norm_inf(xi) * norm_inf(mu)), 38);
  }
  for (const LieAlgebraId g : kAlgebras) {
    const int d = dimension(g);
    const VecX<T> xi = *gen::vec<T>(d, kCoordMax, kCoordBits).as("xi");
    const VecX<T> mu = *gen::vec<T>(d, kCoordMax, kCoordBits).as("mu");
    const std::string name = lie_algebra_name(g);
    require_close(name + ": lie_vee(lie_hat(x)) = x", s.lie_vee(g, s.lie_hat(g, xi)), xi, norm_inf(xi), 0);
    const auto c = structure_constants<T>(d, matrix_bracket(s, g));
    require_close(name + ": (ad*_xi mu)_k = xi^j mu_i c^i_jk", s.ad_star(g, xi, mu), ad_star_components(c, xi, mu),
                  T(T(2 * d * d) * norm_inf(xi) * norm_inf(mu)), d * d + 2);
  }
}

// <ad*_xi mu, eta> = <mu, [xi, eta]> with the bracket of the subject's matrices; for so(3),
// ad*_xi mu = mu x xi. Sizes: 2 d^2 |xi| |mu| |eta| summed once more over d: k = d^2 + d + 4.
template <class T>
void ad_star_definition(const Subject<T>& s) {
  {
    const Vec6<T> a = *gen::vec6<T>(kCoordMax, kCoordBits).as("xi (R^6)"),
                  m = *gen::vec6<T>(kCoordMax, kCoordBits).as("mu (R^6)"),
                  e = *gen::vec6<T>(kCoordMax, kCoordBits).as("eta (R^6)");
    require_close("so(4) = R^6: <ad*_xi mu, eta> = <mu, [xi, eta]_R6>", T(s.ad_star_so4_R6(a, m).dot(e)),
                  T(m.dot(s.so4_bracket_R6(a, e))), T(T(72) * norm_inf(a) * norm_inf(m) * norm_inf(e)), 12);
  }
  for (const LieAlgebraId g : kAlgebras) {
    const int d = dimension(g);
    const VecX<T> xi = *gen::vec<T>(d, kCoordMax, kCoordBits).as("xi");
    const VecX<T> mu = *gen::vec<T>(d, kCoordMax, kCoordBits).as("mu");
    const VecX<T> eta = *gen::vec<T>(d, kCoordMax, kCoordBits).as("eta");
    const T scale = T(2 * d * d * d) * norm_inf(xi) * norm_inf(mu) * norm_inf(eta);
    require_close(std::string(lie_algebra_name(g)) + ": <ad*_xi mu, eta> = <mu, [xi, eta]>",
                  T(s.ad_star(g, xi, mu).dot(eta)), T(mu.dot(matrix_bracket(s, g)(xi, eta))), scale, d * d + d + 4);
  }
  const Vec3<T> xi = *gen::vec3<T>(kCoordMax, kCoordBits).as("xi"), mu = *gen::vec3<T>(kCoordMax, kCoordBits).as("mu");
  require_close("so(3): ad*_xi mu = mu x xi", s.ad_star(LieAlgebraId::so3, VecX<T>(xi), VecX<T>(mu)),
                VecX<T>(truth::cross(mu, xi)), T(T(18) * norm_inf(xi) * norm_inf(mu)), 11);
}

}  // namespace

GM_PROPERTY(ad_star_components_exercise, all_scalars,
            {.spec = "s1.ad-star-coordinates",
             .title = "(ad*_xi mu)_k = xi^j mu_i c^i_jk for so(3), so(4) (and its R^6 slots) and sl(2, R)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_hat", "lie_vee", "ad_star", "so4_bracket_R6", "ad_star_so4_R6"},
             .negative_controls = {"ad_star_transposed_structure_constants", "ad_star_minus_ad",
                                   "ad_star_so4_R6_sign_slip"}});

GM_PROPERTY(ad_star_definition, all_scalars,
            {.spec = "s1.ad-star-definition",
             .title = "<ad*_xi mu, eta> = <mu, [xi, eta]> for so(3), so(4), sl(2, R); ad*_xi mu = mu x xi on so(3)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_hat", "lie_vee", "ad_star", "so4_bracket_R6", "ad_star_so4_R6"},
             .negative_controls = {"ad_star_is_ad", "ad_star_minus_ad", "ad_star_so4_R6_sign_slip",
                                   "so4_bracket_R6_sign_slip"}});

}  // namespace properties_ad_star
}  // namespace gm
