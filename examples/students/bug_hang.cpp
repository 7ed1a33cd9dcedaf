// Buggy: Manakov's Omega found by iterating Omega <- (M - A Omega - Omega A + 2 c Omega) / (2 c)
// "until the residual is exactly zero", which floating point (and exact fractions) never reach.
// The property that calls it ends in TIMEOUT; everything else is still checked.
#include <geomech/student.hpp>

using namespace gm;

struct IterateForever {
  template <class T>
  static MatX<T> manakov_Omega(const MatX<T>& A, const MatX<T>& M) {
    const T c = A.diagonal().maxCoeff();
    MatX<T> W = MatX<T>::Zero(A.rows(), A.cols());
    for (;;) {
      const MatX<T> R = M - (A * W + W * A);
      if (R.cwiseAbs().maxCoeff() == T(0)) break;
      W += R / (T(2) * c);
    }
    return W;
  }
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
};

GEOMECH_STUDENT(IterateForever);
