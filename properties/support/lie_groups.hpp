// Matrix functions properties use as their own truth: the exponential (any matrix Lie group)
// and the Cayley transform (SO(n)).
#pragma once

#include "core/linalg.hpp"

#include <Eigen/LU>

namespace gm::lie {

// exp(X) by scaling and squaring of the Taylor series: X / 2^s has norm <= 1/2, the series is
// summed until its terms are below eps, then squared s times. Accurate to a few eps * |exp(X)|
// for the moderate |X| used here, in any floating scalar.
template <class T>
MatX<T> expm(const MatX<T>& X) {
  const auto n = X.rows();
  T norm(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    T row(0);
    for (Eigen::Index j = 0; j < n; ++j) row += abs_value(X(i, j));
    if (row > norm) norm = row;
  }
  int s = 0;
  T scale(1);
  while (norm * scale > T(1) / T(2)) scale /= T(2), ++s;
  const MatX<T> Y = X * scale;
  MatX<T> term = MatX<T>::Identity(n, n), sum = term;
  for (int k = 1; k < 200; ++k) {
    term = (term * Y / T(k)).eval();
    sum += term;
    if (max_abs(term) <= eps<T>() * T(1) / T(16)) break;
  }
  for (int i = 0; i < s; ++i) sum = (sum * sum).eval();
  return sum;
}

// Cayley transform (Id - S)^-1 (Id + S): orthogonal with det 1 for skew S.
template <class T>
MatX<T> cayley(const MatX<T>& S) {
  const auto n = S.rows();
  const MatX<T> Id = MatX<T>::Identity(n, n);
  return (Id - S).partialPivLu().solve(Id + S);
}

}  // namespace gm::lie
