// Integrator claims, verified for any subject's integrators (harness/ runs these on
// students' code): order, symmetry (time reversibility), the invariants claimed to be kept to
// round-off (Casimir, energy, orthogonality of O, spectrum of M), and the Poisson property.
//
// A claim that is false FAILS. A property that holds although not claimed PASSES with a note
// saying so. A property neither claimed nor holding passes silently (it was not promised).
//
// Round-off or truncation? Each check runs in double and in 50 digits. A truly preserved
// quantity stays within k eps(T) * scale * (number of steps), i.e. drops to ~1e-48 in the 50-digit
// run, where any truncation error of a practical step (h = 1/8 here, errors >= 1e-12 even for
// high orders) stands out by thirty orders of magnitude; the 50-digit verdict is the decisive one.
// In double a truncation error below ~1e-13 could pass for round-off; the steps are chosen large
// enough that the methods of this course do not come near it.
//
// Spec entries: the rigid-body properties check the integrator against the properties of the
// exact flow stated in s3.euler-flow (and s2.reconstruction for O in SO(3)); the Manakov ones
// against s2.manakov-flow and s2.isospectral.
#include "properties/registry.hpp"
#include "properties/support/claims.hpp"
#include "properties/integrators/support/convergence.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/integrators/support/order_claim.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/spectrum.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <cstdio>

