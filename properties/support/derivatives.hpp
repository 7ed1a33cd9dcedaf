// Derivatives a property computes for itself: central differences of order 8 (with the step and
// the error model that go with them) and hyper-dual numbers (exact first and mixed second
// derivatives of rational expressions, to round-off).
#pragma once

#include "core/linalg.hpp"

#include <cmath>

namespace gm::deriv {

// Central difference of order 8:
//   f'(x) ~ sum_{m=1..4} c_m (f(x + m d) - f(x - m d)) / d,  c = (4/5, -1/5, 4/105, -1/280).
// Its error is about |f^(9)| d^8 / 630 (truncation) plus sum |c_m| * 2 * eps |f| / d = 2.08 eps |f| / d
// (round-off); with d = eps^(1/9) both are of order eps^(8/9): ~1e-14 in double and ~1e-45 in
// 50 digits, relative to the size of f and its derivatives.
template <class T>
T step8() {
  // The power of two nearest eps^(1/9): exact increments x +- m d for dyadic x.
  const int e = static_cast<int>(std::lround(std::log2(eps_double<T>()) / 9.0));
  T d(1);
  for (int i = 0; i < -e; ++i) d /= T(2);
  return d;
}

// Round-off amplification of the order-8 stencil: sum_m |c_m| * 2 / d (in units of eps |f|).
template <class T>
T roundoff_factor8() {
  return (T(4) / T(5) + T(1) / T(5) + T(4) / T(105) + T(1) / T(280)) * T(2) / step8<T>();
}

namespace detail {
template <class X>
auto evaluated(const X& x) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<X>, X>)
    return x.eval();
  else
    return x;
}
}  // namespace detail

// The derivative at 0 of f: T -> T or an Eigen vector/matrix over T.
template <class T, class F>
auto central8(const F& f, const T& d) {
  const T c[4] = {T(4) / T(5), T(-1) / T(5), T(4) / T(105), T(-1) / T(280)};
  auto acc = detail::evaluated(c[0] * (f(T(d)) - f(T(-d))));
  for (int m = 2; m <= 4; ++m) acc += detail::evaluated(c[m - 1] * (f(T(T(m) * d)) - f(T(-T(m) * d))));
  return detail::evaluated(acc / d);
}

// Hyper-dual number a + b e1 + c e2 + d e1 e2 with e1^2 = e2^2 = 0: evaluating f on
// x + e1 + e2 (per variable) yields f, df/dx1, df/dx2 and d2f/dx1dx2 exactly, up to round-off
// (no step size, no truncation). Only the operations below are supported: enough for rational
// expressions such as the Cayley transform.
template <class T>
struct HyperDual {
  T a{0}, b{0}, c{0}, d{0};
  HyperDual() = default;
  HyperDual(const T& a_) : a(a_) {}
  HyperDual(const T& a_, const T& b_, const T& c_, const T& d_) : a(a_), b(b_), c(c_), d(d_) {}
  friend HyperDual operator+(const HyperDual& x, const HyperDual& y) {
    return {x.a + y.a, x.b + y.b, x.c + y.c, x.d + y.d};
  }
  friend HyperDual operator-(const HyperDual& x, const HyperDual& y) {
    return {x.a - y.a, x.b - y.b, x.c - y.c, x.d - y.d};
  }
  friend HyperDual operator-(const HyperDual& x) { return {-x.a, -x.b, -x.c, -x.d}; }
  friend HyperDual operator*(const HyperDual& x, const HyperDual& y) {
    return {x.a * y.a, x.a * y.b + x.b * y.a, x.a * y.c + x.c * y.a, x.a * y.d + x.b * y.c + x.c * y.b + x.d * y.a};
  }
  friend HyperDual inverse(const HyperDual& y) {
    const T i = T(1) / y.a;
    const T i2 = i * i;
    return {i, -y.b * i2, -y.c * i2, T(2) * y.b * y.c * i2 * i - y.d * i2};
  }
  friend HyperDual operator/(const HyperDual& x, const HyperDual& y) { return x * inverse(y); }
  HyperDual& operator+=(const HyperDual& y) { return *this = *this + y; }
  HyperDual& operator-=(const HyperDual& y) { return *this = *this - y; }
  HyperDual& operator*=(const HyperDual& y) { return *this = *this * y; }
};

}  // namespace gm::deriv
