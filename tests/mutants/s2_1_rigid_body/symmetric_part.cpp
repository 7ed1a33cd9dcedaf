// Negative controls for Remark 2.3: the pairing (2.15) on non-skew matrices, and the matrix Euler
// vector field (2.12) on skew matrices.
#include "impl/euler.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_symmetric_part {

// Equal to (2.15) on skew matrices, so it passes every check made with skew arguments only.
GM_MUTANT(pairing_upper_triangle, "pairing computed as sum_{i<j} A_ij B_ij (right on skew matrices only)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.pairing = [](const MatX<T>& a, const MatX<T>& b) -> T {
    T sum(0);
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      for (Eigen::Index j = i + 1; j < a.cols(); ++j) sum += a(i, j) * b(i, j);
    return sum;
  };
});

GM_MUTANT(euler_matrix_anticommutator, "(2.12) with the anticommutator, dPi/dt = -(Omega_hat Pi + Pi Omega_hat)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.euler_matrix_2_12 = [](const Vec3<T>& I, const Mat3<T>& P) -> Mat3<T> {
              const Mat3<T> W = ref::hat<T>(ref::vee<T>(P).cwiseQuotient(I));
              return (-(W * P + P * W)).eval();
            };
          });

GM_MUTANT(euler_matrix_one_sided, "(2.12) with half the commutator, dPi/dt = -Omega_hat Pi", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.euler_matrix_2_12 = [](const Vec3<T>& I, const Mat3<T>& P) -> Mat3<T> {
    const Mat3<T> W = ref::hat<T>(ref::vee<T>(P).cwiseQuotient(I));
    return (-(W * P)).eval();
  };
});

}  // namespace mutants_symmetric_part
}  // namespace gm