namespace gm {
namespace properties_integrator_claims {
namespace {

// The verdict on one claimable property: `residual` (the worst over the states tried) against
// k eps scale. The finding goes to the report's claims table (properties/support/claims.hpp):
// claimed and holding, a verified claim; claimed and not holding, a FAIL (a false claim, with the
// residual as evidence); not claimed but holding, "holds (not claimed)" (also a note on the
// verdict). Each case tries kStates generic states (distinct moments, no zero component): a
// degenerate body (a sphere, a symmetric top) keeps more than a generic one, and a finding must
// not come from such a coincidence.
template <class T>
void judge_measured_claim(const char* claim, bool claimed, const std::string& integrator, const std::string& what,
                          const T& residual, const T& scale, double k) {
  const bool holds = is_finite(residual) && residual <= T(k) * eps<T>() * scale;
  const std::string units =
      is_finite(residual) ? fmt("%.3g eps * scale", to_double(T(residual / (eps<T>() * scale)))) : "not finite";
  const std::string evidence = integrator + ": " + what + ": residual " + units + ", allowed " +
                               fmt("%g eps * scale", k) + ", scale " + to_string_full(scale) + scalar_tag<T>();
  if (claimed) {
    judge_claim(claim, true, holds, evidence, "residual " + units);
    require_close(integrator + ": " + what + " (claimed)", residual, T(0), scale, k);  // logs the residual
    return;
  }
  judge_claim(claim, false, holds, evidence, "residual " + units);
  if (holds) record_note(integrator + ": " + what + " holds although not claimed (residual " + units + ")");
}

constexpr int kStates = 3;

// ---------------------------------------------------------------------------------------------
// The rigid body with attitude.

struct NoCallback {
  template <class X>
  void operator()(int, const X&) const {}
};

template <class T, class Each = NoCallback>
RigidBodyState<T> run(const Integrator<T>& in, const Vec3<T>& I, RigidBodyState<T> x, const T& h, int steps,
                      const Each& each = {}) {
  for (int n = 0; n < steps; ++n) {
    x = in.rigid_body_step(I, x, h);
    each(n + 1, x);
  }
  return x;
}

// A rigid-body case by the notes' names.
template <class T>
std::string rigid_body_inputs(const Vec3<T>& I, const RigidBodyState<T>& x) {
  return named("I", I) + named("Pi", x.Pi) + named("O", x.O);
}

template <class T>
T state_distance(const RigidBodyState<T>& a, const RigidBodyState<T>& b) {
  return std::max(max_abs((a.Pi - b.Pi).eval()), max_abs((a.O - b.O).eval()));
}

using stepfield::explaining_manakov_step;
using stepfield::explaining_step;

// Order: errors against the Taylor oracle at t = 1 for h = 1/8 ... 1/128; the log-log slope over
// the points above the round-off plateau (16 eps * scale per step) must be within 0.1 of the claim.
template <class T>
void integrator_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const Vec3<T> I = dyn::draw_generic_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
  const T t_end(1);
  const RigidBodyState<T> exact = dyn::oracle_rigid_body(I, x0, {t_end}).front();
  const T scale = dyn::at_least_one(norm_inf(x0.Pi));
  std::vector<double> hs, errs, floors, errs_pi, errs_O;
  Series ser{"convergence: " + in.name,   "error at t = 1" + scalar_tag<T>(), "step h", "max error", true, true, {},
             static_cast<double>(c.order)};
  for (int N : {8, 16, 32, 64, 128}) {
    const T h = t_end / T(N);
    const RigidBodyState<T> y = run(in, I, x0, h, N);
    const T err = state_distance(y, exact);
    hs.push_back(to_double(h));
    errs.push_back(to_double(err));
    errs_pi.push_back(to_double(T(max_abs(Vec3<T>(y.Pi - exact.Pi)))));
    errs_O.push_back(to_double(T(max_abs(Mat3<T>(y.O - exact.O)))));
    floors.push_back(16.0 * eps_double<T>() * to_double(scale) * N);
    ser.points.emplace_back(hs.back(), errs.back());
  }
  record_series(ser);
  // Each part with its own order: a Lie-group method may be right on Pi and not on O.
  const std::string parts = parts_order({"Pi", "O"}, {errs_pi, errs_O}, hs, floors);
  explaining_step(
      in, I,
      [&] {
        return std::vector<RigidBodyState<T>>{x0, exact};
      },
      hs,
      [&] {
        showing_inputs([&] { return rigid_body_inputs(I, x0) + "    h = 1/8, halved down to 1/128; t = 1\n"; },
                       [&] { judge_order_claim(in.name, c.order, "", scalar_tag<T>(), hs, errs, floors, parts); });
      });
}

// Symmetry: step(h) then step(-h) returns to the start, at round-off: two steps, each accurate to
// a few eps (an implicit method's solve included), k = 64 on the scale of the state.
template <class T>
void integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const T h = T(1) / T(4);
  T worst(0);  // in units of the scale, which is max(1, |Pi|) <= 1 for these draws
  std::string inputs;
  for (int k = 0; k < kStates; ++k) {
    const Vec3<T> I = dyn::draw_generic_inertia<T>();
    const RigidBodyState<T> x0{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
    const RigidBodyState<T> back = in.rigid_body_step(I, in.rigid_body_step(I, x0, h), -h);
    const T r = state_distance(back, x0);
    if (k == 0 || worse(r, worst)) worst = r, inputs = rigid_body_inputs(I, x0) + "    h = 1/4\n";
  }
  showing_inputs([&] { return inputs; },
                 [&] {
                   judge_measured_claim<T>("symmetric", c.symmetric, in.name,
                                           "step(h) then step(-h) returns to the start", worst, T(1), 64);
                 });
}

// Invariants over 64 steps of h = 1/8: round-off accumulates at most linearly, k = 16 per step and
// per degree of the invariant.
constexpr int kSteps = 64;

// Where the worst residual of an invariant claim was seen, for its evidence: a state scaled by
// lambda = 2^k with the step scaled by 1/lambda (claim_state_scale below). A cause is named only
// when an experiment at the failing input confirms it: the failing case's own body and state,
// unscaled (lambda = 1, h = 1/8), is run again; `unscaled` is its residual in units of the scale
// (NaN when that run raised). When it keeps the invariant and the scaled one does not, the defect
// depends on the units (an iteration stopped at an absolute tolerance, a cut-off on the state's
// size); when it fails too, the units are not the cause, and the note says so.
template <class T>
std::string scaled_note(const T& lambda, const T& unscaled, const T& allowed) {
  if (lambda == T(1)) return {};
  const std::string where = " (worst at a state scaled by " + to_string_full(lambda) +
                            " and h by its inverse: the same motion in other units";
  if (!is_finite(unscaled))
    return where +
           "; the same body and state unscaled could not be run to compare (not finite, or the step raised): "
           "cause not identified)";
  if (!(unscaled <= allowed))
    return where + "; the same body and state unscaled fail as well, with " +
           fmt("%.3g", to_double(T(unscaled / allowed))) + " of the allowed residual: the units are not the cause)";
  return where + "; the same body and state unscaled keep it, with " + fmt("%.3g", to_double(T(unscaled / allowed))) +
         " of the allowed residual: the defect depends on the units, so an absolute "
         "tolerance (an iteration stopped when a change is below a fixed size) or a cut-off on the state's size is the "
         "cause to look for; make them relative to the state)";
}

template <class T>
T residual_size(const T& a, const T& b) {
  return abs_value(T(a - b));
}
template <class T>
T residual_size(const VecX<T>& a, const VecX<T>& b) {
  return norm_inf(VecX<T>(a - b));
}

// The experiment of scaled_note: the worst residual of `invariant` along `steps` steps of h from
// x0 (in units of `scale`), or NaN when the step raised there.
template <class T, class X, class Run, class Invariant>
T residual_along(Run&& run_from, const X& x0, const T& scale, Invariant&& invariant) {
  T worst(0);
  try {
    const auto v0 = invariant(x0);
    run_from(x0, [&](int, const X& x) {
      const T r = T(residual_size(invariant(x), v0) / scale);
      if (worse(r, worst)) worst = r;
    });
  } catch (const std::exception&) {
    return std::numeric_limits<T>::quiet_NaN();
  }
  return worst;
}

// The scale of the k-th of the kStates states of an invariant claim: the first as drawn, the
// second slowly turning (2^-j, j = 0..64), the third fast (2^j), with h scaled by 1/lambda: the
// same motion in other units (support/regimes.hpp).
template <class T>
T claim_state_scale(int k) {
  return k == 0 ? T(1) : dyn::pick<T>(gen::motion_scale_side<T>(k == 1 ? -1 : 1), "lambda (the state scaled by it)");
}

// The worst drift of `invariant` over 64 steps of h = 1/8 from kStates generic states, each
// relative to its scale. The momentum of the second and third is scaled by lambda and h by
// 1/lambda (claim_state_scale); `scale_of` is taken on the drawn state and carried over as
// lambda^degree (the invariant's degree in Pi), so the allowance does not change.
template <class T, class Invariant, class Scale>
void invariant_claim(const Integrator<T>& in, const char* claim, bool claimed, const char* name, Invariant invariant,
                     Scale scale_of, int degree) {
  T worst(0), worst_lambda(1), worst_scale(1);
  Vec3<T> I_worst;
  RigidBodyState<T> drawn_worst, x_worst;  // the worst case as drawn, and as run (scaled)
  for (int k = 0; k < kStates; ++k) {
    const Vec3<T> I = dyn::draw_generic_inertia<T>();
    const RigidBodyState<T> drawn{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
    // Inside the integrator's declared domain, h = 1/8 scaled with the state.
    const T lambda =
        within_domain<T>(claim_state_scale<T>(k), stepguard::rate_of(I, drawn), stepguard::size_of(drawn), 0.125);
    const RigidBodyState<T> x0{(drawn.Pi * lambda).eval(), drawn.O};
    const T drawn_scale = scale_of(I, drawn);
    T scale = drawn_scale;
    for (int d = 0; d < degree; ++d) scale *= lambda;
    const T v0 = invariant(I, x0);
    Series ser{std::string("invariants: ") + in.name,
               std::string(name) + scalar_tag<T>(),
               "t",
               "|residual|",
               false,
               true,
               {},
               0};
    bool this_worst = k == 0;
    run(in, I, x0, T(1) / (T(8) * lambda), kSteps, [&](int n, const RigidBodyState<T>& x) {
      const T r = abs_value(T(invariant(I, x) - v0));
      if (worse(T(r / scale), worst))
        worst = r / scale, worst_lambda = lambda, this_worst = true;  // a NaN stays the worst
      ser.points.emplace_back(n / 8.0, to_double(r));
    });
    if (this_worst) I_worst = I, drawn_worst = drawn, x_worst = x0, worst_scale = drawn_scale;
    if (k == 0) record_series(ser);
  }
  const T h_worst = T(1) / (T(8) * worst_lambda);
  const auto states = [&] {
    return std::vector<RigidBodyState<T>>{x_worst, run(in, I_worst, x_worst, h_worst, kSteps)};
  };
  explaining_step(in, I_worst, states, std::vector<double>{to_double(h_worst)}, [&] {
    showing_inputs(
        [&] {
          return rigid_body_inputs(I_worst, x_worst) + "    h = " + to_string_full(h_worst) +
                 ", 64 steps (the case with the worst residual)\n";
        },
        [&] {
          // A cause is named on a failing row only, and only on an experiment.
          const T allowed = T(T(16.0 * degree) * T(kSteps) * eps<T>());
          const bool fails = !(is_finite(worst) && worst <= allowed);
          T unscaled(0);
          if (fails && worst_lambda != T(1))
            unscaled = residual_along(
                [&](const RigidBodyState<T>& x, const auto& each) { run(in, I_worst, x, T(1) / T(8), kSteps, each); },
                drawn_worst, worst_scale, [&](const RigidBodyState<T>& x) { return invariant(I_worst, x); });
          judge_measured_claim<T>(claim, claimed, in.name,
                                  std::string(name) + " is kept to round-off over 64 steps" +
                                      (fails ? scaled_note(worst_lambda, unscaled, allowed) : std::string()),
                                  worst, T(kSteps), 16.0 * degree);
        });
  });
}

template <class T>
void integrator_casimir(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  invariant_claim<T>(
      in, "casimir", c.casimir, "the Casimir |Pi|^2",
      [](const Vec3<T>&, const RigidBodyState<T>& x) { return dyn::casimir(x.Pi); },
      [](const Vec3<T>&, const RigidBodyState<T>& x) {
        const T size = dyn::at_least_one(norm_inf(x.Pi));
        return T(size * size);
      },
      2);
}

template <class T>
void integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  invariant_claim<T>(
      in, "energy", c.energy, "the energy h (3.4)",
      [](const Vec3<T>& I, const RigidBodyState<T>& x) { return dyn::energy(I, x.Pi); },
      [](const Vec3<T>& I, const RigidBodyState<T>& x) {
        const T size = dyn::at_least_one(norm_inf(x.Pi));
        return T(size * size / I.minCoeff());
      },
      2);
}

// O^T O - Id, entrywise (scale 1).
template <class T>
void integrator_orthogonality(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  T worst(0);
  std::string inputs;
  for (int k = 0; k < kStates; ++k) {
    const Vec3<T> I = dyn::draw_generic_inertia<T>();
    const RigidBodyState<T> x0{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
    if (k == 0) inputs = rigid_body_inputs(I, x0) + "    h = 1/8, 64 steps\n";
    Series ser{
        std::string("invariants: ") + in.name, "|O^T O - Id|" + scalar_tag<T>(), "t", "|residual|", false, true, {}, 0};
    run(in, I, x0, T(1) / T(8), kSteps, [&](int n, const RigidBodyState<T>& x) {
      const T r = max_abs((x.O.transpose() * x.O - Mat3<T>::Identity()).eval());
      if (worse(r, worst)) worst = r, inputs = rigid_body_inputs(I, x0) + "    h = 1/8, 64 steps\n";
      ser.points.emplace_back(n / 8.0, to_double(r));
    });
    if (k == 0) record_series(ser);
  }
  showing_inputs([&] { return inputs; },
                 [&] {
                   judge_measured_claim<T>("orthogonality", c.orthogonality, in.name,
                                           "O^T O = Id is kept to round-off over 64 steps", worst, T(kSteps), 32);
                 });
}

// Poisson map for the bracket (3.6): with Phi the Pi-part of one step (O = Id; the Pi-part of a
// left-invariant method does not depend on O) and J(x) = hat(x) the structure matrix
// {Pi_i, Pi_j} = hat(Pi)_ij (3.12), D Phi(x) J(x) D Phi(x)^T = J(Phi(x)). D Phi by the order-8
// central difference (support/derivatives.hpp), accurate to ~eps^(8/9): ~1e-14 in double, ~1e-45
// in 50 digits. The defect's round-off is ~2 |Pi| * roundoff_factor8 eps |Pi|: k = 16 on the scale
// |Pi|^2 roundoff_factor8. A non-Poisson second-order method shows ~h^3 = 1e-2 at h = 1/4.
template <class T>
T poisson_defect(const Integrator<T>& in, std::string* inputs) {
  const Vec3<T> I = dyn::draw_generic_inertia<T>();
  const Vec3<T> Pi = dyn::draw_generic_momentum<T>();
  const T h = T(1) / T(4);
  *inputs = named("I", I) + named("Pi", Pi) + "    O = Id, h = 1/4\n";
  auto phi = [&](const Vec3<T>& p) {
    return Vec3<T>(in.rigid_body_step(I, RigidBodyState<T>{p, Mat3<T>::Identity()}, h).Pi);
  };
  Mat3<T> D;
  for (int j = 0; j < 3; ++j)
    D.col(j) = deriv::central8<T>(
        [&](const T& d) {
          Vec3<T> p = Pi;
          p(j) += d;
          return phi(p);
        },
        deriv::step8<T>());
  const Mat3<T> defect = D * truth::skew_of(Pi) * D.transpose() - truth::skew_of(phi(Pi));
  return max_abs(defect);
}

template <class T>
void integrator_poisson(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  T worst(0);  // in units of |Pi|^2 roundoff_factor8 (|Pi| <= 1 here, so of roundoff_factor8)
  std::string inputs, drawn;
  for (int k = 0; k < kStates; ++k) {
    const T r = poisson_defect<T>(in, &drawn);
    if (k == 0 || worse(r, worst)) worst = r, inputs = drawn;
  }
  showing_inputs([&] { return inputs; },
                 [&] {
                   judge_measured_claim<T>("poisson", c.poisson, in.name,
                                           "D Phi J(Pi) D Phi^T = J(Phi(Pi)): a Poisson map for (3.6)", worst,
                                           deriv::roundoff_factor8<T>(), 16);
                 });
}

// ---------------------------------------------------------------------------------------------
// Manakov's (M, O), A = diag(a).

template <class T>
struct ManakovCase {
  int n;
  std::vector<T> a;
  MatX<T> A;
  ManakovState<T> x0;
};

template <class T>
ManakovCase<T> draw_manakov_case(int lo, int hi) {
  ManakovCase<T> m;
  m.n = dyn::pick<T>(rc::gen::inRange(lo, hi + 1), "n");
  m.a = dyn::draw_generic_manakov_a<T>(m.n);
  m.A = dyn::diag_of(m.a);
  m.x0 = ManakovState<T>{dyn::draw_generic_skew<T>(m.n), dyn::pick<T>(gen::rotation<T>(m.n))};
  return m;
}

// A Manakov case by the notes' names, with the step h.
template <class T>
std::string manakov_inputs(const ManakovCase<T>& m, const T& h) {
  return named("A", m.A) + named("M", m.x0.M) + named("O", m.x0.O) + named("h", h);
}

template <class T, class Each = NoCallback>
ManakovState<T> run(const Integrator<T>& in, const MatX<T>& A, ManakovState<T> x, const T& h, int steps,
                    const Each& each = {}) {
  for (int n = 0; n < steps; ++n) {
    x = in.manakov_step(A, x, h);
    each(n + 1, x);
  }
  return x;
}

template <class T>
T state_distance(const ManakovState<T>& a, const ManakovState<T>& b) {
  return std::max(max_abs((a.M - b.M).eval()), max_abs((a.O - b.O).eval()));
}

template <class T>
void manakov_integrator_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const ManakovCase<T> m = draw_manakov_case<T>(3, 4);
  const T t_end(1);
  const ManakovState<T> exact = dyn::oracle_manakov(m.a, m.x0, {t_end}).front();
  const T scale = dyn::at_least_one(norm_inf(m.x0.M));
  std::vector<double> hs, errs, floors, errs_M, errs_O;
  Series ser{
      "convergence (Manakov): " + in.name, "error at t = 1" + scalar_tag<T>(), "step h", "max error", true, true, {},
      static_cast<double>(c.order)};
  for (int N : {8, 16, 32, 64}) {
    const T h = t_end / T(N);
    const ManakovState<T> y = run(in, m.A, m.x0, h, N);
    const T err = state_distance(y, exact);
    hs.push_back(to_double(h));
    errs.push_back(to_double(err));
    errs_M.push_back(to_double(T(max_abs(MatX<T>(y.M - exact.M)))));
    errs_O.push_back(to_double(T(max_abs(MatX<T>(y.O - exact.O)))));
    floors.push_back(16.0 * eps_double<T>() * to_double(scale) * N * m.n);
    ser.points.emplace_back(hs.back(), errs.back());
  }
  record_series(ser);
  const std::string parts = parts_order({"M", "O"}, {errs_M, errs_O}, hs, floors);
  explaining_manakov_step(
      in, m.A,
      [&] {
        return std::vector<ManakovState<T>>{m.x0, exact};
      },
      [&] {
        showing_inputs([&] { return manakov_inputs(m, T(t_end / T(8))) + "    (h halved down to 1/64)\n"; },
                       [&] {
                         judge_order_claim(in.name, c.order, " on Manakov, n = " + std::to_string(m.n), scalar_tag<T>(),
                                           hs, errs, floors, parts);
                       });
      });
}

// |M_ij| <= 1 and n <= 5 here: the scale n (entries of products summed over n terms).
template <class T>
void manakov_integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const T h = T(1) / T(4);
  T worst(0);
  ManakovCase<T> first, worst_case;
  for (int k = 0; k < kStates; ++k) {
    const ManakovCase<T> m = draw_manakov_case<T>(3, 5);
    if (k == 0) first = m;
    const ManakovState<T> back = in.manakov_step(m.A, in.manakov_step(m.A, m.x0, h), -h);
    const T r = state_distance(back, m.x0) / T(m.n);
    if (k == 0 || worse(r, worst)) worst = r, worst_case = m;
  }
  explaining_manakov_step(
      in, first.A, [&] { return std::vector<ManakovState<T>>{first.x0}; },
      [&] {
        showing_inputs([&] { return manakov_inputs(worst_case, h); },
                       [&] {
                         judge_measured_claim<T>("symmetric", c.symmetric, in.name,
                                                 "Manakov step(h) then step(-h) returns to the start", worst, T(1), 64);
                       });
      });
}

// The worst drift over 32 steps of h = 1/8 from kStates generic cases with n in [lo, hi], relative
// to |M|^degree * n^(degree - 1) (the size of the invariant's terms, summed over n per product).
// With |M_ij| up to 1 a fourth-order method drifts by ~(h |Omega|)^5 ~ 1e-6 per step: far above
// the round-off bound in double too.
constexpr int kManakovSteps = 32;

template <class T, class F>
void manakov_invariant_claim(const Integrator<T>& in, const char* claim, bool claimed, const std::string& name, int lo,
                             int hi, F invariant, int degree, int homogeneity) {
  T worst(0), worst_lambda(1), worst_scale(1);
  ManakovCase<T> worst_case, drawn_worst;  // the worst case as run (scaled), and as drawn
  for (int k = 0; k < kStates; ++k) {
    ManakovCase<T> m = draw_manakov_case<T>(lo, hi);
    const ManakovCase<T> drawn = m;
    T scale(1);
    for (int d = 0; d < degree; ++d) scale *= dyn::at_least_one(norm_inf(m.x0.M)) * (d ? T(m.n) : T(1));
    const T drawn_scale = scale;
    // M scaled by lambda and h by 1/lambda, as in invariant_claim; the invariant is homogeneous
    // of degree `homogeneity` in M (-1: it mixes degrees, as the spectrum's eigenvalues and
    // tr(M^4) do, and the states are not scaled).
    const T lambda = homogeneity < 0 ? T(1)
                                     : within_domain<T>(claim_state_scale<T>(k), stepguard::rate_of(m.A, m.x0),
                                                        stepguard::size_of(m.x0), 0.125);
    m.x0.M *= lambda;
    for (int d = 0; d < homogeneity; ++d) scale *= lambda;
    const auto v0 = invariant(m, m.x0);
    Series ser{"invariants (Manakov): " + in.name, name + scalar_tag<T>(), "t", "|residual|", false, true, {}, 0};
    bool this_worst = k == 0;
    run(in, m.A, m.x0, T(1) / (T(8) * lambda), kManakovSteps, [&](int n, const ManakovState<T>& x) {
      const T r = norm_inf((invariant(m, x) - v0).eval());
      if (worse(T(r / scale), worst)) worst = r / scale, worst_lambda = lambda, this_worst = true;
      ser.points.emplace_back(n / 8.0, to_double(r));
    });
    if (this_worst) worst_case = m, drawn_worst = drawn, worst_scale = drawn_scale;
    if (k == 0) record_series(ser);
  }
  const T h_worst = T(1) / (T(8) * worst_lambda);
  const auto states = [&] {
    return std::vector<ManakovState<T>>{worst_case.x0, run(in, worst_case.A, worst_case.x0, h_worst, kManakovSteps)};
  };
  explaining_manakov_step(in, worst_case.A, states, [&] {
    const auto inputs = [&] {
      return manakov_inputs(worst_case, h_worst) + "    (32 steps; the case with the worst residual)\n";
    };
    showing_inputs(inputs, [&] {
      const T allowed = T(T(16.0 * degree) * T(kManakovSteps) * eps<T>());
      const bool fails = !(is_finite(worst) && worst <= allowed);
      T unscaled(0);
      if (fails && worst_lambda != T(1))
        unscaled = residual_along(
            [&](const ManakovState<T>& x, const auto& each) {
              run(in, drawn_worst.A, x, T(1) / T(8), kManakovSteps, each);
            },
            drawn_worst.x0, worst_scale, [&](const ManakovState<T>& x) { return invariant(drawn_worst, x); });
      judge_measured_claim<T>(claim, claimed, in.name,
                              name + " is kept to round-off over 32 steps" +
                                  (fails ? scaled_note(worst_lambda, unscaled, allowed) : std::string()),
                              worst, T(kManakovSteps), 16.0 * degree);
    });
  });
}

template <class T>
VecX<T> one(const T& x) {
  VecX<T> v(1);
  v(0) = x;
  return v;
}

// The Manakov invariants, with the scales of manakov_invariant_claim.
template <class T>
void manakov_integrator_casimir(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  manakov_invariant_claim<T>(
      in, "casimir", c.casimir, "the Casimir tr(M^2)", 3, 5,
      [](const ManakovCase<T>&, const ManakovState<T>& x) { return one(T((x.M * x.M).trace())); }, 2, 2);
}

template <class T>
void manakov_integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  manakov_invariant_claim<T>(
      in, "energy", c.energy, "the energy -tr(Omega M)/4", 3, 5,
      [](const ManakovCase<T>& m, const ManakovState<T>& x) { return one(dyn::manakov_energy(m.a, x.M)); }, 2, 2);
}

