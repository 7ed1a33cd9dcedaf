// Small formulas properties use as their own ground truth, written from the definitions, not
// taken from any subject (the reference implementation included).
#pragma once

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

}  // namespace gm::truth
