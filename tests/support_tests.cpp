// The property machinery itself: scalars, comparisons (NaN never passes, exact means zero,
// roundoff scales with eps), generators (exactly representable, rotations exactly orthogonal).
#include "properties/integrators/support/long_time.hpp"
#include "properties/integrators/support/order_claim.hpp"
#include "properties/integrators/support/step_runs.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"

#include "tests/support/rc_failure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace gm {
namespace {

using testing_support::failure_of;

TEST(Scalars, DecimalStringsParseExactly) {
  EXPECT_EQ(parse_decimal_rational("-1.25e-3"), Rational(-1) / 800);
  EXPECT_EQ(parse_decimal_rational("17"), Rational(17));
  EXPECT_EQ(parse_decimal_rational(" +0.5 "), Rational(1) / 2);
  EXPECT_EQ(parse_decimal_rational("0.0078"), Rational(78) / 10000);  // leading zeros are not octal
  for (const char* bad : {"", "nan", "inf", "1.2.3", "1e", "0x10", "--1", "1e99999999"})
    EXPECT_THROW(parse_decimal_rational(bad), std::invalid_argument) << bad;
  EXPECT_THROW(from_decimal<double>("1e400"), std::invalid_argument);
}

TEST(Scalars, FullPrecisionPrintingRoundTrips) {
  const double d = 0.1 + 0.2;
  EXPECT_EQ(from_decimal<double>(to_string_full(d)), d);
  const Real50 x = Real50(1) / 3;
  EXPECT_EQ(from_decimal<Real50>(to_string_full(x)), x);
  EXPECT_EQ(to_string_full(Rational(2) / 6), "1/3");
}

TEST(Scalars, EpsilonIsThatOfTheType) {
  EXPECT_EQ(eps<double>(), std::numeric_limits<double>::epsilon());
  EXPECT_LT(eps<Real50>(), Real50("1e-49"));
  EXPECT_GT(eps<Real50>(), Real50("1e-51"));
  EXPECT_EQ(eps<Rational>(), Rational(0));
}

TEST(Tolerance, NaNNeverPasses) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto msg = failure_of([&] { require_close("x = x", nan, nan, 1.0, 1e300); });
  EXPECT_NE(msg.find("NaN"), std::string::npos) << msg;
  Vec3<double> v(1, nan, 3);
  msg = failure_of([&] { require_close("v = v", v, v, 1.0, 1e300); });
  EXPECT_NE(msg.find("NaN"), std::string::npos) << msg;
  const double inf = std::numeric_limits<double>::infinity();
  msg = failure_of([&] { require_close("inf = inf", inf, inf, 1.0, 1e300); });
  EXPECT_NE(msg.find("non-finite"), std::string::npos) << msg;
  const Real50 mpnan = std::numeric_limits<Real50>::quiet_NaN();
  msg = failure_of([&] { require_close("mp nan", mpnan, mpnan, Real50(1), 1e300); });
  EXPECT_NE(msg.find("NaN"), std::string::npos) << msg;
}

// The worst of several residuals: a NaN met on one state must not be replaced by a later finite
// residual (the pattern `if (!(r <= worst)) worst = r;` did that, letting an integrator that gave
// NaN on one of its three states pass a claim).
TEST(Tolerance, NaNStaysTheWorstResidual) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double worst = 0;
  for (double r : {1e-16, nan, 2e-16})
    if (gm::worse(r, worst)) worst = r;
  EXPECT_TRUE(std::isnan(worst));
  // The old pattern, for the record: it ends finite.
  double old = 0;
  for (double r : {1e-16, nan, 2e-16})
    if (!(r <= old)) old = r;
  EXPECT_EQ(old, 2e-16);
  double inf_first = 0;
  for (double r : {std::numeric_limits<double>::infinity(), 1.0})
    if (gm::worse(r, inf_first)) inf_first = r;
  EXPECT_TRUE(std::isinf(inf_first));
}