template <class T>
void manakov_integrator_orthogonality(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  manakov_invariant_claim<T>(
      in, "orthogonality", c.orthogonality, "O^T O = Id", 3, 5,
      [](const ManakovCase<T>& m, const ManakovState<T>& x) {
        const MatX<T> E = x.O.transpose() * x.O - MatX<T>::Identity(m.n, m.n);
        return VecX<T>(E.reshaped());
      },
      2, 0);
}

// The spectrum for n = 5, where the quadratic invariants (tr M^2, and for n = 4 a Pfaffian-like
// quadratic) no longer fix it: the eigenvalues lambda_j^2 of -M^2 and tr(M^4), on the scale
// |M|^4 (the larger of the two scales), tr(M^4) being of degree 4. Not scaled (homogeneity -1):
// the two parts have different degrees in M.
template <class T>
void manakov_integrator_spectrum(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  manakov_invariant_claim<T>(
      in, "spectrum", c.spectrum, "the spectrum of M (eigenvalues of -M^2 and tr(M^4))", 5, 5,
      [](const ManakovCase<T>&, const ManakovState<T>& x) {
        const VecX<T> ev = spectral::skew_spectrum<T>(x.M);
        VecX<T> v(ev.size() + 1);
        v << ev, spectral::power_traces<T>(x.M, 4)[3];
        return v;
      },
      4, -1);
}

