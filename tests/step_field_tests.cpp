// The vector field Manakov's step and the Clebsch steps follow (
// properties/integrators/support/step_field_matrix.hpp): a step of the right equation is said right, each
// mistake the diagnosis names is recognised from a step that makes it, and a false order claim of
// a step that follows the wrong equation leads with that equation, in the verdict and in the claim's
// evidence (the negative controls manakov_midpoint_commutator_reversed,
// manakov_clebsch_midpoint_printed_M and clebsch_midpoint_sign_flipped).
#include "impl/canonical_integrators.hpp"
#include "impl/manakov.hpp"
#include "impl/reference_subject.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/runner.hpp"
#include "tests/mutants/mutants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace gm {
namespace {

using stepfield::Diagnosis;

MatX<double> diagonal(std::initializer_list<double> a) {
  MatX<double> A = MatX<double>::Zero(static_cast<Eigen::Index>(a.size()), static_cast<Eigen::Index>(a.size()));
  Eigen::Index i = 0;
  for (double x : a) A(i, i) = x, ++i;
  return A;
}

ManakovState<double> manakov_state() {
  MatX<double> M(4, 4), O = MatX<double>::Identity(4, 4);
  M << 0, 0.5, -0.25, 0.75, -0.5, 0, 0.375, -0.125, 0.25, -0.375, 0, 0.625, -0.75, 0.125, -0.625, 0;
  // A rotation that is not the identity (a state with O = Id hides a field applied from the wrong side).
  O = ref::cayley_half<double>(MatX<double>(0.5 * M));
  return {M, O};
}

// A one-step method (explicit Euler) of the given field: its own field is that field exactly.
Integrator<double> manakov_euler(std::function<MatX<double>(const MatX<double>&, const MatX<double>&)> M_dot,
                                 std::function<MatX<double>(const MatX<double>&, const ManakovState<double>&)> O_dot) {
  Integrator<double> in;
  in.name = "euler";
  in.manakov_step = [M_dot, O_dot](const MatX<double>& A, const ManakovState<double>& x, const double& h) {
    return ManakovState<double>{MatX<double>(x.M + h * M_dot(A, x.M)), MatX<double>(x.O + h * O_dot(A, x))};
  };
  return in;
}

MatX<double> Omega_of(const MatX<double>& A, const MatX<double>& M) { return ref::manakov_Omega<double>(A, M); }

Diagnosis manakov_diagnosis(const Integrator<double>& in) {
  const MatX<double> A = diagonal({0.5, 0.75, 1.25, 2});
  const ManakovState<double> x = manakov_state();
  return stepfield::diagnose_manakov(stepfield::manakov_field(in, A, x), A, x);
}

const auto right_M = [](const MatX<double>& A, const MatX<double>& M) { return stepfield::bracket(M, Omega_of(A, M)); };
const auto right_O = [](const MatX<double>& A, const ManakovState<double>& x) {
  return MatX<double>(x.O * Omega_of(A, x.M));
};

TEST(StepField, AManakovStepOfTheRightEquationIsSaidRight) {
  for (const char* name : {"implicit_midpoint", "isospectral_cayley", "rk4"}) {
    const SubjectSet s = reference_subject();
    for (const auto& in : s.get<double>()->integrators)
      if (in.name == name && in.manakov_step) {
        const Diagnosis g = manakov_diagnosis(in);
        EXPECT_TRUE(g.field_right) << name << ": " << g.text;
        EXPECT_NE(g.text.find("your step's vector field is right"), std::string::npos) << g.text;
      }
  }
  EXPECT_TRUE(manakov_diagnosis(manakov_euler(right_M, right_O)).field_right);
}

TEST(StepField, EachManakovMistakeIsNamed) {
  auto text = [](auto M_dot, auto O_dot) { return manakov_diagnosis(manakov_euler(M_dot, O_dot)).text; };
  EXPECT_NE(
      text([](const MatX<double>& A, const MatX<double>& M) { return stepfield::bracket(Omega_of(A, M), M); }, right_O)
          .find("your step follows dM/dt = [Omega, M]"),
      std::string::npos);
  const std::string commuting =
      text([](const MatX<double>& A,
              const MatX<double>& M) { return stepfield::bracket(M, MatX<double>(A.inverse() * M / 2)); },
           right_O);
  EXPECT_NE(commuting.find("as if A and Omega commuted"), std::string::npos) << commuting;
  const std::string backwards = text(right_M, [](const MatX<double>& A, const ManakovState<double>& x) {
    return MatX<double>(-x.O * Omega_of(A, x.M));
  });
  EXPECT_NE(backwards.find("dO/dt = -O Omega"), std::string::npos) << backwards;
  EXPECT_EQ(backwards.find("dM/dt"), std::string::npos)
      << "the body part is right and must not be blamed: " << backwards;
  const std::string left = text(right_M, [](const MatX<double>& A, const ManakovState<double>& x) {
    return MatX<double>(Omega_of(A, x.M) * x.O);
  });
  EXPECT_NE(left.find("Omega applied on the left"), std::string::npos) << left;
  const std::string still = text(
      [](const MatX<double>&, const MatX<double>& M) { return MatX<double>(MatX<double>::Zero(M.rows(), M.cols())); },
      right_O);
  EXPECT_NE(still.find("leaves M unchanged"), std::string::npos) << still;
}

MatX<double> clebsch_Z() {
  return ref::stack<double>(Vec3Pair<double>{Vec3<double>(0.5, -0.25, 0.75), Vec3<double>(-0.375, 0.625, 0.125)});
}

MatX<double> manakov_clebsch_Z() {
  MatX<double> Q(3, 3), P(3, 3);
  Q << 0.5, -0.25, 0.125, 0.375, 0.25, -0.5, -0.125, 0.625, 0.25;
  P << -0.25, 0.5, 0.375, 0.125, -0.375, 0.25, 0.5, 0.125, -0.625;
  return ref::stack<double>(MatXPair<double>{Q, P});
}

std::string clebsch_text(const std::function<MatX<double>(const MatX<double>&)>& field) {
  const Vec3<double> I(1.75, 1.5, 1.25);
  const MatX<double> Z = clebsch_Z();
  const auto step = [&](const MatX<double>& W, const double& h) { return MatX<double>(W + h * field(W)); };
  return stepfield::diagnose_clebsch<double>(stepfield::canonical_field<double>(step, Z), I, Z).text;
}

std::string manakov_clebsch_text(const std::function<MatX<double>(const MatX<double>&)>& field) {
  const MatX<double> A = diagonal({0.5, 1.25, 2});
  const MatX<double> Z = manakov_clebsch_Z();
  const auto step = [&](const MatX<double>& W, const double& h) { return MatX<double>(W + h * field(W)); };
  return stepfield::diagnose_manakov_clebsch<double>(stepfield::canonical_field<double>(step, Z), A, Z).text;
}

TEST(StepField, EachClebschMistakeIsNamed) {
  const Vec3<double> I(1.75, 1.5, 1.25);
  const auto F = [&](const MatX<double>& Z) { return ref::clebsch_field<double>(I, Z); };
  EXPECT_NE(clebsch_text(F).find("your step's vector field is right"), std::string::npos);
  EXPECT_NE(clebsch_text([&](const MatX<double>& Z) { return MatX<double>(-F(Z)); }).find("Omega x Q"),
            std::string::npos);
  const std::string inertia = clebsch_text([&](const MatX<double>& Z) {
    const auto [Q, P] = ref::unstack3<double>(Z);
    const Vec3<double> W = I.cwiseProduct(ref::cross<double>(P, Q));
    return ref::stack<double>(
        Vec3Pair<double>{Vec3<double>(-ref::cross<double>(W, Q)), Vec3<double>(-ref::cross<double>(W, P))});
  });
  EXPECT_NE(inertia.find("applied instead of its inverse"), std::string::npos) << inertia;

  const MatX<double> A = diagonal({0.5, 1.25, 2});
  const auto G = [&](const MatX<double>& Z) { return ref::manakov_clebsch_field<double>(A, Z); };
  EXPECT_NE(manakov_clebsch_text(G).find("your step's vector field is right"), std::string::npos);
  const std::string printed = manakov_clebsch_text([&](const MatX<double>& Z) {
    const auto [Q, P] = ref::unstack_n<double>(Z);
    const MatX<double> W = Omega_of(A, MatX<double>((P.transpose() * Q - Q.transpose() * P) / 2));  // as printed
    return ref::stack<double>(MatXPair<double>{MatX<double>(Q * W), MatX<double>(P * W)});
  });
  EXPECT_NE(printed.find("erratum (see spec/CATALOGUE.md, entry mm.manakov-clebsch)"), std::string::npos) << printed;
  const std::string left = manakov_clebsch_text([&](const MatX<double>& Z) {
    const auto [Q, P] = ref::unstack_n<double>(Z);
    const MatX<double> W = Omega_of(A, ref::manakov_clebsch_M<double>(Q, P));
    return ref::stack<double>(MatXPair<double>{MatX<double>(W * Q), MatX<double>(W * P)});
  });
  EXPECT_NE(left.find("Omega on the left"), std::string::npos) << left;
}

// End to end: the order property on each negative control fails, and its message and the order
// claim's evidence lead with the equation the step follows.
void expect_explained(const char* property, const char* mutant, const char* integrator, const std::string& says) {
  const Mutant* m = find_mutant(mutant);
  ASSERT_NE(m, nullptr) << mutant;
  const Property* p = find_property(property);
  ASSERT_NE(p, nullptr) << property;
  RunOptions o;
  o.honour_rc_params = false;
  o.shrink = false;
  bool seen = false;
  for (const auto& v : run_property(*p, m->make(reference_subject()), ScalarKind::Double, o)) {
    if (v.integrator != integrator) continue;
    seen = true;
    EXPECT_EQ(v.outcome, Outcome::Fail) << format_verdict(v);
    EXPECT_NE(v.message.find("the step's own equation: " + says), std::string::npos) << format_verdict(v);
    bool in_evidence = false;
    for (const auto& c : v.claims)
      if (c.claim == "order" && c.evidence.find(says) != std::string::npos) in_evidence = true;
    EXPECT_TRUE(in_evidence) << "the order claim's evidence does not say why:\n" << format_verdict(v);
  }
  EXPECT_TRUE(seen) << integrator << " did not run " << property;
}

TEST(StepField, AFalseManakovOrderClaimSaysWhichEquationTheStepFollows) {
  expect_explained("manakov_integrator_order", "manakov_midpoint_commutator_reversed", "implicit_midpoint",
                   "your step follows dM/dt = [Omega, M]");
}

TEST(StepField, AFalseClebschOrderClaimSaysWhichEquationTheStepFollows) {
  expect_explained("clebsch_integrator_order", "clebsch_midpoint_sign_flipped", "clebsch_midpoint",
                   "your step follows dQ/dt = Omega x Q");
  expect_explained("manakov_clebsch_integrator_order", "manakov_clebsch_midpoint_printed_M", "clebsch_midpoint",
                   "your step's momentum is the notes' printed M = (P^T Q - Q^T P)/2");
}

// The rigid body's field (step_field.hpp) is extrapolated from steps small against the motion's own
// time scale: a right step on a motion scaled by 2^18 (it turns 2^18 times faster) is said right, as
// on the same motion unscaled and slowed down by 2^-30. Before, the steps started at 2^-8 whatever
// the speed, and a right step on a fast motion was said to follow a field it does not (the regime
// convergence of examples/students/bug_order_claim.cpp led with that). The control: a step of the
// reversed cross product is named at every one of these scales.
TEST(StepField, AFastMotionIsLookedAtOnItsOwnTimeScale) {
  const Vec3<double> I(1.75, 1.5, 1.25);
  const Vec3<double> Pi(0.375, -0.5, 0.625);
  auto hat = [](const Vec3<double>& w) {
    Mat3<double> W;
    W << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;
    return W;
  };
  Integrator<double> reversed;
  reversed.name = "euler_reversed";
  reversed.rigid_body_step = [hat](const Vec3<double>& I, const RigidBodyState<double>& x, const double& h) {
    const Vec3<double> W = x.Pi.cwiseQuotient(I);
    return RigidBodyState<double>{Vec3<double>(x.Pi + h * W.cross(x.Pi)), Mat3<double>(x.O + h * x.O * hat(W))};
  };
  for (const double lambda : {1.0, 262144.0, std::ldexp(1.0, -30)}) {
    const RigidBodyState<double> x{Vec3<double>(Pi * lambda), Mat3<double>::Identity()};
    for (const auto& in : reference_subject().get<double>()->integrators)
      if (in.rigid_body_step) {
        const Diagnosis g = stepfield::diagnose(stepfield::rigid_body_field(in, I, x), I, x);
        EXPECT_TRUE(g.field_right) << in.name << ", Pi scaled by " << lambda << ": " << g.text;
      }
    const Diagnosis wrong = stepfield::diagnose(stepfield::rigid_body_field(reversed, I, x), I, x);
    EXPECT_FALSE(wrong.field_right) << lambda;
    EXPECT_NE(wrong.text.find("the cross product is reversed"), std::string::npos) << lambda << ": " << wrong.text;
  }
}

// A cap is named only on its experiment at the failing state (docs/CAUSES.md): explicit Euler of
// (3.8) with the field clamped to a constant size 1024 is said to be (3.8) shrunk to that size at a
// state beyond the clamp; the control, the same step at a state below it, is said to follow (3.8).
TEST(StepField, ACapOfConstantSizeIsNamedWhereItActs) {
  Integrator<double> in;
  in.name = "clamped_euler";
  in.rigid_body_step = [](const Vec3<double>& I, const RigidBodyState<double>& x, const double& h) {
    Vec3<double> F = x.Pi.cross(Vec3<double>(x.Pi.cwiseQuotient(I)));
    const double size = F.cwiseAbs().maxCoeff();
    if (size > 1024) F *= 1024 / size;
    const Vec3<double> W = x.Pi.cwiseQuotient(I);
    Mat3<double> W_hat;
    W_hat << 0, -W(2), W(1), W(2), 0, -W(0), -W(1), W(0), 0;
    return RigidBodyState<double>{Vec3<double>(x.Pi + h * F), Mat3<double>(x.O + h * x.O * W_hat)};
  };
  const Vec3<double> I(1.75, 1.5, 1.25);
  const RigidBodyState<double> fast{Vec3<double>(128, 128, 128), Mat3<double>::Identity()};
  const std::string said = stepfield::explain_rigid_body_step(in, I, {fast}, {1.0 / 8192});
  EXPECT_NE(
      said.find("a cap, by experiment: your step's field is (3.8) shrunk to the constant size max |dPi_i/dt| = 1024"),
      std::string::npos)
      << said;
}

}  // namespace
}  // namespace gm
