// The exact free-rigid-body solution (oracle/elliptic.hpp) against the Taylor oracle, in every
// regime, in double, 50 and 70 digits; and the Gragg-Bulirsch-Stoer flow of properties/support
// against both.
#include "core/linalg.hpp"
#include "oracle/elliptic.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"
#include "properties/support/flow.hpp"

#include <gtest/gtest.h>

#include <string>

namespace gm {
namespace {

template <class T>
using V3 = std::array<T, 3>;

// Largest difference between the elliptic solution and the Taylor oracle (tolerance `tol` per
// step) at 40 times in (0, t_end].
template <class T>
T worst_difference(const V3<T>& I, const V3<T>& P, const T& t_end, const T& tol,
                   oracle::RigidBodyRegime* regime = nullptr) {
  const oracle::FreeRigidBodySolution<T> sol(I, P);
  if (regime) *regime = sol.regime();
  oracle::FreeRigidBodyField<T> f(I[0], I[1], I[2]);
  oracle::TaylorSolver<T, decltype(f)> taylor(f, 3, tol);
  std::vector<T> times;
  for (int i = 1; i <= 40; ++i) times.push_back(t_end * T(i) / T(40));
  const auto xs = taylor.sample({P[0], P[1], P[2]}, T(0), times);
  T worst(0);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto p = sol(times[i]);
    for (int k = 0; k < 3; ++k) {
      const T d = abs_value(T(p[k] - xs[i][k]));
      if (d > worst) worst = d;
    }
  }
  return worst;
}

struct Case {
  const char* what;
  V3<const char*> I, P;
  oracle::RigidBodyRegime regime;
};

// Regimes on either side of the separatrix, with the axes in every role and both signs.
const std::vector<Case>& cases() {
  using R = oracle::RigidBodyRegime;
  static const std::vector<Case> c = {
      {"the notes' body, minor axis",
       {"2", "1", "0.6666666666666666666666666666666666666666666666666666666667"},
       {"0.4535961214255773", "0", "0.8912073600614354"},
       R::MinorAxis},
      {"major axis, sorted moments", {"1", "2", "3"}, {"0.3", "-0.5", "0.9"}, R::MajorAxis},
      {"major axis, permuted moments, negative Pi_c", {"3", "1", "2"}, {"-0.9", "0.5", "0.3"}, R::MajorAxis},
      {"minor axis, sorted moments", {"1", "2", "3"}, {"0.9", "0.5", "-0.3"}, R::MinorAxis},
      {"minor axis, permuted moments, negative Pi_c", {"2", "3", "1"}, {"-0.3", "0.5", "-0.9"}, R::MinorAxis},
      {"separatrix (exact: I = (3, 4, 6), |Pi_s| = |Pi_l|)", {"3", "4", "6"}, {"1", "0.5", "-1"}, R::Separatrix},
      {"separatrix, permuted and signs", {"6", "3", "4"}, {"-1", "1", "-0.25"}, R::Separatrix},
      {"just above the separatrix (k' ~ 0.04)", {"3", "4", "6"}, {"1", "0.5", "-1.001"}, R::MajorAxis},
      {"just below the separatrix (k' ~ 0.04)", {"3", "4", "6"}, {"1", "0.5", "-0.999"}, R::MinorAxis},
      {"nearly symmetric (k small)", {"1", "1.001", "3"}, {"0.3", "-0.5", "0.9"}, R::MajorAxis},
      {"oblate symmetric top", {"1", "1", "3"}, {"0.3", "-0.5", "0.9"}, R::SymmetricTop},
      {"prolate symmetric top, equal moments 1 and 3", {"2", "3", "2"}, {"0.3", "-0.5", "0.9"}, R::SymmetricTop},
      {"sphere", {"2", "2", "2"}, {"0.3", "-0.5", "0.9"}, R::Sphere},
      {"zero momentum", {"1", "2", "3"}, {"0", "0", "0"}, R::Rest},
      {"steady rotation about the middle axis (unstable)", {"1", "2", "3"}, {"0", "1", "0"}, R::SteadyRotation},
      {"steady rotation about the major axis", {"1", "2", "3"}, {"0", "0", "-1"}, R::SteadyRotation},
  };
  return c;
}

template <class T>
V3<T> parse(const V3<const char*>& s) {
  return {from_decimal<T>(s[0]), from_decimal<T>(s[1]), from_decimal<T>(s[2])};
}

TEST(EllipticSolution, AgreesWithTaylorTo1e45In50DigitsOverT20InEveryRegime) {
  for (const auto& c : cases()) {
    oracle::RigidBodyRegime regime;
    const Real50 d =
        worst_difference<Real50>(parse<Real50>(c.I), parse<Real50>(c.P), Real50(20), Real50("1e-49"), &regime);
    EXPECT_EQ(regime, c.regime) << c.what << ": regime " << oracle::regime_name(regime);
    EXPECT_LT(d, Real50("1e-45")) << c.what << ": " << to_string_full(d);
  }
}

TEST(EllipticSolution, AgreesWithTaylorInDouble) {
  for (const auto& c : cases()) {
    const double d = worst_difference<double>(parse<double>(c.I), parse<double>(c.P), 20.0, 1e-17);
    // A few hundred ulps over t = 20: the phase error of omega t + u0 grows linearly in t, and
    // near the separatrix the period's sensitivity to the invariants multiplies it.
    EXPECT_LT(d, 1e-12) << c.what << ": " << d;
  }
}

TEST(EllipticSolution, AgreesWithTaylorIn70Digits) {
  const Real70 d = worst_difference<Real70>(
      {Real70(1), Real70(2), Real70(3)}, {Real70("0.3"), Real70("-0.5"), Real70("0.9")}, Real70(10), Real70("1e-68"));
  EXPECT_LT(d, Real70("1e-64")) << to_string_full(d);
}

TEST(EllipticSolution, KeepsTheInvariantsIn50Digits) {
  const V3<Real50> I = {Real50(1), Real50(2), Real50(3)}, P = {Real50("0.3"), Real50("-0.5"), Real50("0.9")};
  const oracle::FreeRigidBodySolution<Real50> sol(I, P);
  auto C = [](const V3<Real50>& p) { return p[0] * p[0] + p[1] * p[1] + p[2] * p[2]; };
  auto h = [&](const V3<Real50>& p) { return p[0] * p[0] / I[0] + p[1] * p[1] / I[1] + p[2] * p[2] / I[2]; };
  for (int k = 0; k <= 100; ++k) {
    const auto p = sol(Real50(k) * Real50("7.3"));  // up to t = 730: the argument reduction modulo 4K
    EXPECT_LT(abs(C(p) - C(P)), Real50("1e-48")) << k;
    EXPECT_LT(abs(h(p) - h(P)), Real50("1e-48")) << k;
  }
}

TEST(EllipticSolution, IsPeriodic) {
  const oracle::FreeRigidBodySolution<Real50> sol({Real50(1), Real50(2), Real50(3)},
                                                  {Real50("0.3"), Real50("-0.5"), Real50("0.9")});
  const Real50 T = sol.period();
  ASSERT_GT(T, Real50(0));
  const auto p0 = sol(Real50("0.7")), p1 = sol(Real50("0.7") + T), p2 = sol(Real50("0.7") - 3 * T);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(abs(p1[i] - p0[i]), Real50("1e-47"));
    EXPECT_LT(abs(p2[i] - p0[i]), Real50("1e-47"));
  }
}