// Poisson map for the Lie-Poisson bracket of so(n)*, {F, H}(M) = -<M, [dF/dM, dH/dM]> (2.23) in
// the coordinates m_ij = M_ij (i < j), orthonormal for (2.15): J(M)_(ij),(kl) = -<M, [E_ij, E_kl]>.
// n = 4 (6 coordinates). Same difference scheme and tolerance as for the rigid body.
template <class T>
T manakov_poisson_defect(const Integrator<T>& in, std::string* inputs) {
  const int n = 4, d = 6;
  const auto a = dyn::draw_generic_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  const MatX<T> M0 = dyn::draw_generic_skew<T>(n);
  const T h = T(1) / T(4);
  *inputs = named("A", A) + named("M", M0) + "    O = Id, h = 1/4\n";
  std::vector<std::pair<int, int>> idx;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) idx.push_back({i, j});
  auto coords = [&](const MatX<T>& M) {
    VecX<T> v(d);
    for (int k = 0; k < d; ++k) v(k) = M(idx[k].first, idx[k].second);
    return v;
  };
  auto basis = [&](int k) {
    MatX<T> E = MatX<T>::Zero(n, n);
    E(idx[k].first, idx[k].second) = T(1);
    E(idx[k].second, idx[k].first) = T(-1);
    return E;
  };
  auto J = [&](const MatX<T>& M) {
    MatX<T> out(d, d);
    for (int k = 0; k < d; ++k)
      for (int l = 0; l < d; ++l) {
        const MatX<T> Ek = basis(k), El = basis(l);
        out(k, l) = -(M.transpose() * (Ek * El - El * Ek)).trace() / T(2);
      }
    return out;
  };
  auto phi = [&](const MatX<T>& M) { return in.manakov_step(A, ManakovState<T>{M, MatX<T>::Identity(n, n)}, h).M; };
  MatX<T> D(d, d);
  for (int k = 0; k < d; ++k)
    D.col(k) =
        deriv::central8<T>([&](const T& e) { return coords((phi((M0 + e * basis(k)).eval()))); }, deriv::step8<T>());
  const MatX<T> defect = D * J(M0) * D.transpose() - J(phi(M0));
  return max_abs(defect);
}

