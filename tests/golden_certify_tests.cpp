// Certified golden trajectories (golden/certify.hpp): the enclosures prove the
// committed fixtures' digits, and the certificate is known to be able to fail.
#include "golden/certify.hpp"
#include "golden/fixture.hpp"
#include "golden/systems.hpp"
#include "oracle/fields.hpp"

#include <gtest/gtest.h>

#include <string>

namespace gm::golden {
namespace {

Fixture committed(const std::string& name) {
  return load_fixture(std::string(GM_SOURCE_DIR) + "/golden/fixtures/" + name + ".golden");
}

std::vector<Rational> times_of(const Fixture& f) {
  std::vector<Rational> t;
  for (const auto& s : f.times) t.push_back(parse_decimal(s));
  return t;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// One fixture per system: its certificate, recomputed here, confirms every printed value.
class CertifiedFixture : public ::testing::TestWithParam<const char*> {};

TEST_P(CertifiedFixture, EveryPrintedValueLiesWithinItsCertifiedRadius) {
  const Fixture f = committed(GetParam());
  ASSERT_TRUE(f.certified) << f.source << " carries no certificate";
  const Problem pr = validate_fixture(f);
  const Enclosure e = enclose_problem(pr, times_of(f));
  const auto problems = verify_certificate(f, e);
  EXPECT_TRUE(problems.empty()) << joined(problems);
  // At least 45 certified digits at every sample (the floor).
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    double scale = 1;
    for (const auto& v : f.rows[i]) scale = std::max(scale, std::abs(static_cast<double>(parse_decimal(v))));
    EXPECT_LE(static_cast<double>(parse_decimal(f.certified_radius[i])), 1e-45 * scale)
        << f.source << " t = " << f.times[i] << ": fewer than 45 certified digits";
  }
}

INSTANTIATE_TEST_SUITE_P(OnePerSystem, CertifiedFixture,
                         ::testing::Values("free_rigid_body_stable", "rigid_body_attitude", "nambu_3_16"));
// (Every fixture, Clebsch and Manakov included, is certified again by `geomech golden regenerate
// --check`, one ctest test per fixture: golden_tests.cpp. These three are the cheap ones, well
// under a second each.)

// Negative control: one value changed in its 46th significant digit is rejected, by name.
TEST(CertifiedGolden, AValueChangedInItsFortySixthDigitIsRejected) {
  Fixture f = committed("free_rigid_body_stable");
  const std::size_t row = f.rows.size() - 1;
  std::string& v = f.rows[row][1];  // d.ddd...: digit 46 is character 46 (after "d.", 44 more)
  const std::size_t at = (v[0] == '-' ? 1 : 0) + 46;
  v[at] = v[at] == '9' ? '0' : static_cast<char>(v[at] + 1);
  const Enclosure e = enclose_problem(validate_fixture(committed("free_rigid_body_stable")), times_of(f));
  const auto problems = verify_certificate(f, e);
  ASSERT_EQ(problems.size(), 1u) << joined(problems);
  EXPECT_NE(problems[0].find(f.columns[1] + " at t = " + f.times[row]), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("is not within its certified radius"), std::string::npos) << problems[0];
}

// Negative control: the enclosure of a wrong field (a sign in (3.8)) does not certify the fixture.
TEST(CertifiedGolden, AWrongFieldDoesNotCertifyTheFixture) {
  const Fixture f = committed("free_rigid_body_stable");
  const Problem pr = validate_fixture(f);
  const Ball::Precision precision(320);
  oracle::FreeRigidBodyField<Ball> wrong(Ball(pr.p[0]), Ball(pr.p[1]), Ball(pr.p[2]));
  wrong.c1 = -wrong.c1;  // dPi1/dt with the wrong sign
  const Enclosure e = enclose_field(wrong, pr.dim(), pr.x0, times_of(f), EnclosureOptions{});
  const auto problems = verify_certificate(f, e);
  EXPECT_FALSE(problems.empty());
  if (!problems.empty())
    EXPECT_NE(problems[0].find("is not within its certified radius"), std::string::npos) << problems[0];
}

// The enclosure is a proof, so it must contain what the 70-digit oracle computed: checked through
// the fixtures above; here, its radius at t = 0 is that of the exact initial data (tiny) and it
// grows, but stays far below the printed digits.
TEST(CertifiedGolden, TheEnclosureIsTightAtTheStartAndStaysTight) {
  const Fixture f = committed("rigid_body_attitude");
  const Enclosure e = enclose_problem(validate_fixture(f), times_of(f));
  ASSERT_TRUE(e.failure.empty()) << e.failure;
  for (const auto& b : e.values.front()) EXPECT_LT(b.radius_bound(), 1e-90);
  EXPECT_LT(e.largest_radius, 1e-52);
}

}  // namespace
}  // namespace gm::golden
