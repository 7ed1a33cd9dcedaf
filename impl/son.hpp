// so(n), the skew-symmetric n x n matrices, with a hat map from R^{n(n-1)/2}.
//
// Coordinates are built recursively: so(n) = so(n-1) + R^{n-1},
//   hat_n(u, v) = [ hat_{n-1}(u)   v ]
//                 [ -v^T           0 ],
// starting from the so(3) hat map (2.11). So the first three coordinates are those of (2.11),
// and for n = 4 the coordinates (u, v) in R^3 x R^3 = R^6 are the "analogue of the hat map for
// so(4)" asked for in the SO(4) exercise of section 1 (see lie_algebras.hpp for its bracket).
// The basis is orthonormal for the pairing (2.15): <hat_n(a), hat_n(b)> = a . b for every n.
#pragma once

#include "impl/so3.hpp"

#include <stdexcept>

namespace gm::ref {

inline int so_dim(int n) { return n * (n - 1) / 2; }

template <class T>
MatX<T> hat_n(const VecX<T>& v, int n) {
  if (n < 2 || v.size() != so_dim(n))
    throw std::invalid_argument("hat_n: vector of length " + std::to_string(v.size()) +
                                " is not a coordinate vector of so(" + std::to_string(n) + ")");
  MatX<T> m = MatX<T>::Zero(n, n);
  if (n == 2) {
    m(0, 1) = -v(0);
    m(1, 0) = v(0);
    return m;
  }
  if (n == 3) {
    m = hat<T>(Vec3<T>(v(0), v(1), v(2)));
    return m;
  }
  const int d = so_dim(n - 1);
  m.topLeftCorner(n - 1, n - 1) = hat_n<T>(v.head(d), n - 1);
  for (int i = 0; i < n - 1; ++i) {
    m(i, n - 1) = v(d + i);
    m(n - 1, i) = -v(d + i);
  }
  return m;
}

template <class T>
VecX<T> vee_n(const MatX<T>& m) {
  const int n = static_cast<int>(m.rows());
  if (n < 2 || m.cols() != n) throw std::invalid_argument("vee_n: not a square matrix of size >= 2");
  VecX<T> v(so_dim(n));
  if (n == 2) {
    v(0) = m(1, 0);
    return v;
  }
  if (n == 3) {
    Mat3<T> m3 = m;
    v = vee<T>(m3);
    return v;
  }
  const int d = so_dim(n - 1);
  v.head(d) = vee_n<T>(m.topLeftCorner(n - 1, n - 1));
  for (int i = 0; i < n - 1; ++i) v(d + i) = m(i, n - 1);
  return v;
}

}  // namespace gm::ref
