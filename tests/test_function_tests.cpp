// The machinery behind the bracket properties: polynomial test functions with exact derivatives
// (properties/support/polynomial.hpp) and certified derivatives of black boxes by interpolation
// (properties/support/line_derivative.hpp).
#include "properties/support/line_derivative.hpp"
#include "properties/support/polynomial.hpp"

#include "tests/support/rc_failure.hpp"

#include <gtest/gtest.h>

namespace gm {
namespace {

using testing_support::failure_of;

// p = 3/4 x1^2 x2 - 1/2 x2 x3^3 + 2 x3 - 5/4 (n = 3), exactly.
Polynomial<Rational> sample() {
  Polynomial<Rational> p(3);
  p.add(Rational(3) / 4, {2, 1, 0, 0, 0, 0});
  p.add(Rational(-1) / 2, {0, 1, 3, 0, 0, 0});
  p.add(Rational(2), {0, 0, 1, 0, 0, 0});
  p.add(Rational(-5) / 4, {});
  return p;
}

VecX<Rational> point(Rational a, Rational b, Rational c) {
  VecX<Rational> x(3);
  x << a, b, c;
  return x;
}

TEST(Polynomials, ValueGradientAndHessianAreExact) {
  const auto p = sample();
  const auto x = point(Rational(1) / 2, Rational(-3) / 8, Rational(5) / 4);
  const Rational x1 = x(0), x2 = x(1), x3 = x(2);
  EXPECT_EQ(p(x), Rational(3) / 4 * x1 * x1 * x2 - Rational(1) / 2 * x2 * x3 * x3 * x3 + 2 * x3 - Rational(5) / 4);
  const VecX<Rational> g = p.gradient(x);
  EXPECT_EQ(g(0), Rational(3) / 2 * x1 * x2);
  EXPECT_EQ(g(1), Rational(3) / 4 * x1 * x1 - Rational(1) / 2 * x3 * x3 * x3);
  EXPECT_EQ(g(2), Rational(-3) / 2 * x2 * x3 * x3 + 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(g(i), p.derivative(i)(x));
  const MatX<Rational> H = p.hessian(x);
  EXPECT_EQ(H(0, 1), Rational(3) / 2 * x1);
  EXPECT_EQ(H(1, 0), H(0, 1));
  EXPECT_EQ(H(2, 2), Rational(-3) * x2 * x3);
  EXPECT_EQ(p.degree(), 4);
}

TEST(Polynomials, ProductsSumsAndSubstitutionAreSymbolic) {
  const auto p = sample();
  auto q = Polynomial<Rational>::coordinate(3, 1) * Polynomial<Rational>::coordinate(3, 2) +
           Polynomial<Rational>::constant(3, 3);
  const auto x = point(Rational(7) / 8, Rational(1) / 4, Rational(-1));
  EXPECT_EQ((p * q)(x), p(x) * q(x));
  EXPECT_EQ((p - p).terms().size(), 0u);  // cancelling terms are dropped
  EXPECT_EQ((p + q.scaled(Rational(2)))(x), p(x) + 2 * q(x));
  // f(y1(x), y2(x), y3(x)) with y = (x2 x3, x1 + 1, x1 x2 x3): a polynomial in x with f's values.
  std::vector<Polynomial<Rational>> y{Polynomial<Rational>::coordinate(3, 1) * Polynomial<Rational>::coordinate(3, 2),
                                      Polynomial<Rational>::coordinate(3, 0) + Polynomial<Rational>::constant(3, 1),
                                      Polynomial<Rational>::coordinate(3, 0) * Polynomial<Rational>::coordinate(3, 1) *
                                          Polynomial<Rational>::coordinate(3, 2)};
  const auto composed = substitute(p, y);
  EXPECT_EQ(composed(x), p(point(y[0](x), y[1](x), y[2](x))));
}

TEST(Polynomials, BoundMajorisesOnTheBox) {
  const auto p = sample();
  const Rational R(2);
  for (int a = -2; a <= 2; ++a)
    for (int b = -2; b <= 2; ++b)
      for (int c = -2; c <= 2; ++c) {
        const auto x = point(a, b, c);
        EXPECT_LE(abs_value(p(x)), p.bound(R));
        EXPECT_LE(max_abs(p.gradient(x)), p.gradient_bound(R));
      }
}

TEST(LineDerivatives, WeightsAreExactForPolynomialsOfTheDegree) {
  for (int degree : {0, 1, 2, 5, 9}) {
    const auto nodes = central_nodes<Rational>(degree);
    ASSERT_GE(2 * nodes.m, degree);
    // d/ds s^j at 0 is 1 for j = 1 and 0 otherwise, for every j <= 2m; l reproduces s^j at the check node.
    for (int j = 0; j <= 2 * nodes.m; ++j) {
      Rational d(0), v(0);
      for (std::size_t k = 0; k < nodes.s.size(); ++k) {
        Rational sj(1);
        for (int i = 0; i < j; ++i) sj *= nodes.s[k];
        d += nodes.w[k] * sj;
        v += nodes.l[k] * sj;
      }
      Rational check(1);
      for (int i = 0; i < j; ++i) check *= nodes.s_check;
      EXPECT_EQ(d, Rational(j == 1 ? 1 : 0)) << "degree " << degree << ", s^" << j;
      EXPECT_EQ(v, check) << "degree " << degree << ", s^" << j;
    }
  }
}

TEST(LineDerivatives, GradientOfAPolynomialBlackBoxIsExactInRationals) {
  const auto p = sample();
  const auto x = point(Rational(1) / 8, Rational(-5) / 8, Rational(3) / 2);
  const auto nodes = central_nodes<Rational>(p.degree());
  const auto g = line_gradient(
      "p", [&](const VecX<Rational>& y) { return p(y); }, x, nodes, Rational(1), 0);
  EXPECT_EQ(g, p.gradient(x));
}

TEST(LineDerivatives, GradientOfAPolynomialBlackBoxIsCloseInDouble) {
  Polynomial<double> p(3);
  const auto exact = sample();  // named: a range-for over sample().terms() would dangle
  for (const auto& t : exact.terms()) p.add(convert<double>(t.coef), t.e);
  VecX<double> x(3);
  x << 0.125, -0.625, 1.5;
  const auto nodes = central_nodes<double>(p.degree());
  const double R = 1.5 + to_double(nodes.radius());
  const auto g = line_gradient(
      "p", [&](const VecX<double>& y) { return p(y); }, x, nodes, p.bound(R), p.eval_ops());
  EXPECT_LE(max_abs((g - p.gradient(x)).eval()), (p.eval_ops() + nodes.ops()) * eps<double>() * nodes.W * p.bound(R));
}

TEST(LineDerivatives, CertificateRejectsAFunctionOfHigherDegree) {
  const auto x = point(Rational(1) / 2, 0, 0);
  const auto nodes = central_nodes<Rational>(2);
  // 1 / (1 + |y|^2) is not a polynomial: the interpolant cannot predict the next node.
  const auto msg = failure_of([&] {
    line_gradient(
        "1/(1+|y|^2)", [](const VecX<Rational>& y) { return Rational(1) / (1 + y.squaredNorm()); }, x, nodes,
        Rational(1), 0);
  });
  EXPECT_NE(msg.find("is a polynomial of degree <= 2"), std::string::npos) << msg;
  // A polynomial of degree 3 > 2m = 2 is rejected too.
  const auto msg3 = failure_of([&] {
    line_gradient(
        "y1^3", [](const VecX<Rational>& y) { return Rational(y(0) * y(0) * y(0)); }, x, nodes, Rational(1), 0);
  });
  EXPECT_NE(msg3.find("is a polynomial of degree <= 2"), std::string::npos) << msg3;
}

}  // namespace
}  // namespace gm
