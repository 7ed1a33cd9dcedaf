// Spectral quantities of a skew matrix M, computed by the property itself: tr(M^k) and the
// eigenvalues of the symmetric positive semi-definite -M^2 = M^T M (the squares of the moduli of
// M's eigenvalues +-i lambda_j), by the cyclic Jacobi method, which is accurate to round-off in
// any scalar type and needs no Eigen decomposition instantiated for multiprecision types.
#pragma once

#include "core/linalg.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gm::spectral {

// tr(M^k) for k = 1..kmax.
template <class T>
std::vector<T> power_traces(const MatX<T>& M, int kmax) {
  std::vector<T> out;
  MatX<T> P = M;
  for (int k = 1; k <= kmax; ++k) {
    out.push_back(P.trace());
    if (k < kmax) P = (P * M).eval();
  }
  return out;
}

// Eigen-decomposition of a symmetric matrix by cyclic Jacobi rotations, until the off-diagonal
// part is at round-off: S = V diag(values) V^T, values ascending, V's columns the eigenvectors.
template <class T>
struct SymmetricEigen {
  std::vector<T> values;
  MatX<T> vectors;
};

template <class T>
SymmetricEigen<T> symmetric_eigen(MatX<T> S) {
  using std::sqrt;
  const int n = static_cast<int>(S.rows());
  MatX<T> V = MatX<T>::Identity(n, n);
  for (int sweep = 0; sweep < 100; ++sweep) {
    T off(0), diag(0);
    for (int i = 0; i < n; ++i) {
      diag += S(i, i) * S(i, i);
      for (int j = i + 1; j < n; ++j) off += S(i, j) * S(i, j);
    }
    if (off <= eps<T>() * eps<T>() * diag || off == T(0)) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (S(p, q) == T(0)) continue;
        const T theta = (S(q, q) - S(p, p)) / (T(2) * S(p, q));
        const T t = (theta >= T(0) ? T(1) : T(-1)) / (abs_value(theta) + sqrt(theta * theta + T(1)));
        const T c = T(1) / sqrt(t * t + T(1)), s = t * c;
        for (int k = 0; k < n; ++k) {
          const T skp = S(k, p), skq = S(k, q);
          S(k, p) = c * skp - s * skq;
          S(k, q) = s * skp + c * skq;
        }
        for (int k = 0; k < n; ++k) {
          const T spk = S(p, k), sqk = S(q, k);
          S(p, k) = c * spk - s * sqk;
          S(q, k) = s * spk + c * sqk;
        }
        for (int k = 0; k < n; ++k) {
          const T vkp = V(k, p), vkq = V(k, q);
          V(k, p) = c * vkp - s * vkq;
          V(k, q) = s * vkp + c * vkq;
        }
      }
  }
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return S(a, a) < S(b, b); });
  SymmetricEigen<T> out;
  out.vectors = MatX<T>(n, n);
  for (int i = 0; i < n; ++i) {
    out.values.push_back(S(order[i], order[i]));
    out.vectors.col(i) = V.col(order[i]);
  }
  return out;
}

template <class T>
std::vector<T> symmetric_eigenvalues(const MatX<T>& S) {
  return symmetric_eigen<T>(S).values;
}

// Eigenvalues of -M^2 for skew M: lambda_j^2 (each twice, plus a 0 when n is odd).
template <class T>
VecX<T> skew_spectrum(const MatX<T>& M) {
  const auto ev = symmetric_eigenvalues<T>((M.transpose() * M).eval());
  VecX<T> v(static_cast<Eigen::Index>(ev.size()));
  for (std::size_t i = 0; i < ev.size(); ++i) v(static_cast<Eigen::Index>(i)) = ev[i];
  return v;
}

}  // namespace gm::spectral
