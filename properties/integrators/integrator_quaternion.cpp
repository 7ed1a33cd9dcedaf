// The norm of the quaternion an integrator keeps its attitude in (core/state_form.hpp): the claim
// unit_quaternion, which is to a quaternion what orthogonality is to a matrix. A q of another norm
// still names an attitude (that of q / |q|, which is how the suite reads it for every other
// property), so its drift would go unseen there: it is measured here, in the integrator's own form,
// stepping its own state (declared_step), never a conversion of it.
//
// Spec entry: s2.reconstruction (the attitude stays in SO(3); a unit quaternion is a point of SU(2),
// its double cover, so |q| = 1 is the same statement in the declared form).
#include "properties/integrators/support/roundoff_claim.hpp"
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_integrator_quaternion {
namespace {

constexpr int kStates = 3;
constexpr int kSteps = 64;

// | |q|^2 - 1 | over 64 steps of h = 1/8 from three generic states, each in the declared form.
// Round-off: a step's quaternion product (or renormalisation) changes |q|^2 by a few eps; over n
// steps at most linearly: k = 32 per step on the scale 1, as integrator_orthogonality allows O^T O.
template <class T>
void integrator_unit_quaternion(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  T worst(0);
  std::string inputs;
  for (int k = 0; k < kStates; ++k) {
    const Vec3<T> I = dyn::draw_generic_inertia<T>();
    const RigidBodyState<T> x0{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
    EngineState<T> u = to_declared<T>(in.form, I, x0.O, x0.Pi);
    const std::string drawn = named("I", I) + named("q", u.q) + named(angular_key(in.form.angular), u.angular()) +
                              "    (" + describe_state_form(in.form) + "), h = 1/8, 64 steps\n";
    if (k == 0) inputs = drawn;
    Series ser{
        std::string("invariants: ") + in.name, "||q|^2 - 1|" + judged_tag<T>(), "t", "|residual|", false, true, {}, 0};
    for (int n = 1; n <= kSteps; ++n) {
      u = in.declared_step(I, u, T(1) / T(8));
      u.form = in.form;
      const T r = abs_value(T(u.q.squaredNorm() - T(1)));
      if (worse(r, worst)) worst = r, inputs = drawn;
      ser.points.emplace_back(n / 8.0, to_double(r));
    }
    if (k == 0) record_series(ser);
  }
  showing_inputs([&] { return inputs; },
                 [&] {
                   judge_roundoff_claim<T>("unit_quaternion", c.unit_quaternion, in.name,
                                           your_attitude(in.form) + " keeps |q|^2 = 1 to round-off over 64 steps",
                                           worst, T(kSteps), 32);
                 });
}

}  // namespace

GM_PROPERTY(
    integrator_unit_quaternion, integrator_scalars,
    {.spec = "s2.reconstruction",
     .title = "rigid-body integrator keeping a quaternion and claiming unit_quaternion: |q| = 1 kept to round-off",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {},
     .negative_controls = {"quaternion_euler_claims_unit_norm"},
     .cases = {.d = 10, .mp = 2, .q = 0},
     .step = StepKind::RigidBodyQuaternion,
     .judges = {"unit_quaternion"}});

}  // namespace properties_integrator_quaternion
}  // namespace gm
