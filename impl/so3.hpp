// The Lie algebra so(3) and its identification with R^3 (section 2 of the notes).
#pragma once

#include "core/linalg.hpp"

namespace gm::ref {

// Hat map (2.11): hat(v)_jk = -v_i eps_ijk, the skew matrix with hat(v) w = v x w.
template <class T>
Mat3<T> hat(const Vec3<T>& v) {
  Mat3<T> m;
  m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
  return m;
}

// Inverse of the hat map on skew matrices: reads v back from the entries below the diagonal.
template <class T>
Vec3<T> vee(const Mat3<T>& m) {
  return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
}

template <class T>
Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return Vec3<T>(a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2), a(0) * b(1) - a(1) * b(0));
}

// Matrix commutator (2.14): [A, B] = AB - BA.
template <class M>
M commutator(const M& a, const M& b) {
  return (a * b - b * a).eval();
}

// Trace pairing (2.15): <A, B> = (1/2) trace(A^T B). With the factor 1/2,
// <hat(a), hat(b)> = a . b.
template <class T>
T pairing(const MatX<T>& a, const MatX<T>& b) {
  return (a.transpose() * b).trace() / T(2);
}

template <class T>
T pairing3(const Mat3<T>& a, const Mat3<T>& b) {
  return (a.transpose() * b).trace() / T(2);
}

}  // namespace gm::ref