// |M_ij| <= 1: scale d * roundoff_factor8 (sums of d terms).
template <class T>
void manakov_integrator_poisson(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  T worst(0);
  std::string inputs, drawn;
  for (int k = 0; k < kStates; ++k) {
    const T r = manakov_poisson_defect<T>(in, &drawn);
    if (k == 0 || worse(r, worst)) worst = r, inputs = drawn;
  }
  showing_inputs([&] { return inputs; },
                 [&] {
                   judge_measured_claim<T>(
                       "poisson", c.poisson, in.name,
                       "D Phi J(M) D Phi^T = J(Phi(M)): a Poisson map for the Lie-Poisson bracket of so(4)*", worst,
                       T(T(6) * deriv::roundoff_factor8<T>()), 16);
                 });
}

}  // namespace

#define GM_RB .cases = {.d = 10, .mp = 2, .q = 0}, .step = StepKind::RigidBody
#define GM_MK .cases = {.d = 5, .mp = 1, .q = 0}, .step = StepKind::Manakov
// The quadratic invariants in 50 digits: three cases, so that some state turns slowly enough
// (2^-20 or less) for an absolute tolerance at 1e-50 to show (about 0.7 per case).
#define GM_MK_SCALED .cases = {.d = 5, .mp = 3, .q = 0}, .step = StepKind::Manakov

