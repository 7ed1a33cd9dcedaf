// Exact derivatives of black-box functions that are polynomials of known degree along lines.
//
// The Jacobi identity needs the gradient of x -> {g, h}(x) = B(x; grad g(x), grad h(x)), where B
// is the subject's bracket: a black box that only takes gradients at a point. For the brackets of
// the notes and polynomial g, h (and c), s -> {g, h}(x + s v) is a polynomial in s of a degree D
// the property knows (e.g. 1 + (deg g - 1) + (deg h - 1) for the Lie-Poisson bracket (3.6), which
// is linear in Pi). Its derivative at s = 0 is then a fixed linear combination of its values at
// 2m + 1 >= D + 1 nodes s_k = k h, k = -m..m (the derivative of the Lagrange interpolant):
//   d/ds phi(x + s v)|_0 = sum_k w_k phi(x + s_k v),
// exactly in Rational (nodes and weights are rational) and with a bounded number of roundings in
// floats (the nodes are dyadic, so x + s_k v is exact; the weights are rounded once).
//
// Why not differentiate through the subject with automatic differentiation? The slots are typed on
// the scalar T; a student's implementation cannot be re-instantiated on a dual-number type. Why
// not assume B is multilinear and use the product rule with Hessians? That would test the identity
// only for subjects that meet the assumption; a subject that does not is exactly what a negative
// control is. Interpolation assumes only the degree bound, and the degree bound is certified:
// the interpolant through the 2m + 1 nodes must predict the value at one more node, s = (m + 1) h.
// A subject whose bracket is not a polynomial of degree <= 2m along the line (not the notes'
// bracket, e.g. one that divides by |Pi|^2) fails that certificate with its own message instead of
// producing a meaningless derivative; in Rational the certificate is exact, in floats it is judged
// with the a-priori rounding bound below.
//
// Rounding in floats. If every value phi(y) at the nodes is bounded by Phi and computed with error
// <= gamma_k Phi, the derivative has error <= gamma_{k + 2m + 2} W Phi, W = sum_k |w_k| (one more
// rounding per weight and a sequential sum of 2m + 1 terms). The certificate compares sum_k l_k
// phi(s_k) with phi(s_{m+1}): error <= gamma_{k + 2m + 2} (L + 1) Phi, L = sum_k |l_k| (the
// Lebesgue sum of the extrapolation, 2^{2m+1} - 1 for equispaced nodes).
#pragma once

#include "core/linalg.hpp"
#include "properties/support/tolerance.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace gm {

// Node spacing: dyadic, so the nodes x + k h e_i are exact in every scalar; small, so the box the
// nodes span (radius |x|_inf + (m + 1) h) is not much larger than |x|_inf and the bounds stay tight.
inline constexpr int kLineStepBits = 3;  // h = 1/8

template <class T>
struct CentralNodes {
  int m = 0;                                 // nodes s_k = k h, k = -m..m: exact for polynomials of degree <= 2m
  T h;                                       // node spacing
  std::vector<T> s;                          // the 2m + 1 nodes, in order k = -m..m
  std::vector<T> w;                          // derivative weights at 0 (divided by h)
  std::vector<T> l;                          // Lagrange weights of the value at the certificate node (m + 1) h
  T s_check;                                 // the certificate node
  T W;                                       // sum |w_k|, rounded up to no less than the exact value
  T L;                                       // sum |l_k|
  int ops() const { return 2 * m + 2; }      // roundings added by the weighted sum
  T radius() const { return T(m + 1) * h; }  // how far the nodes (and the check node) reach
};

// Nodes and weights exact for polynomials of degree <= `degree` (at least 2 nodes' worth).
// The weights are computed in Rational from the Lagrange basis and converted once.
template <class T>
CentralNodes<T> central_nodes(int degree) {
  const int m = degree < 1 ? 1 : (degree + 1) / 2;
  const int N = 2 * m + 1;
  Rational h(1);
  for (int b = 0; b < kLineStepBits; ++b) h /= 2;
  std::vector<Rational> t(N);
  for (int k = 0; k < N; ++k) t[k] = Rational(k - m);
  const Rational t_check(m + 1);
  CentralNodes<T> c;
  c.m = m;
  c.h = convert<T>(h);
  c.s_check = convert<T>(Rational(t_check * h));
  Rational W(0), L(0);
  for (int k = 0; k < N; ++k) {
    // l_k(t) = prod_{j != k} (t - t_j) / (t_k - t_j); l_k'(0) = sum_{j != k} 1/(t_k - t_j) prod_{i != k, j} (0 - t_i)/(t_k - t_i).
    Rational denom(1), value(1), deriv(0);
    for (int j = 0; j < N; ++j) {
      if (j == k) continue;
      denom *= (t[k] - t[j]);
      value *= (t_check - t[j]);
    }
    for (int j = 0; j < N; ++j) {
      if (j == k) continue;
      Rational prod(1);
      for (int i = 0; i < N; ++i)
        if (i != k && i != j) prod *= (Rational(0) - t[i]);
      deriv += prod;
    }
    const Rational wk = deriv / denom / h;  // derivative with respect to s = t h
    const Rational lk = value / denom;
    c.s.push_back(convert<T>(Rational(t[k] * h)));
    c.w.push_back(convert<T>(wk));
    c.l.push_back(convert<T>(lk));
    W += abs_value(wk);
    L += abs_value(lk);
  }
  // Rounded to the nearest T, then enlarged by a relative 2^-20 so the bound is never below the
  // exact sum (the bounds are only used to scale tolerances in floats).
  const Rational widen = Rational(1) + Rational(1) / Rational(1 << 20);
  c.W = convert<T>(Rational(W * widen));
  c.L = convert<T>(Rational(L * widen));
  return c;
}

// Directional derivative at s = 0 of s -> phi(x + s v), for phi a polynomial of degree <= 2m
// along the line (certified, see above). `Phi` bounds |phi| on the box |y - x|_inf <= radius();
// `k_phi` is the length of phi's rounding chain. Returns the derivative; the certificate is a
// require_close, so a failing certificate fails the property with `what` in its message.
template <class T, class F>
T line_derivative(std::string_view what, const F& phi, const VecX<T>& x, const VecX<T>& v, const CentralNodes<T>& nodes,
                  const T& Phi, int k_phi) {
  std::vector<T> values;
  values.reserve(nodes.s.size());
  for (const T& s : nodes.s) values.push_back(phi(VecX<T>(x + s * v)));
  T d(0), predicted(0);
  for (std::size_t k = 0; k < values.size(); ++k) {
    d += nodes.w[k] * values[k];
    predicted += nodes.l[k] * values[k];
  }
  const T checked = phi(VecX<T>(x + nodes.s_check * v));
  require_close(std::string(what) + ": is a polynomial of degree <= " + std::to_string(2 * nodes.m) +
                    " along the line (interpolant predicts the next node)",
                predicted, checked, T((nodes.L + T(1)) * Phi), k_phi + nodes.ops());
  return d;
}

// Gradient of phi at x from line derivatives along the coordinate axes.
template <class T, class F>
VecX<T> line_gradient(std::string_view what, const F& phi, const VecX<T>& x, const CentralNodes<T>& nodes, const T& Phi,
                      int k_phi) {
  const Eigen::Index n = x.size();
  VecX<T> g(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    VecX<T> e = VecX<T>::Zero(n);
    e(i) = T(1);
    g(i) = line_derivative(what, phi, x, e, nodes, Phi, k_phi);
  }
  return g;
}

}  // namespace gm
