// A family of reduced Lagrangians that are neither quadratic nor diagonal, for the statements of
// the notes that hold "for any Lagrangian" (Theorems 1.1 and 2.3):
//
//   l(xi) = a . xi + s / 2 + c s^2 / 8,   s = xi . K xi,
//
// with a drawn linear term a, a quartic term (c in [0, 1]) and K symmetric, in general not
// diagonal, positive definite: diagonal in [2, 4], off-diagonal entries at most 1/4 in size
// (1/16 when d > 8), so by Gershgorin every eigenvalue is at least 2 - 7/4 (2 - 14/16 at d = 15).
// With c >= 0 the Hessian (1 + c s / 2) K + c (K xi)(K xi)^T is at least K: l is strictly convex,
// the Legendre map xi -> mu = dl/dxi is a diffeomorphism.
//
// Its derivatives are taken by hyper-dual numbers (support/derivatives.hpp), exactly, not by hand:
// l evaluated at xi + e1 u + e2 w has the parts l, dl.u, dl.w and d2l(u, w). Where a flow needs
// them at every evaluation (and the hyper-dual Hessian's d^2 evaluations of l would dominate in 50
// digits), the closed forms
//   dl/dxi = a + (1 + c s / 2) K xi,   d2l/dxi2 = (1 + c s / 2) K + c (K xi)(K xi)^T
// are there too; a property that uses them checks against l itself (its hyper-dual derivative),
// so a slip in them cannot pass unnoticed.
#pragma once

#include "core/linalg.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/generators.hpp"

#include <rapidcheck.h>

#include <vector>

namespace gm {

template <class T>
struct GeneralLagrangian {
  VecX<T> a;
  MatX<T> K;
  T c;

  // l for any scalar S built from T (T itself or hyper-dual numbers over T).
  template <class S>
  S operator()(const std::vector<S>& xi) const {
    S lin(T(0)), s(T(0));
    for (std::size_t i = 0; i < xi.size(); ++i) {
      lin += S(a(static_cast<Eigen::Index>(i))) * xi[i];
      for (std::size_t j = 0; j < xi.size(); ++j)
        s += xi[i] * S(K(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))) * xi[j];
    }
    return lin + s * S(T(1) / T(2)) + S(c / T(8)) * s * s;
  }

  // l at xi + e1 u + e2 w.
  deriv::HyperDual<T> seeded(const VecX<T>& xi, const VecX<T>& u, const VecX<T>& w) const {
    std::vector<deriv::HyperDual<T>> x;
    for (Eigen::Index i = 0; i < xi.size(); ++i) x.emplace_back(xi(i), u(i), w(i), T(0));
    return (*this)(x);
  }
  // dl(xi) . v, the first variation of l at xi in the direction v.
  T derivative(const VecX<T>& xi, const VecX<T>& v) const { return seeded(xi, v, VecX<T>::Zero(xi.size())).b; }
  VecX<T> gradient(const VecX<T>& xi) const {  // mu = dl/dxi
    const auto n = xi.size();
    VecX<T> g(n);
    for (Eigen::Index k = 0; k < n; ++k) g(k) = derivative(xi, VecX<T>::Unit(n, k));
    return g;
  }
  VecX<T> gradient_closed_form(const VecX<T>& xi) const {
    const VecX<T> Kxi = K * xi;
    return (a + (T(1) + c * xi.dot(Kxi) / T(2)) * Kxi).eval();
  }
  MatX<T> hessian_closed_form(const VecX<T>& xi) const {
    const VecX<T> Kxi = K * xi;
    return ((T(1) + c * xi.dot(Kxi) / T(2)) * K + c * Kxi * Kxi.transpose()).eval();
  }
  MatX<T> hessian(const VecX<T>& xi) const {  // symmetric: the upper triangle is computed
    const auto n = xi.size();
    MatX<T> H(n, n);
    for (Eigen::Index k = 0; k < n; ++k)
      for (Eigen::Index j = k; j < n; ++j) H(k, j) = H(j, k) = seeded(xi, VecX<T>::Unit(n, k), VecX<T>::Unit(n, j)).d;
    return H;
  }
};

template <class T>
GeneralLagrangian<T> draw_lagrangian(int d) {
  GeneralLagrangian<T> l{*gen::vec<T>(d, 8, 3).as("a (l(xi) = a . xi + xi.K xi / 2 + c (xi.K xi)^2 / 8)"),
                         MatX<T>::Zero(d, d), T(*rc::gen::inRange(0, 5).as("4 c")) / T(4)};
  for (int i = 0; i < d; ++i) {
    l.K(i, i) = T(*rc::gen::inRange(8, 17).as("4 K_ii")) / T(4);
    for (int j = 0; j < i; ++j) l.K(i, j) = l.K(j, i) = *gen::scalar<T>(d <= 8 ? 4 : 1, 4).as("K_ij");
  }
  return l;
}

}  // namespace gm
