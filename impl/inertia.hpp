// The moment of inertia of a body made of point masses (2.3).
#pragma once

#include "impl/so3.hpp"

#include <stdexcept>

namespace gm::ref {

// (2.3) for point masses m_k at body positions X_k (columns of X):
// (a, b) = sum_k m_k (a x X_k) . (b x X_k).
template <class T>
T inertia_bilinear_2_3(const VecX<T>& m, const MatX<T>& X, const Vec3<T>& a, const Vec3<T>& b) {
  if (X.rows() != 3 || X.cols() != m.size())
    throw std::invalid_argument("inertia_bilinear_2_3: X must be 3 x N with N = number of masses");
  T s(0);
  for (Eigen::Index k = 0; k < m.size(); ++k) {
    const Vec3<T> Xk = X.col(k);
    s += m(k) * cross<T>(a, Xk).dot(cross<T>(b, Xk));
  }
  return s;
}

// The tensor of (2.3): I = sum_k m_k (|X_k|^2 Id - X_k X_k^T), so that (a, b) = I a . b.
template <class T>
Mat3<T> inertia_tensor_2_3(const VecX<T>& m, const MatX<T>& X) {
  if (X.rows() != 3 || X.cols() != m.size())
    throw std::invalid_argument("inertia_tensor_2_3: X must be 3 x N with N = number of masses");
  Mat3<T> I = Mat3<T>::Zero();
  for (Eigen::Index k = 0; k < m.size(); ++k) {
    const Vec3<T> Xk = X.col(k);
    I += m(k) * (Xk.squaredNorm() * Mat3<T>::Identity() - Xk * Xk.transpose());
  }
  return I;
}

}  // namespace gm::ref
