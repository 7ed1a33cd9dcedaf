// Pointwise forms of two dynamical ingredients, checked exactly: the reconstruction formula
// (2.10) and the recovery of Manakov's Omega from M (2.34). Flows along them are checked by integrating;
// these catch the convention mistakes (a right-invariant reconstruction, an Omega recovered as if
// A commuted with it) at a single point, with exact rational inputs.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_pointwise_dynamics {
namespace {

// (2.10): dO/dt = O hat(Omega), so O^-1 dO/dt = hat(Omega) (left-invariant). O is an exact
// rational rotation (rounded once in floats, identically on both sides). Each entry of O hat(W)
// is a sum of two products of terms of size <= |W| (|O_ij| <= 1): at most 4 roundings of size
// |W| on each side, hence k = 8 with scale |W|.
template <class T>
void reconstruction_is_left_invariant(const Subject<T>& s) {
  const Mat3<T> O = *gen::rotation3<T>().as("O");
  const Vec3<T> W = *gen::vec3<T>().as("Omega");
  const Mat3<T> expected = O * truth::skew_of(W);
  require_close("reconstruction_2_10(O, Omega) = O hat(Omega), i.e. O^-1 dO/dt = hat(Omega) (left-invariant)",
                s.reconstruction_2_10(O, W), expected, T(norm_inf(W)), 8);
}

// A symmetric positive-definite n x n matrix R diag(a) R^T with R an exact rational rotation
// (or the identity, for the diagonal A of the notes' examples) and a_i in [1/4, 16]; computed in
// Rational, then rounded once entrywise (so it stays exactly symmetric).
template <class T>
MatX<T> draw_inertia_matrix(int n) {
  const bool diagonal = *rc::gen::arbitrary<bool>().as("A diagonal");
  const VecX<Rational> a =
      *rc::gen::map(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n), rc::gen::inRange(1, 65)),
                    [](const std::vector<int>& ks) {
                      VecX<Rational> v(static_cast<Eigen::Index>(ks.size()));
                      for (std::size_t i = 0; i < ks.size(); ++i)
                        v(static_cast<Eigen::Index>(i)) = Rational(ks[i]) / Rational(4);
                      return v;
                    })
           .as("a (A = R diag(a) R^T)");
  MatX<Rational> A = a.asDiagonal();
  if (!diagonal) {
    const MatX<Rational> R = *gen::rotation<Rational>(n).as("R (A = R diag(a) R^T)");
    A = (R * A * R.transpose()).eval();
  }
  return convert_matrix<T>(A);
}

// (2.34): the Omega a subject recovers from M solves A Omega + Omega A = M. In rationals exactly.
// In floats the recovery is a linear solve of the n^2 equations, each with at most 2n terms of
// size |A| |Omega|: a backward-stable solve leaves a residual of a few n^2 roundings of
// 2n |A| |Omega|, and evaluating A Omega + Omega A here adds 2n more: k = n^2 + 2n with scale
// 2n |A| |Omega|.
template <class T>
void manakov_omega_solves_2_34(const Subject<T>& s) {
  const int n = *rc::gen::inRange(3, 6).as("n");
  const MatX<T> A = draw_inertia_matrix<T>(n);
  const MatX<T> M = *gen::skew<T>(n).as("M");
  const MatX<T> W = s.manakov_Omega(A, M);
  require(
      "manakov_Omega(A, M) is n x n", W.rows() == n && W.cols() == n,
      "got a " + std::to_string(W.rows()) + " x " + std::to_string(W.cols()) + " matrix for n = " + std::to_string(n));
  const T scale = T(2 * n) * norm_inf(A) * norm_inf(W);
  require_close("A Omega + Omega A = M for Omega = manakov_Omega(A, M)", (A * W + W * A).eval(), M, scale,
                n * n + 2 * n);
}

}  // namespace

GM_PROPERTY(
    reconstruction_is_left_invariant, all_scalars,
    {.spec = "s2.reconstruction-formula",
     .title = "(2.10): dO/dt = O hat(Omega), so O^-1 dO/dt = hat(Omega) (left-invariant, body angular velocity)",
     .tolerance = ToleranceClass::Exact,
     .needs = {"reconstruction_2_10"},
     .negative_controls = {"reconstruction_right_invariant"}});

GM_PROPERTY(manakov_omega_solves_2_34, all_scalars,
            {.spec = "s2.manakov-momentum",
             .title = "(2.34): the Omega recovered from M solves A Omega + Omega A = M (A symmetric positive definite)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"manakov_Omega"},
             .negative_controls = {"manakov_Omega_as_if_commuting"},
             .cases = {.d = 100, .mp = 25, .q = 15}});

}  // namespace properties_pointwise_dynamics
}  // namespace gm
