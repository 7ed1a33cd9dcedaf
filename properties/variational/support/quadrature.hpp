// Gauss-Legendre quadrature in any scalar type: nodes by Newton's method on the Legendre
// polynomial (from the usual cos-initial guesses), weights 2 / ((1 - x^2) P_n'(x)^2).
#pragma once

#include "core/linalg.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gm::quad {

template <class T>
struct Rule {
  std::vector<T> x, w;  // on [-1, 1]
};

template <class T>
Rule<T> gauss_legendre(int n) {
  using std::cos;
  Rule<T> r;
  r.x.resize(n);
  r.w.resize(n);
  const T pi = boost::math::constants::pi<T>();
  for (int i = 0; i < n; ++i) {
    T x = cos(pi * (T(i) + T(3) / T(4)) / (T(n) + T(1) / T(2)));
    T dp(0);
    for (int it = 0; it < 100; ++it) {
      // P_n(x) and P_n'(x) by the three-term recurrence.
      T p0(1), p1 = x;
      for (int k = 2; k <= n; ++k) {
        const T p2 = (T(2 * k - 1) * x * p1 - T(k - 1) * p0) / T(k);
        p0 = p1;
        p1 = p2;
      }
      dp = T(n) * (x * p1 - p0) / (x * x - T(1));
      const T dx = p1 / dp;
      x -= dx;
      if (abs_value(dx) <= eps<T>()) break;
    }
    {
      T p0(1), p1 = x;
      for (int k = 2; k <= n; ++k) {
        const T p2 = (T(2 * k - 1) * x * p1 - T(k - 1) * p0) / T(k);
        p0 = p1;
        p1 = p2;
      }
      dp = T(n) * (x * p1 - p0) / (x * x - T(1));
    }
    r.x[i] = x;
    r.w[i] = T(2) / ((T(1) - x * x) * dp * dp);
  }
  return r;
}

// Nodes and weights of the composite rule with `panels` equal panels of an n-point rule on [a, b].
template <class T>
Rule<T> composite(const T& a, const T& b, int n, int panels) {
  const Rule<T> g = gauss_legendre<T>(n);
  Rule<T> r;
  const T H = (b - a) / T(panels);
  for (int p = 0; p < panels; ++p) {
    const T lo = a + T(p) * H;
    for (int i = 0; i < n; ++i) {
      r.x.push_back(lo + (g.x[i] + T(1)) * H / T(2));
      r.w.push_back(g.w[i] * H / T(2));
    }
  }
  // Gauss nodes come in decreasing order within a panel; sort ascending (weights with them).
  std::vector<std::pair<T, T>> xw;
  for (std::size_t i = 0; i < r.x.size(); ++i) xw.emplace_back(r.x[i], r.w[i]);
  std::sort(xw.begin(), xw.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
  for (std::size_t i = 0; i < xw.size(); ++i) r.x[i] = xw[i].first, r.w[i] = xw[i].second;
  return r;
}

}  // namespace gm::quad
