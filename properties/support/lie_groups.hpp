// Matrix functions properties use as their own truth: the exponential (any matrix Lie group)
// and the Cayley transform (SO(n)).
#pragma once

#include "core/linalg.hpp"

#include <Eigen/LU>

#include <vector>

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

// The element M of g (spanned by the matrices E) that represents mu in g* through a pairing B:
// B(M, E_k) = mu_k for every k. B(A, C) = tr(A C), ad-invariant on every matrix Lie algebra
// (Theorem 2.3 as corrected in spec/catalogue.json), or the transpose pairing (2.15),
// tr(A^T C) / 2, which is ad-invariant on so(n) only. Exact in rationals.
template <class T>
MatX<T> representative(const std::vector<MatX<T>>& E, const VecX<T>& mu, bool transpose_pairing = false) {
  const auto d = static_cast<Eigen::Index>(E.size());
  MatX<T> G(d, d);
  for (Eigen::Index k = 0; k < d; ++k)
    for (Eigen::Index l = 0; l < d; ++l)
      G(k, l) = transpose_pairing ? T((E[k].transpose() * E[l]).trace() / T(2)) : T((E[k] * E[l]).trace());
  const VecX<T> m = G.fullPivLu().solve(mu);
  MatX<T> M = MatX<T>::Zero(E[0].rows(), E[0].cols());
  for (Eigen::Index k = 0; k < d; ++k) M += m(k) * E[static_cast<std::size_t>(k)];
  return M;
}

}  // namespace gm::lie
