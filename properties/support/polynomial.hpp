// Test functions for the Poisson-bracket properties: multivariate polynomials with exact
// derivatives in every scalar.
//
// Jacobi and Leibniz (Definition 3.3) are statements about arbitrary functions, and checking
// them needs first and second derivatives. A polynomial with dyadic coefficients, evaluated at a
// dyadic point, has exact value, gradient and Hessian in Rational, and in double and Real50 they
// are computed with a few roundings whose size the property can bound a priori: for |y|_inf <= R,
//   |p(y)| <= sum_terms |c| R^deg =: bound(R),
// and evaluating p term by term (powers by repeated multiplication, then a sequential sum) makes
// a relative error of at most gamma_n on that majorant, n = eval_ops() (Higham, ch. 3 and 5).
//
// Products, sums and substitution (f(P x Q) as a polynomial in (Q, P)) are symbolic, so the
// gradient of a product or of a composition is computed from its own coefficients, not from the
// product or chain rule: Leibniz and the Clebsch map are then checked, not assumed.
#pragma once

#include "core/linalg.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/show.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace gm {

inline constexpr int kMaxPolynomialVars = 6;
using Exponents = std::array<int, kMaxPolynomialVars>;

inline int total_degree(const Exponents& e) {
  int d = 0;
  for (int k : e) d += k;
  return d;
}

template <class T>
struct Monomial {
  T coef;
  Exponents e;  // entries past the polynomial's number of variables are 0
};

template <class T>
class Polynomial {
 public:
  Polynomial() = default;
  explicit Polynomial(int n) : n_(n) {
    if (n < 1 || n > kMaxPolynomialVars) throw std::invalid_argument("Polynomial: 1 to 6 variables");
  }

  static Polynomial constant(int n, const T& c) {
    Polynomial p(n);
    p.add(c, Exponents{});
    return p;
  }
  // The coordinate function x_i.
  static Polynomial coordinate(int n, int i) {
    Polynomial p(n);
    Exponents e{};
    e[static_cast<std::size_t>(i)] = 1;
    p.add(T(1), e);
    return p;
  }

  int vars() const { return n_; }
  const std::vector<Monomial<T>>& terms() const { return terms_; }

  // Largest total degree of a term (0 for constants and for the zero polynomial).
  int degree() const {
    int d = 0;
    for (const auto& t : terms_) d = std::max(d, total_degree(t.e));
    return d;
  }

  // Adds c x^e, merging it with a term of the same exponents; terms that cancel are dropped.
  void add(const T& c, const Exponents& e) {
    if (c == T(0)) return;
    for (auto it = terms_.begin(); it != terms_.end(); ++it)
      if (it->e == e) {
        it->coef += c;
        if (it->coef == T(0)) terms_.erase(it);
        return;
      }
    terms_.push_back({c, e});
  }

  T operator()(const VecX<T>& x) const {
    T s(0);
    for (const auto& t : terms_) s += t.coef * power_product(x, t.e);
    return s;
  }

  // d/dx_i, symbolically.
  Polynomial derivative(int i) const {
    Polynomial d(n_);
    for (const auto& t : terms_) {
      const int k = t.e[static_cast<std::size_t>(i)];
      if (k == 0) continue;
      Exponents e = t.e;
      --e[static_cast<std::size_t>(i)];
      d.add(T(k) * t.coef, e);
    }
    return d;
  }

  // Exact gradient at x (each component is the derivative polynomial evaluated term by term).
  VecX<T> gradient(const VecX<T>& x) const {
    VecX<T> g = VecX<T>::Zero(n_);
    for (const auto& t : terms_)
      for (int i = 0; i < n_; ++i) {
        const int k = t.e[static_cast<std::size_t>(i)];
        if (k == 0) continue;
        Exponents e = t.e;
        --e[static_cast<std::size_t>(i)];
        g(i) += T(k) * t.coef * power_product(x, e);
      }
    return g;
  }

  // Exact Hessian at x.
  MatX<T> hessian(const VecX<T>& x) const {
    MatX<T> H(n_, n_);
    for (int i = 0; i < n_; ++i) {
      const Polynomial di = derivative(i);
      for (int j = 0; j < n_; ++j) H(i, j) = di.derivative(j)(x);
    }
    return H;
  }

  Polynomial operator+(const Polynomial& o) const {
    Polynomial r = *this;
    for (const auto& t : o.terms_) r.add(t.coef, t.e);
    return r;
  }
  Polynomial operator-(const Polynomial& o) const { return *this + o.scaled(T(-1)); }
  Polynomial scaled(const T& a) const {
    Polynomial r(n_);
    for (const auto& t : terms_) r.add(a * t.coef, t.e);
    return r;
  }
  Polynomial operator*(const Polynomial& o) const {
    Polynomial r(n_);
    for (const auto& a : terms_)
      for (const auto& b : o.terms_) {
        Exponents e{};
        for (int i = 0; i < kMaxPolynomialVars; ++i)
          e[static_cast<std::size_t>(i)] = a.e[static_cast<std::size_t>(i)] + b.e[static_cast<std::size_t>(i)];
        r.add(a.coef * b.coef, e);
      }
    return r;
  }