GM_PROPERTY(
    integrator_order, integrator_scalars,
    {.id = "integrator_order",
     .spec = "s3.euler-flow",
     .title = "rigid-body integrator: the claimed order is the log-log slope of the error against h (within 0.1)",
     .tolerance = ToleranceClass::Truncation,
     .needs = {},
     .negative_controls = {"splitting_lie_trotter", "midpoint_one_iteration"},
     GM_RB,
     .judges = {"order"}});

GM_PROPERTY(integrator_symmetric, integrator_scalars,
            {.id = "integrator_symmetric",
             .spec = "s3.euler-flow",
             .title = "rigid-body integrator claimed symmetric: step(h) then step(-h) is the identity to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"splitting_lie_trotter", "rk4_claims_everything"},
             GM_RB,
             .judges = {"symmetric"}});

GM_PROPERTY(integrator_casimir, integrator_scalars,
            {.id = "integrator_casimir",
             .spec = "s3.euler-flow",
             .title = "rigid-body integrator claiming the Casimir: |Pi|^2 kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything", "midpoint_one_iteration", "midpoint_absolute_tolerance"},
             GM_RB,
             .judges = {"casimir"}});

GM_PROPERTY(integrator_energy, integrator_scalars,
            {.id = "integrator_energy",
             .spec = "s3.euler-flow",
             .title = "rigid-body integrator claiming the energy: h (3.4) kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything", "midpoint_one_iteration", "midpoint_absolute_tolerance"},
             GM_RB,
             .judges = {"energy"}});

