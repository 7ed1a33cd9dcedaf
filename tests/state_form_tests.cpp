// The state forms engines keep (core/state_form.hpp), the suite's conversions, the adapter that
// keeps a user's own state along a run (core/declared_step.hpp), and the step field read in the
// declared form (properties/integrators/support/step_field_form.hpp): engines speak back in their own form.
#include "core/declared_step.hpp"
#include "impl/integrators.hpp"
#include "properties/integrators/support/step_field.hpp"
#include "properties/support/step_guard.hpp"

#include <gtest/gtest.h>

namespace gm {
namespace {

const char* kForms[] = {"matrix Pi",          "matrix Omega",          "matrix omega",          "matrix pi",
                        "quaternion_wxyz Pi", "quaternion_wxyz Omega", "quaternion_wxyz omega", "quaternion_wxyz pi",
                        "quaternion_xyzw Pi", "quaternion_xyzw Omega", "quaternion_xyzw omega", "quaternion_xyzw pi"};

// A rotation made without the suite's conversions: the Cayley transform of hat(c) (rational in c).
template <class T>
Mat3<T> cayley(const Vec3<T>& c) {
  Mat3<T> C;
  C << T(0), -c(2), c(1), c(2), T(0), -c(0), -c(1), c(0), T(0);
  const Mat3<T> Id = Mat3<T>::Identity();
  return (Id - C).inverse() * (Id + C);
}

// v rotated by a unit quaternion (w, x, y, z) as q (0, v) q^-1, by quaternion products alone: a
// truth for the rotation matrix the suite makes of q, written independently of it.
template <class T>
Vec3<T> rotate_by_products(const Vec4<T>& q, const Vec3<T>& v) {
  const Vec4<T> qv = ref::quaternion_product<T>(q, Vec4<T>(T(0), v(0), v(1), v(2)));
  const Vec4<T> r = ref::quaternion_product<T>(qv, Vec4<T>(q(0), -q(1), -q(2), -q(3)));
  return Vec3<T>(r(1), r(2), r(3));
}

TEST(StateForm, ReadsTheDeclaredWordsAndNamesAWrongOne) {
  const StateForm f = parse_state_form("quaternion_xyzw, omega");
  EXPECT_EQ(f.attitude, Attitude::quaternion_xyzw);
  EXPECT_EQ(f.angular, Angular::omega);
  EXPECT_EQ(state_form_words(f), "quaternion_xyzw omega");
  EXPECT_TRUE(parse_state_form("matrix Pi").is_notes());
  // The case matters: Omega is the body's, omega the world's.
  EXPECT_EQ(parse_state_form("matrix Omega").angular, Angular::Omega);
  try {
    parse_state_form("quaternion omega");
    FAIL() << "an unknown attitude was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'quaternion' is not an attitude"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_state_form("quaternion_wxyz"), std::invalid_argument);
  EXPECT_THROW(parse_state_form("matrix OMEGA"), std::invalid_argument);
}

template <class T>
void conversions_round_trip_and_mean_what_they_say() {
  const T tol = T(64) * eps<T>();
  const Vec3<T> I(T(5) / T(4), T(3) / T(4), T(1) / T(2));
  const Vec3<T> Pi(T(3) / T(8), T(-5) / T(16), T(7) / T(32));
  for (const Vec3<T>& c :
       {Vec3<T>(T(1) / T(3), T(-1) / T(5), T(2) / T(7)), Vec3<T>(T(3), T(-2), T(5)), Vec3<T>(T(0), T(0), T(0))}) {
    const Mat3<T> O = cayley<T>(c);
    for (const char* words : kForms) {
      SCOPED_TRACE(words);
      const StateForm f = parse_state_form(words);
      const EngineState<T> u = to_declared<T>(f, I, O, Pi);
      // What each part is: the notes' formulas, written here.
      switch (f.angular) {
        case Angular::Pi:
          EXPECT_LE(max_abs(Vec3<T>(u.Pi - Pi)), tol);
          break;
        case Angular::Omega:
          EXPECT_LE(max_abs(Vec3<T>(u.Omega.cwiseProduct(I) - Pi)), tol);
          break;
        case Angular::omega:
          EXPECT_LE(max_abs(Vec3<T>(u.omega - O * Pi.cwiseQuotient(I))), tol);
          break;
        case Angular::pi:
          EXPECT_LE(max_abs(Vec3<T>(u.pi - O * Pi)), tol);
          break;
      }
      if (f.has_quaternion()) {
        const Vec4<T> q = state_form::wxyz<T>(u.q, f.attitude);
        EXPECT_LE(abs_value(T(q.squaredNorm() - T(1))), tol);
        if (f.attitude == Attitude::quaternion_xyzw) {
          EXPECT_EQ(u.q(3), q(0));  // w last
        }
        for (int k = 0; k < 3; ++k) {
          const Vec3<T> e = Vec3<T>::Unit(k);
          EXPECT_LE(max_abs(Vec3<T>(rotate_by_products<T>(q, e) - O * e)), tol) << "q rotates e_" << k << " as O does";
        }
        // q and -q are one attitude.
        EngineState<T> minus = u;
        minus.q = -u.q;
        EXPECT_LE(max_abs(Mat3<T>(attitude_of(minus) - attitude_of(u))), T(0));
      }
      // Back to the notes' state.
      const Mat3<T> O2 = attitude_of(u);
      EXPECT_LE(max_abs(Mat3<T>(O2 - O)), tol);
      EXPECT_LE(max_abs(Vec3<T>(body_momentum_of(u, I, O2) - Pi)), tol);
    }
  }
}

TEST(StateForm, ConversionsRoundTripAndMeanWhatTheySayInDouble) {
  conversions_round_trip_and_mean_what_they_say<double>();
}
TEST(StateForm, ConversionsRoundTripAndMeanWhatTheySayIn50Digits) {
  conversions_round_trip_and_mean_what_they_say<Real50>();
}

// The negative control of the test above: a quaternion taken as (x, y, z, w) where it is (w, x, y, z)
// does not rotate as O does.
TEST(StateForm, AQuaternionReadInTheWrongOrderIsAnotherAttitude) {
  const Mat3<double> O = cayley<double>(Vec3<double>(0.25, -0.5, 0.125));
  const Vec4<double> q = state_form::quaternion_of<double>(O);
  const Vec4<double> misread(q(1), q(2), q(3), q(0));
  EXPECT_GT(max_abs(Vec3<double>(rotate_by_products<double>(misread, Vec3<double>::UnitX()) - O.col(0))), 0.1);
}

// Explicit Euler on (q, omega) as a careless engine writes it: the rotation read from q by the
// unit-quaternion formula (1 - 2(y^2 + z^2), ...) and q never renormalised, so |q| grows and the
// rotation it reads stops being one. Its run depends on its own |q|, which only its own state keeps
// (a conversion through O = R(q / |q|) hands it a unit q again).
Mat3<double> unit_formula(const Vec4<double>& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Mat3<double> R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z), 1 - 2 * (x * x + z * z),
      2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

EngineState<double> growing_step(const Vec3<double>& I, const EngineState<double>& x, const double& h) {
  Vec3<double> W = unit_formula(x.q).transpose() * x.omega;
  W += h * Vec3<double>(I.cwiseProduct(W).cross(W)).cwiseQuotient(I);
  EngineState<double> y = x;
  y.q = x.q + h / 2 * ref::quaternion_product<double>(x.q, Vec4<double>(0, W(0), W(1), W(2)));
  y.omega = unit_formula(y.q) * W;
  return y;
}

TEST(DeclaredStep, ARunThroughTheNotesStateIsTheUsersOwnRun) {
  Integrator<double> in;
  in.name = "growing";
  in.form = parse_state_form("quaternion_wxyz omega");
  in.declared_step = growing_step;
  adapt_declared_step(in);
  const Vec3<double> I(2, 1, 2.0 / 3);
  const RigidBodyState<double> x0{Vec3<double>(0.5, -0.25, 0.75), cayley<double>(Vec3<double>(0.1, 0.2, -0.3))};
  const double h = 1.0 / 8;
  RigidBodyState<double> x = x0;
  EngineState<double> u = to_declared<double>(in.form, I, x0.O, x0.Pi);
  for (int n = 0; n < 20; ++n) {
    x = in.rigid_body_step(I, x, h);
    u = growing_step(I, u, h);
  }
  EXPECT_GT(u.q.norm(), 1 + 1e-3) << "the control: this step lets |q| grow";
  const Mat3<double> O = attitude_of(u);
  EXPECT_EQ(x.O, O) << "the adapted run is the user's own, bit for bit";
  EXPECT_EQ(x.Pi, body_momentum_of(u, I, O));
  // The negative control: converting afresh at every step (no memory) renormalises q each time and
  // is another run.
  RigidBodyState<double> y = x0;
  for (int n = 0; n < 20; ++n) {
    EngineState<double> v = growing_step(I, to_declared<double>(in.form, I, y.O, y.Pi), h);
    v.form = in.form;
    const Mat3<double> Ov = attitude_of(v);
    y = RigidBodyState<double>{body_momentum_of(v, I, Ov), Ov};
  }
  EXPECT_GT(max_abs(Mat3<double>(y.O - x.O)) + max_abs(Vec3<double>(y.Pi - x.Pi)), 1e-6);
  // What the properties are handed back is the user's own quaternion, not a unit one.
  const DeclaredStates<double> states(in.form);
  const RigidBodyState<double> z = states.notes(I, u);
  EXPECT_EQ(states.of(I, z).q, u.q);
  EXPECT_LE(
      std::abs(states.of(I, RigidBodyState<double>{z.Pi, z.O * cayley<double>(Vec3<double>(0, 0, 0.5))}).q.norm() - 1),
      1e-15)
      << "a state the user's step did not return is converted";
}

TEST(DeclaredStep, AStepReturningNoFiniteStateGivesANaNStateNotARaise) {
  // A step that computed a NaN (after its energy overflowed, say) returned it: the checks measure
  // it as they do a notes-form step's NaN ("H is not finite"), never "your step raised".
  Integrator<double> in;
  in.name = "broken";
  in.form = parse_state_form("quaternion_xyzw omega");
  in.declared_step = [](const Vec3<double>&, const EngineState<double>& x, const double&) {
    EngineState<double> y = x;
    y.omega(1) = std::numeric_limits<double>::quiet_NaN();
    return y;
  };
  adapt_declared_step(in);
  const RigidBodyState<double> x{Vec3<double>(1, 0, 0), Mat3<double>::Identity()};
  const RigidBodyState<double> y = in.rigid_body_step(Vec3<double>(2, 1, 1), x, 0.1);
  EXPECT_TRUE(y.Pi.array().isNaN().all() && y.O.array().isNaN().all()) << "a NaN omega gives the NaN state";
  // The control: an infinite quaternion does the same, and a zero quaternion is still refused (no
  // attitude at all), in the declared form's words.
  in.declared_step = [](const Vec3<double>&, const EngineState<double>& x, const double&) {
    EngineState<double> y = x;
    y.q(0) = std::numeric_limits<double>::infinity();
    return y;
  };
  adapt_declared_step(in);
  EXPECT_TRUE(in.rigid_body_step(Vec3<double>(2, 1, 1), x, 0.1).Pi.array().isNaN().all());
  in.declared_step = [](const Vec3<double>&, const EngineState<double>& x, const double&) {
    EngineState<double> y = x;
    y.q.setZero();
    return y;
  };
  adapt_declared_step(in);
  try {
    in.rigid_body_step(Vec3<double>(2, 1, 1), x, 0.1);
    FAIL() << "a zero quaternion passed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("returned by the step is zero"), std::string::npos) << e.what();
  }
}

// A declared step called in its own form (integrator_unit_quaternion steps the quaternion itself) is
// guarded like the notes-form step: its raise is a StepRaised, which the runner reports as a raise
// (an unclaimed check NOT CHARACTERISED, as orthogonality is), not as the check failing.
TEST(DeclaredStep, ARaiseInTheDeclaredFormIsToldAsARaise) {
  Integrator<double> in;
  in.name = "engine";
  in.form = parse_state_form("quaternion_wxyz omega");
  in.declared_step = [](const Vec3<double>&, const EngineState<double>&, const double&) -> EngineState<double> {
    throw std::runtime_error("must be real number, not mpf");
  };
  adapt_declared_step(in);
  const Integrator<double> g = guarded(in);
  const EngineState<double> u =
      to_declared<double>(in.form, Vec3<double>(2, 1, 1), Mat3<double>::Identity(), Vec3<double>(2, 0, 0));
  try {
    g.declared_step(Vec3<double>(2, 1, 1), u, 0.125);
    FAIL() << "the raise passed";
  } catch (const StepRaised& e) {
    EXPECT_EQ(e.raise().message, "must be real number, not mpf");
    EXPECT_DOUBLE_EQ(e.raise().rate, 1.0) << "|Omega| of omega = (1, 0, 0)";
    EXPECT_DOUBLE_EQ(e.raise().h, 0.125);
  }
  current_step_raise().reset();
  // The control: without the guard it is a plain exception, which a check reports as its own failure.
  EXPECT_THROW(
      try { in.declared_step(Vec3<double>(2, 1, 1), u, 0.125); } catch (const StepRaised&) {
        FAIL() << "guarded already";
      },
      std::runtime_error);
}

// The step's field read in the declared form (step_field_form.hpp): a right step "follows the notes",
// a world-side quaternion rate and a transposed conversion are named in the user's words.
enum class Slip { None, Transpose, WorldSide };

Integrator<double> semi_implicit_world_omega(Slip slip) {
  Integrator<double> in;
  in.name = "semi_implicit";
  in.form = parse_state_form("quaternion_wxyz omega");
  in.declared_step = [slip](const Vec3<double>& I, const EngineState<double>& x, const double& h) {
    const Mat3<double> R = attitude_of(x);
    Vec3<double> W = slip == Slip::Transpose ? Vec3<double>(R * x.omega) : Vec3<double>(R.transpose() * x.omega);
    W += h * Vec3<double>(I.cwiseProduct(W).cross(W)).cwiseQuotient(I);
    const Vec4<double> pure(0, W(0), W(1), W(2));
    const Vec4<double> rate = slip == Slip::WorldSide ? ref::quaternion_product<double>(pure, x.q)
                                                      : ref::quaternion_product<double>(x.q, pure);
    EngineState<double> y = x;
    y.q = (x.q + h / 2 * rate).normalized();
    y.omega = state_form::rotation_of<double>(y.q) * W;
    return y;
  };
  adapt_declared_step(in);
  return in;
}

std::string reading(Slip slip) {
  const Integrator<double> in = semi_implicit_world_omega(slip);
  const Vec3<double> I(2, 1, 2.0 / 3);
  const RigidBodyState<double> x{Vec3<double>(0.5, -0.25, 0.75), cayley<double>(Vec3<double>(0.1, 0.2, -0.3))};
  const stepfield::Diagnosis notes = stepfield::diagnose(stepfield::rigid_body_field(in, I, x), I, x);
  const stepfield::Diagnosis d = stepfield::in_declared_form(in, I, x, notes);
  return d.text + (d.field_right ? " [field right]" : " [field wrong]");
}

TEST(DeclaredStepField, ARightStepFollowsTheNotesInItsOwnForm) {
  const std::string r = reading(Slip::None);
  EXPECT_NE(r.find("your state is a unit quaternion q = (w, x, y, z) and the spatial angular velocity omega"),
            std::string::npos)
      << r;
  EXPECT_NE(r.find("follow the notes"), std::string::npos) << r;
  EXPECT_NE(r.find("[field right]"), std::string::npos) << r;
}

TEST(DeclaredStepField, AQuaternionTurnedFromTheWorldsSideIsNamed) {
  const std::string r = reading(Slip::WorldSide);
  EXPECT_NE(r.find("your quaternion q = (w, x, y, z) turns with the body's Omega on the left"), std::string::npos) << r;
  EXPECT_NE(r.find("[field wrong]"), std::string::npos) << r;
}

TEST(DeclaredStepField, AConversionNotUndoneIsNamedNotAHugeField) {
  const std::string r = reading(Slip::Transpose);
  EXPECT_NE(r.find("your step is not consistent in it"), std::string::npos) << r;
  EXPECT_NE(r.find("omega: "), std::string::npos) << r;
}

}  // namespace
}  // namespace gm
