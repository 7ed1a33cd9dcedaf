// Negative controls for the bugs that live outside the generic case: code that is
// right on a random box of moderate, generic inputs and wrong on the special inputs the notes and
// real code care about. Each is caught by a direct property drawing from that regime
// (properties/definitions_*.cpp, support/regimes.hpp).
#include "impl/energy.hpp"
#include "impl/euler.hpp"
#include "impl/manakov.hpp"
#include "impl/son.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_regimes {

// Dimension: hat_n written with the so(4) layout in mind: (2.11) for the first three coordinates
// and every further column read from v(3 + i). Right for n = 2, 3 and 4, wrong from n = 5 on.
GM_MUTANT(hat_n_written_for_so4, "hat_n written for n = 4 only (every column after the third read from v(3 + i))",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.hat_n = [](const VecX<T>& v, int n) -> MatX<T> {
              Vec3<T> u = Vec3<T>::Zero();
              for (int i = 0; i < 3 && i < v.size(); ++i) u(n == 2 ? 2 : i) = v(i);
              const Mat3<T> h = ref::hat<T>(u);
              MatX<T> m = MatX<T>::Zero(n, n);
              m.topLeftCorner(std::min(n, 3), std::min(n, 3)) = h.topLeftCorner(std::min(n, 3), std::min(n, 3));
              for (int c = 3; c < n; ++c)
                for (int i = 0; i < c && 3 + i < v.size(); ++i) {
                  m(i, c) = v(3 + i);  // right for c = 3 only: column c starts at c(c-1)/2
                  m(c, i) = -v(3 + i);
                }
              return m;
            };
          });

GM_MUTANT(vee_n_written_for_so4, "vee_n written for n = 4 only (reads the last column, then (2.11) of the rest)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.vee_n = [](const MatX<T>& m) -> VecX<T> {
              const int n = static_cast<int>(m.rows());
              if (n < 3) return VecX<T>::Zero(1);
              VecX<T> v(n * (n - 1) / 2);
              v.head(3) = ref::vee<T>(Mat3<T>(m.topLeftCorner(3, 3)));
              for (int i = 0; i + 3 < v.size(); ++i) v(3 + i) = m(i % (n - 1), n - 1);
              return v;
            };
          });

// Scale: an absolute cut-off, "if |Pi|^2 < 1e-6 the body is at rest". Right for every input of
// the generic box (|Pi| >= 1/64), wrong for a slowly spinning body.
GM_MUTANT(euler_3_8_small_momentum_guard, "(3.8) returning 0 when |Pi|^2 < 1e-6 (an absolute cut-off)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_8 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> {
    if (P.squaredNorm() < T(1e-6)) return Vec3<T>::Zero();
    return ref::euler_3_8<T>(I, P);
  };
});

// Special states: a "fast path" for a body spinning about a principal axis, where the student
// expects dPi/dt = 0 and forgets that only the axis component is zero: right exactly on the
// axis, wrong near it (it tests |Pi_i| against 1e-9 |Pi| instead of 0).
GM_MUTANT(euler_3_7_axis_fast_path, "(3.7) returning 0 when Pi is within 1e-9 of a principal axis", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_3_7 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> {
    using std::abs;
    const T big = P.cwiseAbs().maxCoeff();
    int small = 0;
    for (int i = 0; i < 3; ++i)
      if (abs(P(i)) <= T(1e-9) * big) ++small;
    if (small == 2) return Vec3<T>::Zero();
    return ref::euler_3_7<T>(I, P);
  };
});

// Degenerate bodies: a formula written with I1 - I2 in a denominator and a branch for the
// symmetric top that gets it wrong (uses the spherical-top answer 0 whenever two moments agree).
GM_MUTANT(euler_2_1_symmetric_top_branch, "(2.1) returning 0 whenever two moments are equal", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_2_1 = [](const Vec3<T>& I, const Vec3<T>& W) -> Vec3<T> {
    if (I(0) == I(1) || I(1) == I(2) || I(0) == I(2)) return Vec3<T>::Zero();
    return ref::euler_2_1<T>(I, W);
  };
});

// Precision: Omega = I^-1 Pi computed in double and converted back. Exact in double, and
// wrong in the 17th digit in 50 digits: only a 50-digit check sees it.
GM_MUTANT(omega_3_5_through_double, "(3.5) computed in double precision whatever the scalar", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.omega_3_5 = [](const Vec3<T>& I, const Vec3<T>& P) -> Vec3<T> {
    Vec3<T> W;
    for (int i = 0; i < 3; ++i) W(i) = convert<T>(to_double(P(i)) / to_double(I(i)));
    return W;
  };
});

GM_MUTANT_WRONG_ONLY_IN(omega_3_5_through_double, ScalarKind::MP50, ScalarKind::Exact);

// Precision: the energy with a constant written as a double literal, 0.1 * 5 for the 1/2.
GM_MUTANT(hamiltonian_3_4_double_constant, "(3.4) with the 1/2 written as the double constant 0.1 * 5", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.hamiltonian_3_4 = [](const Vec3<T>& I, const Vec3<T>& P) -> T { return T(0.1) * T(5) * P.dot(P.cwiseQuotient(I)); };
});
GM_MUTANT_WRONG_ONLY_IN(hamiltonian_3_4_double_constant, ScalarKind::MP50, ScalarKind::Exact);

// Structure: Manakov's Omega from M by Omega_ij = M_ij / (A_ii + A_jj), right only for a
// diagonal A (every Manakov property but one used to draw diagonal A).
GM_MUTANT(manakov_Omega_diagonal_A_only, "Omega from (2.34) as M_ij / (A_ii + A_jj): right only for diagonal A",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.manakov_Omega = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> {
              MatX<T> W(M.rows(), M.cols());
              for (Eigen::Index i = 0; i < M.rows(); ++i)
                for (Eigen::Index j = 0; j < M.cols(); ++j) W(i, j) = M(i, j) / (A(i, i) + A(j, j));
              return W;
            };
          });

GM_MUTANT(manakov_2_34_diagonal_A_only, "(2.34) with Omega_ij = M_ij / (A_ii + A_jj): right only for diagonal A",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.manakov_2_34 = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> {
              MatX<T> W(M.rows(), M.cols());
              for (Eigen::Index i = 0; i < M.rows(); ++i)
                for (Eigen::Index j = 0; j < M.cols(); ++j) W(i, j) = M(i, j) / (A(i, i) + A(j, j));
              return (M * W - W * M).eval();
            };
          });

}  // namespace mutants_regimes
}  // namespace gm