GM_PROPERTY(integrator_orthogonality, integrator_scalars,
            {.id = "integrator_orthogonality",
             .spec = "s2.reconstruction",
             .title = "rigid-body integrator claiming orthogonality: O^T O = Id kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything"},
             // Its own matrix only: a quaternion's matrix is the suite's R(q / |q|), orthogonal by
             // construction (its norm is integrator_unit_quaternion's).
             .cases = {.d = 10, .mp = 2, .q = 0},
             .step = StepKind::RigidBodyMatrix,
             .judges = {"orthogonality"}});

GM_PROPERTY(integrator_poisson, integrator_scalars,
            {.id = "integrator_poisson",
             .spec = "s3.euler-flow",
             .title = "rigid-body integrator claimed Poisson: D Phi J D Phi^T = J o Phi for the bracket (3.6)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything"},
             GM_RB,
             .judges = {"poisson"}});

GM_PROPERTY(manakov_integrator_order, integrator_scalars,
            {.id = "manakov_integrator_order",
             .spec = "s2.manakov-flow",
             .title = "Manakov integrator: the claimed order is the log-log slope of the error against h (within 0.1)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"manakov_isospectral_explicit", "midpoint_one_iteration",
                                   "manakov_midpoint_commutator_reversed"},
             GM_MK,
             .judges = {"order"}});

