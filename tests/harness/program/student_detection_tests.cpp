// What GEOMECH_STUDENT detects in a student's struct, in each scalar (student/geomech/student.hpp):
// templates fill a slot in every scalar, plain double functions in double only, a near miss in
// the signature is a note rather than silence, skip lists are honoured, integrators and claims
// are read.
#include <geomech/student.hpp>

#include <gtest/gtest.h>

namespace {

using namespace gm;
using gm::student::PartInfo;
using gm::student::detail::fill_all;

struct Mixed {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m = Mat3<T>::Zero();
    m(0, 1) = -v(2);
    return m;
  }
  static Eigen::Vector3d vee(const Eigen::Matrix3d& m) { return {m(2, 1), m(0, 2), m(1, 0)}; }
  template <class T>
  static T pairing(const MatX<T>& a) {  // one argument too few: a near miss
    return a.sum();
  }
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cross(Pi.cwiseQuotient(I));
  }
  static constexpr const char* skip_exact = "euler_3_8";
};

struct Step {
  static constexpr const char* name = "step";
  static constexpr gm::student::Claims claims{.order = 3, .energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>&, const RigidBodyState<T>& x, const T&) {
    return x;
  }
};

struct NoStep {
  static constexpr const char* name = "no_step";
  static int rigid_body_step(int) { return 0; }
};

TEST(StudentDetection, TemplatesFillEveryScalarPlainFunctionsDoubleOnly) {
  Subject<double> d;
  Subject<Real50> mp;
  Subject<Rational> q;
  PartInfo di, mi, qi;
  fill_all<Mixed, double>(d, di);
  fill_all<Mixed, Real50>(mp, mi);
  fill_all<Mixed, Rational>(q, qi);
  EXPECT_TRUE(d.provides("hat") && mp.provides("hat") && q.provides("hat"));
  EXPECT_TRUE(d.provides("vee"));
  EXPECT_FALSE(mp.provides("vee"));
  EXPECT_FALSE(q.provides("vee"));
  EXPECT_FALSE(d.provides("pairing"));
  ASSERT_TRUE(di.slot_notes.count("pairing"));
  EXPECT_NE(di.slot_notes["pairing"].find("a function named 'pairing' exists, but it cannot be called as"),
            std::string::npos);
  EXPECT_TRUE(d.provides("euler_3_8") && mp.provides("euler_3_8"));
  EXPECT_FALSE(q.provides("euler_3_8"));
  EXPECT_NE(qi.slot_notes["euler_3_8"].find("skip_exact"), std::string::npos);
  EXPECT_FALSE(d.provides("euler_2_1"));
  EXPECT_FALSE(di.slot_notes.count("euler_2_1"));  // simply not written: no note, the runner says "not provided"
  // The slots call the student's functions.
  EXPECT_EQ(d.hat(Vec3<double>(1, 2, 3))(0, 1), -3.0);
}

TEST(StudentDetection, IntegratorsAndTheirClaims) {
  Subject<double> d;
  PartInfo info;
  gm::student::detail::gm_integrator_of<Step, double>(d, info);
  gm::student::detail::gm_integrator_of<NoStep, double>(d, info);
  ASSERT_EQ(d.integrators.size(), 1u);
  EXPECT_EQ(d.integrators[0].name, "step");
  EXPECT_TRUE(static_cast<bool>(d.integrators[0].rigid_body_step));
  EXPECT_FALSE(static_cast<bool>(d.integrators[0].manakov_step));
  // A step that cannot be called leaves the claims unchecked: that is recorded as unchecked (which
  // fails the check), not as a warning.
  EXPECT_TRUE(info.warnings.empty());
  ASSERT_EQ(info.unchecked.size(), 1u);
  EXPECT_NE(info.unchecked[0].find("integrator 'no_step' has none of rigid_body_step("), std::string::npos);
  const IntegratorClaims c = gm::student::detail::claims_of<Step>();
  EXPECT_EQ(c.integrator, "step");
  EXPECT_EQ(c.order, 3);
  EXPECT_TRUE(c.energy);
  EXPECT_FALSE(c.casimir);
  EXPECT_FALSE(gm::student::detail::claims_of<NoStep>().energy);
}

TEST(StudentDetection, ListsOfSlotNames) {
  using gm::student::detail::listed;
  static_assert(listed("hat vee", "vee"));
  static_assert(listed("hat,vee", "hat"));
  static_assert(!listed("hat vee", "ve"));
  static_assert(listed("all", "anything"));
  static_assert(!listed("", "hat"));
  SUCCEED();
}

}  // namespace