TEST(Tolerance, ExactMeansZeroInRationals) {
  const Rational a(1), b = Rational(1) + Rational(1) / Rational(bmp::cpp_int(1) << 200);
  EXPECT_EQ(failure_of([&] { require_close("a = a", a, a, Rational(1), 1e9); }), "");
  auto msg = failure_of([&] { require_close("a = b", a, b, Rational(1), 1e9); });
  EXPECT_NE(msg.find("exact"), std::string::npos) << msg;
}

TEST(Tolerance, RoundoffScalesWithEpsAndScale) {
  const double e = eps<double>();
  EXPECT_EQ(failure_of([&] { require_close("within", 1.0, 1.0 + 2 * e, 1.0, 4); }), "");
  EXPECT_NE(failure_of([&] { require_close("beyond", 1.0, 1.0 + 8 * e, 1.0, 4); }), "");
  EXPECT_EQ(failure_of([&] { require_close("scaled", 1e6, 1e6 + 1e6 * 2 * e, 1e6, 4); }), "");
  // The same k in 50 digits is 1e-34 times tighter: a double-sized error fails there.
  const Real50 one(1);
  EXPECT_NE(failure_of([&] { require_close("mp", one, Real50(one + Real50(e)), one, 4); }), "");
}

TEST(Tolerance, FailureMessageShowsBothSidesAtFullPrecision) {
  auto msg = failure_of([&] { require_close("third", 1.0 / 3.0, 0.3333, 1.0, 4); });
  EXPECT_NE(msg.find("0.33333333333333331"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lhs-rhs"), std::string::npos) << msg;
  EXPECT_NE(msg.find("eps * scale"), std::string::npos) << msg;
}

template <class G>
auto sample(const G& g, int seed) {
  return g(rc::Random(seed), 50).value();
}

TEST(Generators, DyadicValuesAreIdenticalInEveryScalar) {
  for (int seed = 0; seed < 200; ++seed) {
    const auto vq = sample(gen::vec3<Rational>(), seed);
    const auto vd = sample(gen::vec3<double>(), seed);
    const auto vm = sample(gen::vec3<Real50>(), seed);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(Rational(vd(i)), vq(i));
      EXPECT_EQ(Rational(vm(i)), vq(i));
    }
  }
}

TEST(Generators, RotationsAreExactlyOrthogonalInRationals) {
  for (int n = 2; n <= 6; ++n)
    for (int seed = 0; seed < 20; ++seed) {
      const MatX<Rational> R = sample(gen::rotation<Rational>(n), seed);
      EXPECT_EQ(MatX<Rational>(R.transpose() * R), MatX<Rational>::Identity(n, n));
      EXPECT_EQ(R.determinant(), Rational(1));
    }
}

TEST(Generators, InertiaIsPositiveWithStrictTriangleInequalities) {
  for (int seed = 0; seed < 500; ++seed) {
    const auto I = sample(gen::inertia<Rational>(), seed);
    EXPECT_GT(I.minCoeff(), Rational(0));
    EXPECT_LT(I(0), I(1) + I(2));
    EXPECT_LT(I(1), I(2) + I(0));
    EXPECT_LT(I(2), I(0) + I(1));
  }
}

TEST(Generators, IntegersShrinkTowardZero) {
  EXPECT_EQ(gen::zigzag(0), 0);
  EXPECT_EQ(gen::zigzag(1), 1);
  EXPECT_EQ(gen::zigzag(2), -1);
  EXPECT_EQ(gen::zigzag(3), 2);
}

// The long-time energy classifier (support/long_time.hpp) on synthetic errors whose nature is
// known by construction: a linear drift under an oscillation (down and up), a pure oscillation, a
// slow one (10 periods in the run), round-off, a blow-up, and the issue-47 case: a monotone loss
// that saturates early (backward Euler loses half of its energy and then changes little), which the
// maximum over windows called bounded.
TEST(LongTime, TellsOscillationLossGrowthAndRoundoffApart) {
  std::vector<double> t, loss, growth, wave, slow, tiny, blowup, saturating;
  for (int k = 0; k <= 20000; ++k) {
    const double s = k / 8.0;
    t.push_back(s);
    loss.push_back(1e-6 * std::sin(s) - 4e-9 * s);  // drift -1e-5 over the run: c T = 10 a (a trend once c T > 4 a)
    growth.push_back(1e-6 * std::sin(s) + 4e-9 * s);
    wave.push_back(1e-4 * (1 - std::cos(s)));
    slow.push_back(1e-4 * std::sin(s / 40));  // period ~250: 10 periods in the run
    tiny.push_back(1e-14 * std::sin(s));
    blowup.push_back(k < 15000 ? 1e-3 * std::exp(s / 100) : std::numeric_limits<double>::infinity());
    saturating.push_back(-0.51 * (1 - std::exp(-s / 10)));  // 51% lost, nearly all in the first 1% of the run
  }
  using longtime::EnergyKind;
  const double eps = std::numeric_limits<double>::epsilon(), budget = 32.0 * 20000 * eps, step = 16 * eps;
  EXPECT_EQ(longtime::classify_energy_error(t, loss, budget, step).kind, EnergyKind::Losing);
  EXPECT_EQ(longtime::classify_energy_error(t, growth, budget, step).kind, EnergyKind::Gaining);
  EXPECT_EQ(longtime::classify_energy_error(t, wave, budget, step).kind, EnergyKind::Oscillating);
  EXPECT_EQ(longtime::classify_energy_error(t, slow, budget, step).kind, EnergyKind::Oscillating);
  EXPECT_EQ(longtime::classify_energy_error(t, tiny, budget, step).kind, EnergyKind::Conserved);
  EXPECT_EQ(longtime::classify_energy_error(t, blowup, budget, step).kind, EnergyKind::Gaining);
  const auto s = longtime::classify_energy_error(t, saturating, budget, step);
  EXPECT_EQ(s.kind, EnergyKind::Losing);
  EXPECT_FALSE(s.holds());
  EXPECT_NE(s.words().find("loses energy at every step that changes it"), std::string::npos) << s.words();
  EXPECT_NE(s.words().find("51% lost after 20000 steps"), std::string::npos) << s.words();
  // Not finite: after a growth it is the growth's end; from a state whose energy had not grown, a NaN
  // the step returned, said as such (never "gains energy"), and the run's statistics not shown.
  const auto b = longtime::classify_energy_error(t, blowup, budget, step);
  EXPECT_NE(b.words().find("gains energy without bound: H is not finite within 15000 steps"), std::string::npos)
      << b.words();
  EXPECT_EQ(b.evidence(), b.words());
  std::vector<double> nan_early(wave.begin(), wave.begin() + 100);
  nan_early.push_back(std::numeric_limits<double>::quiet_NaN());
  const auto n = longtime::classify_energy_error(t, nan_early, budget, step);
  EXPECT_FALSE(n.holds());
  EXPECT_NE(n.words().find("the step returns a state that is not finite at step 100"), std::string::npos) << n.words();
  EXPECT_EQ(n.words().find("gains"), std::string::npos) << n.words();
  // Control: a trend at the size of the oscillation is not one (c T < 4 a).
  std::vector<double> hidden;
  for (double s2 : t) hidden.push_back(1e-6 * std::sin(s2) - 1e-10 * s2);
  EXPECT_EQ(longtime::classify_energy_error(t, hidden, budget, step).kind, EnergyKind::Oscillating);
}

// Errors at round-off at every step size are an exact step: any claimed order holds,
// with a note saying so. Controls: one error above its floor with two below is "not measurable"
// (an incomplete finding: the claim is not verified by it), and a clean slope of 1 against a claim of 2 is false.
TEST(OrderClaim, AnExactStepHoldsAnyClaimedOrder) {
  const std::vector<double> hs{0.25, 0.125, 0.0625, 0.03125}, floors(4, 1e-13);
  auto judge = [&](const std::vector<double>& errs, int claimed) {
    recorded_claims().clear();
    recorded_notes().clear();
    judge_order_claim("step", claimed, "", " (double)", hs, errs, floors);
  };
  judge({3e-15, 1e-14, 2e-15, 5e-14}, 2);
  ASSERT_EQ(recorded_claims().size(), 1u);
  EXPECT_TRUE(recorded_claims()[0].holds);
  EXPECT_NE(recorded_claims()[0].evidence.find("exact for this problem (error at round-off for every step size"),
            std::string::npos)
      << recorded_claims()[0].evidence;

  // Not measurable is an incomplete finding: it refutes nothing and verifies nothing (the
  // claims block then says NOT VERIFIED, with this reason).
  judge({1e-3, 5e-14, 2e-15, 5e-14}, 2);
  ASSERT_EQ(recorded_claims().size(), 1u);
  EXPECT_TRUE(recorded_claims()[0].holds);
  EXPECT_FALSE(recorded_claims()[0].complete);
  EXPECT_NE(recorded_claims()[0].measured.find("not measurable"), std::string::npos) << recorded_claims()[0].measured;
  ASSERT_EQ(recorded_notes().size(), 1u);
  EXPECT_NE(recorded_notes()[0].find("order not measurable"), std::string::npos) << recorded_notes()[0];

  const std::string why = failure_of([&] { judge({0.25, 0.125, 0.0625, 0.03125}, 2); });  // order 1 claimed as 2
  EXPECT_NE(why.find("false claim 'order': step: measured order 1.000, claimed 2"), std::string::npos) << why;
  ASSERT_EQ(recorded_claims().size(), 1u);
  EXPECT_FALSE(recorded_claims()[0].holds);
  recorded_claims().clear();
  recorded_notes().clear();
}

// A long run fetched in chunks gives the states of the steps one by one; a chunk whose run raises
// is stepped again one step at a time, so the step that raises does so at its own place; without
// a run every state is one call of the step; no chunk goes beyond the steps asked for.
TEST(StepRuns, ChunksGiveTheStepsOneByOneAndAFailingRunFallsBackToSteps) {
  using State = RigidBodyState<double>;
  int calls = 0, longest = 0;
  const Vec3<double> I(1, 2, 3);
  auto step = [&](const Vec3<double>&, const State& x, const double& h) {
    ++calls;
    if (x.Pi(0) >= 100) throw std::runtime_error("step 100 raises");
    return State{x.Pi + Vec3<double>(h, 0, 0), x.O};
  };
  auto run = [&](const Vec3<double>& p, const State& x, const double& h, int n) {
    longest = std::max(longest, n);
    std::vector<State> out;
    State y = x;
    for (int k = 0; k < n; ++k) out.push_back(y = step(p, y, h));
    return out;
  };
  const State x0{Vec3<double>::Zero(), Mat3<double>::Identity()};
  runs::StepStream<State, Vec3<double>, double> chunked(step, run, I, x0, 1.0, 1000, 64);
  for (int k = 1; k <= 100; ++k) EXPECT_EQ(chunked.next().Pi(0), k);
  try {
    chunked.next();
    FAIL() << "step 101 must raise";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "step 100 raises");
  }
  EXPECT_EQ(longest, 64);
  runs::StepStream<State, Vec3<double>, double> plain(step, {}, I, x0, 1.0, 10);
  calls = 0;
  for (int k = 1; k <= 10; ++k) EXPECT_EQ(plain.next().Pi(0), k);
  EXPECT_EQ(calls, 10);
  runs::StepStream<State, Vec3<double>, double> short_run(step, run, I, x0, 1.0, 5, 64);
  longest = 0;
  for (int k = 1; k <= 5; ++k) EXPECT_EQ(short_run.next().Pi(0), k);
  EXPECT_EQ(longest, 5);
}

}  // namespace
}  // namespace gm