GM_PROPERTY(manakov_integrator_symmetric, integrator_scalars,
            {.id = "manakov_integrator_symmetric",
             .spec = "s2.manakov-flow",
             .title = "Manakov integrator claimed symmetric: step(h) then step(-h) is the identity to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"manakov_isospectral_explicit", "rk4_claims_everything"},
             GM_MK,
             .judges = {"symmetric"}});

GM_PROPERTY(manakov_integrator_casimir, integrator_scalars,
            {.id = "manakov_integrator_casimir",
             .spec = "s2.isospectral",
             .title = "Manakov integrator claiming the Casimir: tr(M^2) kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything", "midpoint_one_iteration", "midpoint_absolute_tolerance"},
             GM_MK_SCALED,
             .judges = {"casimir"}});

GM_PROPERTY(manakov_integrator_energy, integrator_scalars,
            {.id = "manakov_integrator_energy",
             .spec = "s2.manakov-flow",
             .title = "Manakov integrator claiming the energy: -tr(Omega M)/4 kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything", "manakov_isospectral_explicit",
                                   "midpoint_absolute_tolerance"},
             GM_MK_SCALED,
             .judges = {"energy"}});

GM_PROPERTY(manakov_integrator_orthogonality, integrator_scalars,
            {.id = "manakov_integrator_orthogonality",
             .spec = "s2.manakov-flow",
             .title = "Manakov integrator claiming orthogonality: O^T O = Id kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything"},
             GM_MK,
             .judges = {"orthogonality"}});

GM_PROPERTY(
    manakov_integrator_spectrum, integrator_scalars,
    {.id = "manakov_integrator_spectrum",
     .spec = "s2.isospectral",
     .title = "Manakov integrator claiming the spectrum: eigenvalues of M and tr(M^4) kept to round-off (n = 5)",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {},
     .negative_controls = {"rk4_claims_everything"},
     GM_MK,
     .judges = {"spectrum"}});

GM_PROPERTY(manakov_integrator_poisson, integrator_scalars,
            {.id = "manakov_integrator_poisson",
             .spec = "s2.manakov-flow",
             .title = "Manakov integrator claimed Poisson: D Phi J D Phi^T = J o Phi on so(4)*",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"rk4_claims_everything"},
             GM_MK,
             .judges = {"poisson"}});

#undef GM_RB
#undef GM_MK
#undef GM_MK_SCALED

}  // namespace properties_integrator_claims
}  // namespace gm
