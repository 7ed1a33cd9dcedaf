// The Taylor oracle against closed-form solutions and its own invariants, in double and 50 digits.
#include "core/scalar.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"
#include "properties/support/dynamics.hpp"

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

// Mixed precision (oracle/taylor.hpp): the orders computed in double-double and double must not
// change the trajectory beyond what the tolerance allows. Each step may add at most tol |x| / 16,
// so a run of n steps may differ from the all-T run by n tol max(1, |x|) at most (these flows do
// not amplify errors by more than the 16 left over). The run must also have used the cheaper
// tiers, or the comparison would check nothing.
template <class T, class Field>
struct MixedRun {
  T difference;  // max over samples and components
  T allowed;
  long steps, mixed_steps, recomputed;
};

template <class T, class Field>
MixedRun<T, Field> compare_mixed_with_all_T(const Field& f, const std::vector<T>& x0, const std::vector<T>& times,
                                            const T& tol, int guard_bits = oracle::TaylorSolver<T, Field>::kGuardBits,
                                            int slack_bits = oracle::TaylorSolver<T, Field>::kPredictionSlackBits) {
  oracle::TaylorSolver<T, Field> mixed(f, f.dim, tol), plain(f, f.dim, tol);
  mixed.set_mixed_precision(true, guard_bits, slack_bits);
  plain.set_mixed_precision(false);
  const auto a = mixed.sample(x0, T(0), times), b = plain.sample(x0, T(0), times);
  T diff(0), size(1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k < a[i].size(); ++k) {
      diff = std::max(diff, T(abs(T(a[i][k] - b[i][k]))));
      size = std::max(size, T(abs(b[i][k])));
    }
  EXPECT_EQ(plain.stats().mixed_steps, 0);
  return {diff, T(plain.stats().steps) * tol * size, mixed.stats().steps, mixed.stats().mixed_steps,
          mixed.stats().recomputed};
}

TEST(OracleMixedPrecision, AgreesWithEveryOrderInTheWorkingPrecision) {
  {
    oracle::FreeRigidBodyField<Real50> f(Real50(2), Real50(1), Real50(2) / 3);
    const auto r = compare_mixed_with_all_T(f, {cos(Real50("1.1")), Real50(0), sin(Real50("1.1"))},
                                            dyn::times_to(Real50(20), 40), Real50("1e-48"));
    EXPECT_LE(r.difference, r.allowed) << "free rigid body, 50 digits: " << to_string_full(r.difference);
    EXPECT_GE(r.mixed_steps, r.steps - 1) << "the tiers were not used";
  }
  {
    oracle::RigidBodyAttitudeField<Real50> f(Real50(3), Real50(2), Real50(1));
    const std::vector<Real50> x0 = {Real50("0.3"), Real50("-1.2"), Real50("0.7"), 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const auto r = compare_mixed_with_all_T(f, x0, dyn::times_to(Real50(10), 40), eps<Real50>());
    EXPECT_LE(r.difference, r.allowed) << "attitude, tol = eps: " << to_string_full(r.difference);
    EXPECT_GE(r.mixed_steps, r.steps - 1) << "the tiers were not used";
  }
  {
    oracle::ClebschField<Real70> f(Real70(2), Real70(1), Real70(2) / 3);
    const std::vector<Real70> x0 = {Real70("0.5"),  Real70("-1.5"), Real70("0.25"),
                                    Real70("1.25"), Real70("0.75"), Real70("-2")};
    const auto r = compare_mixed_with_all_T(f, x0, dyn::times_to(Real70(5), 5), Real70("1e-62"));
    EXPECT_LE(r.difference, r.allowed) << "Clebsch, 70 digits: " << to_string_full(r.difference);
    EXPECT_GE(r.mixed_steps, r.steps - 1) << "the tiers were not used";
  }
}

// The split is predicted from the previous step and checked once the step size is known. The
// profile |x_k| h^k keeps its shape from step to step on these flows (the step follows the radius
// of convergence), so predictions rarely fail; with the prediction's margin set to -30 bits they
// fail on every step, and the recomputed steps must be as accurate.
TEST(OracleMixedPrecision, RecomputesAStepWhosePredictedSplitFails) {
  oracle::FreeRigidBodyField<Real50> f(Real50(2), Real50(1), Real50(2) / 3);
  const auto r = compare_mixed_with_all_T(f, {cos(Real50("1.1")), Real50(0), sin(Real50("1.1"))}, {Real50(10)},
                                          Real50("1e-48"), oracle::TaylorSolver<Real50, decltype(f)>::kGuardBits, -30);
  EXPECT_GE(r.recomputed, r.steps - 1) << "the predictions held: the recomputation went untested";
  EXPECT_GE(r.mixed_steps, r.steps - 1);
  EXPECT_LE(r.difference, r.allowed) << to_string_full(r.difference);
}

// dx/dt = x^2 from x0 = 1e20: the coefficients are x0^(k+1), beyond double's range from k = 15 on,
// while the terms x_k h^k stay small enough for the cheaper tiers. Computed there, they would
// overflow to inf and NaN. The split must leave every order in T from the start (the tiers are
// ranges up to N, and order N is the largest): not try the tiers and fall back (the check after
// the step would catch the inf, at the cost of computing every step twice), and the solution at
// t = 1/(2 x0), exactly 2 x0, must come out right.
TEST(OracleMixedPrecision, KeepsCoefficientsBeyondDoubleRangeInT) {
  const Real50 x0("1e20"), tol("1e-48");
  const Real50 t1 = Real50(1) / (2 * x0);
  oracle::TaylorSolver<Real50, Riccati> s(Riccati{}, 1, tol);
  const Real50 x = s.flow({x0}, Real50(0), t1).front();
  EXPECT_LE(abs(x / (2 * x0) - 1), Real50(s.stats().steps + 1) * tol * 4) << to_string_full(x);
  EXPECT_EQ(s.stats().mixed_steps, 0);
  EXPECT_EQ(s.stats().recomputed, 0) << "the split tried double for coefficients beyond its range";
  // Control: the same flow scaled down to x0 = 1 (coefficients of size 1) does use the tiers.
  oracle::TaylorSolver<Real50, Riccati> small(Riccati{}, 1, tol);
  small.flow({Real50(1)}, Real50(0), Real50("0.5"));
  EXPECT_GT(small.stats().mixed_steps, 0);
}

// Control: a split that claims 40 more bits than the tiers have puts the double tier on orders
// whose terms are far above the tolerance, and the comparison above sees it.
TEST(OracleMixedPrecision, ControlTooLittleGuardIsCaught) {
  oracle::FreeRigidBodyField<Real50> f(Real50(2), Real50(1), Real50(2) / 3);
  const auto r = compare_mixed_with_all_T(f, {cos(Real50("1.1")), Real50(0), sin(Real50("1.1"))},
                                          dyn::times_to(Real50(20), 40), Real50("1e-48"), -40);
  EXPECT_GT(r.difference, 1000 * r.allowed) << to_string_full(r.difference);
}

// In double there is no cheaper tier: nothing changes.
TEST(OracleMixedPrecision, DoubleHasNoTiers) {
  oracle::FreeRigidBodyField<double> f(2.0, 1.0, 2.0 / 3.0);
  oracle::TaylorSolver<double, decltype(f)> s(f, 3, 1e-16);
  s.flow({std::cos(1.1), 0.0, std::sin(1.1)}, 0.0, 10.0);
  EXPECT_EQ(s.stats().mixed_steps, 0);
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