  // Majorant on the box |y|_inf <= R: sum |c| R^deg >= |p(y)|, and >= |fl(p(y)) - p(y)| / gamma_n
  // with n = eval_ops().
  T bound(const T& R) const {
    T s(0);
    for (const auto& t : terms_) s += abs_value(t.coef) * int_power(R, total_degree(t.e));
    return s;
  }
  // Majorant of every component of the gradient on that box: max_i bound of d/dx_i.
  T gradient_bound(const T& R) const {
    T best(0);
    for (int i = 0; i < n_; ++i) best = std::max(best, derivative(i).bound(R));
    return best;
  }
  // Length of the longest chain of roundings when evaluating p or a component of its gradient
  // term by term: one per factor of a term (coefficient, exponent factor, powers) plus one per
  // term for the sequential sum.
  int eval_ops() const { return degree() + 2 + static_cast<int>(terms_.size()); }

 private:
  static T int_power(const T& x, int k) {
    T r(1);
    for (int i = 0; i < k; ++i) r *= x;
    return r;
  }
  static T power_product(const VecX<T>& x, const Exponents& e) {
    T r(1);
    for (Eigen::Index i = 0; i < x.size(); ++i)
      for (int k = 0; k < e[static_cast<std::size_t>(i)]; ++k) r *= x(i);
    return r;
  }

  int n_ = 1;
  std::vector<Monomial<T>> terms_;
};

// f(y_1(x), ..., y_m(x)) for f in m variables and polynomials y_k in n variables, symbolically.
template <class T>
Polynomial<T> substitute(const Polynomial<T>& f, const std::vector<Polynomial<T>>& y) {
  if (static_cast<int>(y.size()) != f.vars()) throw std::invalid_argument("substitute: one polynomial per variable");
  const int n = y.front().vars();
  Polynomial<T> out(n);
  for (const auto& t : f.terms()) {
    Polynomial<T> m = Polynomial<T>::constant(n, t.coef);
    for (int k = 0; k < f.vars(); ++k)
      for (int j = 0; j < t.e[static_cast<std::size_t>(k)]; ++j) m = m * y[static_cast<std::size_t>(k)];
    out = out + m;
  }
  return out;
}

template <class T>
std::string show_polynomial(const Polynomial<T>& p) {
  if (p.terms().empty()) return "0";
  std::ostringstream os;
  bool first = true;
  for (const auto& t : p.terms()) {
    if (!first) os << " + ";
    first = false;
    os << "(" << to_string_full(t.coef) << ")";
    for (int i = 0; i < p.vars(); ++i) {
      const int k = t.e[static_cast<std::size_t>(i)];
      if (k == 0) continue;
      os << " x" << (i + 1);
      if (k > 1) os << "^" << k;
    }
  }
  return os.str();
}

template <class T>
void showValue(const Polynomial<T>& p, std::ostream& os) {
  os << show_polynomial(p);
}

namespace gen {

// Sizes of the random test functions. Degree 4 is what the issue asks for; terms, coefficients
// and points are kept small so that the rational arithmetic of a Jacobi check (up to 3 x 3 x 12
// evaluations of a bracket of degree-4 functions) stays well under a second for 25 cases.
inline constexpr int kPolyMaxDegree = 4;
inline constexpr int kPolyMaxTerms = 4;
inline constexpr int kPolyCoefMax = 8;  // coefficients k / 4, |k| <= 8: in [-2, 2]
inline constexpr int kPolyCoefBits = 2;
inline constexpr int kPointMax = 16;  // points k / 8, |k| <= 16: in [-2, 2]^n
inline constexpr int kPointBits = 3;

// A random polynomial in n variables: 1 to max_terms terms c x_{i1} ... x_{id}, d <= max_degree.
// Shrinks toward fewer terms, lower degrees, the first variable and coefficient 0.
template <class T>
rc::Gen<Polynomial<T>> polynomial(int n, int max_degree = kPolyMaxDegree, int max_terms = kPolyMaxTerms) {
  using Spec = std::pair<int, std::vector<int>>;  // (coefficient numerator, variable indices)
  const auto term =
      rc::gen::pair(signed_int(kPolyCoefMax), rc::gen::mapcat(rc::gen::inRange(0, max_degree + 1), [n](int d) {
                      return rc::gen::container<std::vector<int>>(static_cast<std::size_t>(d), rc::gen::inRange(0, n));
                    }));
  return rc::gen::map(rc::gen::mapcat(rc::gen::inRange(1, max_terms + 1),
                                      [term](int k) {
                                        return rc::gen::container<std::vector<Spec>>(static_cast<std::size_t>(k), term);
                                      }),
                      [n](const std::vector<Spec>& specs) {
                        Polynomial<T> p(n);
                        for (const auto& [c, vars] : specs) {
                          Exponents e{};
                          for (int v : vars) ++e[static_cast<std::size_t>(v)];
                          p.add(dyadic<T>(c, kPolyCoefBits), e);
                        }
                        return p;
                      });
}

// A point of [-2, 2]^n on the grid 1/8.
template <class T>
rc::Gen<VecX<T>> point(int n) {
  return vec<T>(n, kPointMax, kPointBits);
}

// Instantiated once, in polynomial.cpp (RapidCheck's generators over Real50 and Rational are
// expensive to compile).
#define GM_POLYNOMIAL_GENERATORS_FOR(PREFIX, T)                        \
  PREFIX template rc::Gen<Polynomial<T>> polynomial<T>(int, int, int); \
  PREFIX template rc::Gen<VecX<T>> point<T>(int);

GM_POLYNOMIAL_GENERATORS_FOR(extern, double)
GM_POLYNOMIAL_GENERATORS_FOR(extern, Real50)
GM_POLYNOMIAL_GENERATORS_FOR(extern, Rational)

}  // namespace gen
}  // namespace gm
