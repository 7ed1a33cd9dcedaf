// Vector and matrix types over any of the suite's scalars, and the few helpers every layer
// uses. Include this (not <Eigen/...>) so the multiprecision fix in scalar.hpp is always in force.
#pragma once

#include "core/eigen_kernels.hpp"
#include "core/scalar.hpp"

#include <Eigen/Dense>

namespace gm {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using Vec6 = Eigen::Matrix<T, 6, 1>;
template <class T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template <class T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

// Largest absolute entry (the infinity norm of the entries); exact for Rational.
template <class Derived>
typename Derived::Scalar max_abs(const Eigen::MatrixBase<Derived>& m) {
  using T = typename Derived::Scalar;
  T best(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      T a = m(i, j) < T(0) ? T(-m(i, j)) : T(m(i, j));
      if (a > best) best = a;
    }
  return best;
}

template <class T>
T abs_value(const T& x) {
  return x < T(0) ? T(-x) : x;
}

template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!is_finite(m(i, j))) return false;
  return true;
}

// Entry-wise conversion between scalar types.
template <class To, class Derived>
Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> convert_matrix(
    const Eigen::MatrixBase<Derived>& m) {
  Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = convert<To>(m(i, j));
  return out;
}

}  // namespace gm
