// Small formulas properties use as their own ground truth, written from the definitions, not
// taken from any subject (the reference implementation included).
#pragma once

#include "core/lie_algebra_id.hpp"
#include "core/linalg.hpp"

namespace gm::truth {

// Levi-Civita symbol eps_ijk for indices 0..2.
inline int levi_civita(int i, int j, int k) {
  if (i == j || j == k || i == k) return 0;
  return ((j - i + 3) % 3 == 1) ? 1 : -1;
}

// (a x b)_i = eps_ijk a_j b_k.
template <class T>
Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  Vec3<T> c = Vec3<T>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const int e = levi_civita(i, j, k);
        if (e) c(i) += T(e) * a(j) * b(k);
      }
  return c;
}

// The skew matrix of (2.11) built from eps: m_jk = -v_i eps_ijk.
template <class T>
Mat3<T> skew_of(const Vec3<T>& v) {
  Mat3<T> m = Mat3<T>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const int e = levi_civita(i, j, k);
        if (e) m(j, k) -= T(e) * v(i);
      }
  return m;
}

// Gradient of a function that is a polynomial of degree <= 2, from central differences with
// unit steps: (f(x + e_i) - f(x - e_i)) / 2 is the exact derivative for such f (in exact
// arithmetic; in floats it costs a few roundings of |f|).
template <class T, class F>
Vec3<T> gradient_of_quadratic(F&& f, const Vec3<T>& x) {
  Vec3<T> g;
  for (int i = 0; i < 3; ++i) {
    Vec3<T> xp = x, xm = x;
    xp(i) += T(1);
    xm(i) -= T(1);
    g(i) = (f(xp) - f(xm)) / T(2);
  }
  return g;
}

// so(n) coordinates as documented for the slots hat_n / vee_n (`geomech slots`): so(2) is
// [[0, -v0], [v0, 0]]; for n >= 3 the top-left 3 x 3 block is the hat map (2.11) of (v0, v1, v2),
// and column c >= 3 above the diagonal holds v(c(c-1)/2 + i) in row i (minus it below). Written
// entry by entry, not recursively, so that it shares nothing with an implementation's loops.
inline int so_dimension(int n) { return n * (n - 1) / 2; }

template <class T>
MatX<T> so_n_matrix(const VecX<T>& v, int n) {
  MatX<T> m = MatX<T>::Zero(n, n);
  if (n == 2) {
    m(0, 1) = -v(0);
    m(1, 0) = v(0);
    return m;
  }
  m.topLeftCorner(3, 3) = skew_of(Vec3<T>(v(0), v(1), v(2)));
  for (int c = 3; c < n; ++c)
    for (int i = 0; i < c; ++i) {
      m(i, c) = v(so_dimension(c) + i);
      m(c, i) = -v(so_dimension(c) + i);
    }
  return m;
}

template <class T>
VecX<T> so_n_coordinates(const MatX<T>& m) {
  const int n = static_cast<int>(m.rows());
  VecX<T> v(so_dimension(n));
  if (n == 2) {
    v(0) = m(1, 0);
    return v;
  }
  v(0) = m(2, 1);
  v(1) = m(0, 2);
  v(2) = m(1, 0);
  for (int c = 3; c < n; ++c)
    for (int i = 0; i < c; ++i) v(so_dimension(c) + i) = m(i, c);
  return v;
}

// The three algebras of the slots lie_hat / lie_vee: so(3) and so(4) in the so(n) coordinates
// above, sl(2, R) as (a, b, c) -> [[a, b], [c, -a]].
inline int algebra_dimension(LieAlgebraId g) { return g == LieAlgebraId::so4 ? 6 : 3; }

template <class T>
MatX<T> algebra_matrix(LieAlgebraId g, const VecX<T>& x) {
  if (g == LieAlgebraId::so3) return so_n_matrix<T>(x, 3);
  if (g == LieAlgebraId::so4) return so_n_matrix<T>(x, 4);
  MatX<T> m(2, 2);
  m << x(0), x(1), x(2), -x(0);
  return m;
}

template <class T>
VecX<T> algebra_coordinates(LieAlgebraId g, const MatX<T>& m) {
  if (g != LieAlgebraId::sl2) return so_n_coordinates<T>(m);
  VecX<T> x(3);
  x << m(0, 0), m(0, 1), m(1, 0);
  return x;
}

// ad*_xi mu from its definition <ad*_xi mu, eta> = <mu, [xi, eta]> (Theorem 1.1 (iv)), the pairing
// of g* with g being mu_i eta^i: component k is mu . [xi, e_k], the bracket taken as the matrix
// commutator. (The reference implementation sums structure constants instead.)
template <class T>
VecX<T> ad_star_by_definition(LieAlgebraId g, const VecX<T>& xi, const VecX<T>& mu) {
  const int d = algebra_dimension(g);
  const MatX<T> X = algebra_matrix<T>(g, xi);
  VecX<T> out(d);
  for (int k = 0; k < d; ++k) {
    VecX<T> e = VecX<T>::Zero(d);
    e(k) = T(1);
    const MatX<T> E = algebra_matrix<T>(g, e);
    out(k) = mu.dot(algebra_coordinates<T>(g, MatX<T>(X * E - E * X)));
  }
  return out;
}

}  // namespace gm::truth