TEST(EllipticSolution, RejectsInvalidBodies) {
  using S = oracle::FreeRigidBodySolution<double>;
  EXPECT_THROW(S({0.0, 1.0, 2.0}, {1.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(S({-1.0, 1.0, 2.0}, {1.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(S({std::nan(""), 1.0, 2.0}, {1.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(S({1.0, 1.0, 2.0}, {1.0, std::numeric_limits<double>::infinity(), 0.0}), std::invalid_argument);
  try {
    S({1.0, -2.0, 3.0}, {1.0, 0.0, 0.0});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("I2"), std::string::npos) << e.what();
  }
}

// The GBS flow of support/flow.hpp (used for subjects' vector fields) meets the exact solution to
// ~100 eps over t = 20 in double and 50 digits, forward and backward.
template <class T>
T gbs_against_exact(const V3<T>& I, const V3<T>& P, const T& t_end) {
  const oracle::FreeRigidBodySolution<T> sol(I, P);
  flow::Gbs<T> g([&](const T&, const VecX<T>& x) {
    VecX<T> d(3);
    d << (T(1) / I[2] - T(1) / I[1]) * x(1) * x(2), (T(1) / I[0] - T(1) / I[2]) * x(2) * x(0),
        (T(1) / I[1] - T(1) / I[0]) * x(0) * x(1);
    return d;
  });
  std::vector<T> times;
  for (int i = 1; i <= 20; ++i) times.push_back(t_end * T(i) / T(20));
  VecX<T> x0(3);
  x0 << P[0], P[1], P[2];
  const auto xs = g.sample(x0, T(0), times);
  T worst(0);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto p = sol(times[i]);
    for (int k = 0; k < 3; ++k) worst = std::max(worst, abs_value(T(p[k] - xs[i](k))));
  }
  return worst;
}

TEST(GbsFlow, MeetsTheExactSolution) {
  EXPECT_LT(gbs_against_exact<double>({1.0, 2.0, 3.0}, {0.3, -0.5, 0.9}, 20.0), 200 * eps<double>());
  EXPECT_LT(gbs_against_exact<double>({1.0, 2.0, 3.0}, {0.3, -0.5, 0.9}, -20.0), 200 * eps<double>());
  EXPECT_LT(gbs_against_exact<Real50>({Real50(1), Real50(2), Real50(3)}, {Real50("0.3"), Real50("-0.5"), Real50("0.9")},
                                      Real50(20)),
            200 * eps<Real50>());
}

TEST(GbsFlow, RejectsBadInput) {
  flow::Gbs<double> g([](const double&, const VecX<double>& x) { return x; });
  VecX<double> x0(1);
  x0 << 1.0;
  EXPECT_THROW(g.sample(x0, 0.0, {1.0, 0.5}), std::invalid_argument);
  x0 << std::nan("");
  EXPECT_THROW(g.sample(x0, 0.0, {1.0}), std::invalid_argument);
  // A field that returns NaN cannot be integrated: an error, not a silent NaN state.
  flow::Gbs<double> bad([](const double&, const VecX<double>& x) { return VecX<double>(x * std::nan("")); });
  x0 << 1.0;
  EXPECT_THROW(bad.sample(x0, 0.0, {1.0}), std::runtime_error);
}

}  // namespace
}  // namespace gm
