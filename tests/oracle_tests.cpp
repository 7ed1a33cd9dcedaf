// The Taylor oracle against closed-form solutions and its own invariants, in double and 50 digits.
#include "core/scalar.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gm {
namespace {

// dx/dt = x^2 has x(t) = x0 / (1 - x0 t): a pole at 1/x0 makes step control matter.
struct Riccati {
  int dim = 1;
  template <class S>
  void operator()(const S* x, S* dx) const {
    dx[0] = x[0] * x[0];
  }
};

// dx/dt = c x (a Scale node): x(t) = x0 exp(c t).
template <class T>
struct Linear {
  int dim = 1;
  T c;
  template <class S>
  void operator()(const S* x, S* dx) const {
    dx[0] = x[0] * c;
  }
};

TEST(Oracle, RiccatiNearItsPoleIn50Digits) {
  const Real50 x0(1), t1("0.9");
  oracle::TaylorSolver<Real50, Riccati> s(Riccati{}, 1, Real50("1e-48"));
  const Real50 x = s.flow({x0}, Real50(0), t1).front();
  const Real50 exact = x0 / (Real50(1) - x0 * t1);  // = 10
  EXPECT_LT(abs(x - exact) / exact, Real50("1e-46")) << to_string_full(x);
}

// The step tolerance is relative to max(1, |x|): for a growing solution the relative error stays
// near (number of steps) * tol.
TEST(Oracle, ExponentialForwardAndBackward) {
  Linear<Real50> f{1, Real50("0.75")};
  oracle::TaylorSolver<Real50, Linear<Real50>> s(f, 1, Real50("1e-49"));
  const Real50 x = s.flow({Real50(1)}, Real50(0), Real50(20)).front();
  EXPECT_LT(abs(x / exp(Real50("15")) - 1), Real50("1e-46")) << to_string_full(x);
  const Real50 back = s.flow({x}, Real50(20), Real50(0)).front();
  EXPECT_LT(abs(back - 1), Real50("1e-46")) << to_string_full(back);
}

TEST(Oracle, SamplesInsideStepsMatchFlowsToThem) {
  oracle::FreeRigidBodyField<double> f(2.0, 1.0, 2.0 / 3.0);
  oracle::TaylorSolver<double, decltype(f)> s(f, 3, 1e-16);
  const std::vector<double> x0 = {std::cos(1.1), 0.0, std::sin(1.1)};
  const auto samples = s.sample(x0, 0.0, {0.0, 0.3, 2.5, 7.25, 10.0});
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(samples[0], x0);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double t = std::vector<double>{0.0, 0.3, 2.5, 7.25, 10.0}[i];
    const auto direct = s.flow(x0, 0.0, t);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(samples[i][k], direct[k], 64 * 2.2e-16) << "t = " << t;
  }
}

// Euler's flow in 50 digits over t = 20: |Pi|^2 and h are conserved to ~1e-48, and 50 and 70
// digits agree: the oracle is accurate to the 1e-45 level the dynamic properties rely on.
TEST(Oracle, FreeRigidBodyIn50DigitsKeepsInvariantsAndAgreesWith70Digits) {
  const Real50 I1(2), I2(1), I3 = Real50(2) / 3;
  oracle::FreeRigidBodyField<Real50> f(I1, I2, I3);
  oracle::TaylorSolver<Real50, decltype(f)> s(f, 3, Real50("1e-48"));
  const std::vector<Real50> x0 = {cos(Real50("1.1")), Real50(0), sin(Real50("1.1"))};
  const auto x = s.flow(x0, Real50(0), Real50(20));
  auto casimir = [](const std::vector<Real50>& p) { return p[0] * p[0] + p[1] * p[1] + p[2] * p[2]; };
  auto energy = [&](const std::vector<Real50>& p) { return p[0] * p[0] / I1 + p[1] * p[1] / I2 + p[2] * p[2] / I3; };
  EXPECT_LT(abs(casimir(x) - casimir(x0)), Real50("1e-47"));
  EXPECT_LT(abs(energy(x) - energy(x0)), Real50("1e-47"));

  const Real70 J1(2), J2(1), J3 = Real70(2) / 3;
  oracle::FreeRigidBodyField<Real70> g(J1, J2, J3);
  oracle::TaylorSolver<Real70, decltype(g)> s70(g, 3, Real70("1e-66"));
  const auto y = s70.flow({cos(Real70("1.1")), Real70(0), sin(Real70("1.1"))}, Real70(0), Real70(20));
  for (int i = 0; i < 3; ++i) EXPECT_LT(abs(Real70(x[i]) - y[i]), Real70("1e-46")) << i;
}

TEST(Oracle, AttitudeStaysOrthogonal) {
  oracle::RigidBodyAttitudeField<Real50> f(Real50(3), Real50(2), Real50(1));
  oracle::TaylorSolver<Real50, decltype(f)> s(f, 12, Real50("1e-48"));
  std::vector<Real50> x0 = {Real50("0.3"), Real50("-1.2"), Real50("0.7"), 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const auto x = s.flow(x0, Real50(0), Real50(20));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Real50 d = 0;
      for (int k = 0; k < 3; ++k) d += x[3 + 3 * k + i] * x[3 + 3 * k + j];
      EXPECT_LT(abs(d - (i == j ? 1 : 0)), Real50("1e-46")) << i << j;
    }
}

TEST(Oracle, RejectsBadInput) {
  oracle::FreeRigidBodyField<double> f(2.0, 1.0, 0.5);
  oracle::TaylorSolver<double, decltype(f)> s(f, 3, 1e-15);
  EXPECT_THROW(s.flow({1.0, 2.0}, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(s.flow({1.0, std::nan(""), 0.0}, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(s.sample({1.0, 0.0, 0.0}, 0.0, {1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW((oracle::TaylorSolver<double, decltype(f)>(f, 3, -1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace gm
