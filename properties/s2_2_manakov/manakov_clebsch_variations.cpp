// mm.manakov-clebsch, the closing exercise: Hamilton's principle for
//     S(Omega, Q, P) = int l(Omega) + tr(P^T (dQ/dt - Q Omega)) dt,   l = -tr(Omega A Omega)/2,
// varied in P and in Q (variations vanishing at the end points), gives (3.23):
//   - delta P:  int tr(delta P^T (dQ/dt - Q Omega)) dt = 0 for every delta P   <=>  dQ/dt = Q Omega;
//   - delta Q:  int tr(P^T (d(delta Q)/dt - delta Q Omega)) dt
//             = -int tr((dP/dt)^T delta Q) + tr(P^T delta Q Omega) dt  (by parts, end terms 0)
//             = 0 for every delta Q                                        <=>  dP/dt = P Omega
//     (tr(P^T dQ Omega) = tr((P Omega^T)^T dQ) = -tr((P Omega)^T dQ) for skew Omega).
// The variation in Omega (manakov_clebsch_momentum_is_dl_dOmega) fixes Omega through
// A Omega + Omega A = M, M = Q^T P - P^T Q; for diagonal A = diag(a) this is
// Omega_ij = M_ij / (a_i + a_j), written here from the notes (not from the subject).
// The property checks that the subject's (3.23) field (dQ/dt, dP/dt) annihilates both pointwise
// Euler-Lagrange integrands for every elementary variation E_ij (n^2 of them, Q and P being
// general matrices in the action): exactly in rationals, Q and P rational rotations.
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"

#include <cstdio>

namespace gm {
namespace properties_manakov_clebsch_variations {
namespace {

template <class T>
void manakov_clebsch_variations_in_Q_and_P(const Subject<T>& s) {
  const int n = dyn::pick<T>(rc::gen::inRange(3, 6), "n");
  const auto a = dyn::draw_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  const MatX<T> Q = dyn::pick<T>(gen::rotation<T>(n), "Q");
  const MatX<T> P = dyn::pick<T>(gen::rotation<T>(n), "P");
  const MatX<T> M = Q.transpose() * P - P.transpose() * Q;
  MatX<T> W(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) W(i, j) = M(i, j) / (a[i] + a[j]);
  const auto field = s.manakov_clebsch_3_23(A, Q, P);
  const MatX<T>& dQ = field.first;
  const MatX<T>& dP = field.second;
  // Scale: Q, P have entries <= 1, |M|_inf <= 2n, |Omega|_inf <= |M|_inf / (2 min a) <= 2n (a_i >= 1/2);
  // each residual is a sum of n^2-term products of these: n^2 (1 + |Omega|)^2 bounds it, k = 64
  // covers the subject's own rounding of its Omega (a linear solve of size n^2) and the n-term
  // products here, as in manakov_clebsch_momentum_is_dl_dOmega.
  T scale = dyn::at_least_one(T(norm_inf(W) + T(1)));
  scale = scale * scale * T(n * n) * T(2);
  const MatX<T> QW = Q * W, WPt = W * P.transpose();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      // delta P = E_ij: tr(E_ij^T (dQ/dt - Q Omega)) = (dQ/dt - Q Omega)_ij.
      char what[200];
      std::snprintf(what, sizeof what,
                    "closing exercise: delta S / delta P along E_%d%d = (dQ/dt - Q Omega)_%d%d = 0 (first of (3.23))",
                    i + 1, j + 1, i + 1, j + 1);
      require_close(what, dQ(i, j), QW(i, j), scale, 64);
      // delta Q = E_ij: tr((dP/dt)^T E_ij) + tr(P^T E_ij Omega) = (dP/dt)_ij + (Omega P^T)_ji.
      std::snprintf(
          what, sizeof what,
          "closing exercise: delta S / delta Q along E_%d%d = -(dP/dt + (Omega P^T)^T)_%d%d = 0 (second of (3.23))",
          i + 1, j + 1, i + 1, j + 1);
      require_close(what, T(dP(i, j) + WPt(j, i)), T(0), scale, 64);
    }
}

}  // namespace

GM_PROPERTY(
    manakov_clebsch_variations_in_Q_and_P, all_scalars,
    {.spec = "mm.manakov-clebsch",
     .title = "closing exercise: the variations of S in P and in Q give dQ/dt = Q Omega and dP/dt = P Omega (3.23)",
     .tolerance = ToleranceClass::Exact,
     .needs = {"manakov_clebsch_3_23"},
     .negative_controls = {"manakov_clebsch_P_left_multiplied", "manakov_clebsch_M_as_printed"},
     .cases = {.d = 50, .mp = 10, .q = 10}});

}  // namespace properties_manakov_clebsch_variations
}  // namespace gm
