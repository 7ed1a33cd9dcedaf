// Negative controls for the moment of inertia (2.3) and its spatial form (Remark 2.1).
#include "impl/inertia.hpp"
#include "impl/reconstruction.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_inertia {

GM_MUTANT(inertia_bilinear_dot_for_cross, "(2.3) evaluated with dot products, sum m (a . X)(b . X)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.inertia_bilinear_2_3 = [](const VecX<T>& m, const MatX<T>& X, const Vec3<T>& a, const Vec3<T>& b) -> T {
    T sum(0);
    for (Eigen::Index k = 0; k < m.size(); ++k) sum += m(k) * a.dot(X.col(k)) * b.dot(X.col(k));
    return sum;
  };
});

GM_MUTANT(inertia_tensor_missing_identity, "inertia tensor without the |X|^2 Id term, I = -sum m X X^T", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.inertia_tensor_2_3 = [](const VecX<T>& m, const MatX<T>& X) -> Mat3<T> {
    Mat3<T> I = Mat3<T>::Zero();
    for (Eigen::Index k = 0; k < m.size(); ++k) {
      const Vec3<T> Xk = X.col(k);
      I -= m(k) * Xk * Xk.transpose();
    }
    return I;
  };
});

GM_MUTANT(inertia_space_inverted, "I_space written O^-1 I O (the conjugation inverted)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.inertia_space = [](const Mat3<T>& O, const Vec3<T>& I) -> Mat3<T> { return O.transpose() * I.asDiagonal() * O; };
});

}  // namespace mutants_inertia
}  // namespace gm
