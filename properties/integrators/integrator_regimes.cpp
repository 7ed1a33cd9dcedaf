// Integrators outside the generic case: the states and bodies real code has branches
// for, and the 50-digit floor.
//
// 1. Convergence in every regime. The properties of integrator_claims.cpp draw generic states
//    (distinct moments, every |Pi_i| >= 1/8), so a "fast path" for a body spinning about a
//    principal axis, or a branch for a symmetric top, is never entered. Here the state is drawn
//    from: a relative equilibrium (Pi along a principal axis: it must stay one, O turning about
//    that axis), a state near one, a symmetric top (two equal moments), a spherical top; and in
//    half of the cases that state has its momentum scaled by lambda = 2^k, k = -64..64, and the
//    time by 1/lambda. Euler's equations and (2.20) are homogeneous: Pi(t) solves them iff
//    lambda Pi(t / lambda) does, with the same O. So the scaled problem is the drawn one in other
//    units, and a step written without a hard-coded scale (every correct one: multiplying by 2^k
//    is exact in binary floating point) gives the same relative errors; a step with a cut-off
//    ("a body with |Pi| < 1e-10 is at rest", a solver stopped at an absolute tolerance such as
//    eps (1 + |Pi|)) does not, once the scale crosses it. The error at a fixed time against the
//    Taylor oracle (oracle/, independent of every subject) must converge: at least at the claimed order
//    where one is claimed (order at least p: a regime may be easier, never harder), and at least
//    at order 1 - 0.1 otherwise (an integrator of (2.20) that does not converge is wrong whatever
//    it claims).
// 2. The 50-digit floor. One step of h = 2^-40 from a generic state, in 50 digits: a method of
//    any order p >= 1 has a local error C h^(p+1) <= C 2^-80 ~ 1e-24 |x|, and the oracle is exact
//    to ~1e-48; a step that is computed (in part) in double shows an error near 1e-16 |x|.
//    Only a 50-digit run can see this, so the property runs in mp50 only.
// 3. The local order. One step from a generic state for a decreasing sequence of h, against the
//    oracle: a method of order p has a local error C h^(p+1), so the log-log slope of the error
//    against h must be at least p + 1 - 0.1 (a claimed order p), or 2 - 0.1 (no claim: a step whose
//    local error is not O(h^2) does not converge). The global checks (integrator_claims.cpp) use
//    h >= 1/128 and dyadic steps 1/N, and miss a step taken with a slightly wrong h: h (1 + 2^-20),
//    or h stored in a float (rounded to 24 bits), adds an error delta h |f| that is first order
//    but hidden under C h^p there, and a dyadic h is exact in a float anyway. Here h = c 2^-k t_s,
//    c = j / (3 2^6) in [1/2, 1) is not a dyadic rational (a float cannot hold it), t_s is the time
//    scale of the motion, and k = 6..10 in double for a second-order method (its local error stays
//    ~1e-10 |x|, far above round-off and above an implicit solve stopped at a tolerance of 1e-12;
//    4..8 for fourth order, see local_order_exponents) and 8..28 in 50 digits, where delta h |f|
//    outweighs C h^3 by 10^10 for delta = 2^-24.
// 4. Small turns. An engine may skip the attitude's update when a step turns it by less than some
//    angle ("nothing to integrate" below |Omega h| = 1e-6): a slowly turning body never turns, and
//    every other check turns it by 2^-10 rad a step or more. Here a generic state is stepped 1024
//    times at h |Omega| = 2^-j, j = 10, 14, 18, ... down to two bits above the precision the step is
//    judged at (float: 2^-21 = 4.8e-7 rad a step, still four to eight units of the last place of
//    O's entries; double: 2^-50); the state must move as the flow does: its distance from the flow
//    after the 1024 steps at most half of how far the flow moved it. A skip leaves all of it; round-off,
//    even half a unit of the last place a step in one direction, leaves at most an eighth at the
//    smallest turn, and truncation is h^p smaller still.
//
// Spec entries: the flows of (2.20) and Manakov's (M, O) (s3.euler-flow, s2.manakov-flow).
#include "properties/integrators/support/convergence.hpp"
#include "properties/integrators/support/step_field.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/integrators/support/step_kind.hpp"
#include "properties/integrators/support/step_runs.hpp"
#include "properties/registry.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace gm {
namespace properties_integrator_regimes {
namespace {

// The traits of both kinds (support/step_kind.hpp), for the local order and the 50-digit floor.
using stepkind::ManakovKind;
using stepkind::RigidBodyKind;

const char* kRegimeNames[] = {"generic",
                              "relative equilibrium (Pi along a principal axis)",
                              "near a relative equilibrium",
                              "symmetric top (two equal moments)",
                              "spherical top",
                              "nearly symmetric top (two moments 2^-k apart)"};

struct RegimeDraw {
  int regime;
  int axis;
  int k;
};

template <class T>
struct RigidBodyRegime {
  Vec3<T> I;
  RigidBodyState<T> x0;
  T t_end;
  int regime;
  T lambda = T(1);  // the scale: x0.Pi = lambda Pi_drawn, t_end = t_drawn / lambda (1: not scaled)
};

// The regime's name, with the scale if any.
template <class T>
std::string regime_name(const RigidBodyRegime<T>& r) {
  return std::string(kRegimeNames[r.regime]) +
         (r.lambda == T(1) ? "" : ", momentum scaled by " + to_string_full(r.lambda) + " and time by its inverse");
}

// A body and a state from one of the regimes above; t_drawn = 1 / max(1, |Omega|) so that the
// motion turns by at most about a radian, then scaled (half of the cases).
template <class T>
RigidBodyRegime<T> draw_rigid_body_regime() {
  RigidBodyRegime<T> r;
  r.regime = dyn::pick<T>(gen::uniform(0, 6),
                          "regime (0 generic, 1 on an axis, 2 near one, 3 symmetric top, 4 sphere, "
                          "5 nearly symmetric)");
  const int axis = dyn::pick<T>(gen::uniform(0, 3), "axis (of the regime)");
  r.I = dyn::draw_generic_inertia<T>();
  Vec3<T> P = dyn::draw_generic_momentum<T>();
  switch (r.regime) {
    case 1: {  // along a principal axis
      const T p = P(axis);
      P = Vec3<T>::Zero();
      P(axis) = p;
      break;
    }
    case 2: {  // near one: the other components 2^-k times smaller, k in [10, 40]
      const int k = dyn::pick<T>(gen::uniform(10, 41), "k (the other components 2^-k smaller)");
      for (int i = 0; i < 3; ++i)
        if (i != axis) P(i) *= gen::pow2<T>(-k);
      break;
    }
    case 3: {  // symmetric top: the two moments other than `axis` equal
      r.I((axis + 2) % 3) = r.I((axis + 1) % 3);
      break;
    }
    case 4:  // spherical top
      r.I = Vec3<T>::Constant(r.I(0));
      break;
    case 5: {  // nearly symmetric: two moments 2^-k apart, k in [10, 52] (a branch for I1 == I2 taken too early)
      const int k = dyn::pick<T>(gen::uniform(10, 53), "k (two moments 2^-k apart, relatively)");
      r.I((axis + 2) % 3) = r.I((axis + 1) % 3) * (T(1) + gen::pow2<T>(-k));
      break;
    }
    default:
      break;
  }
  // In half of the cases (support/regimes.hpp); a failing case shrinks to the scale nearest 1 that still fails.
  r.lambda = dyn::pick<T>(gen::motion_scale<T>(1, 2), "lambda (Pi scaled by it)");
  r.x0 = RigidBodyState<T>{P, dyn::draw_attitude<T>()};
  const T rate = dyn::at_least_one(T(norm_inf(P) / r.I.minCoeff()));
  // Inside the integrator's declared domain: the scale halved until the state, its rate
  // and the smallest step (t / 128) are.
  r.lambda = within_domain<T>(r.lambda, stepguard::rate_of(r.I, r.x0), to_double(T(norm_inf(P))),
                              to_double(T(T(1) / rate / T(128))));
  r.t_end = T(1) / rate;
  r.x0.Pi *= r.lambda;
  r.t_end /= r.lambda;
  return r;
}

// The flow at t_end. The oracle runs on the drawn problem (Pi / lambda to t_end lambda), whose sizes
// it is made for, and its momentum is scaled back: exact, since lambda is a power of 2.
template <class T>
RigidBodyState<T> flow_at_end(const RigidBodyRegime<T>& r) {
  const RigidBodyState<T> drawn{(r.x0.Pi / r.lambda).eval(), r.x0.O};
  RigidBodyState<T> x = dyn::oracle_rigid_body(r.I, drawn, {T(r.t_end * r.lambda)}).front();
  x.Pi *= r.lambda;
  return x;
}

template <class T>
RigidBodyState<T> run_steps(const Integrator<T>& in, const Vec3<T>& I, RigidBodyState<T> x, const T& h, int steps) {
  for (int n = 0; n < steps; ++n) x = in.rigid_body_step(I, x, h);
  return x;
}

template <class T>
ManakovState<T> run_steps(const Integrator<T>& in, const MatX<T>& A, ManakovState<T> x, const T& h, int steps) {
  for (int n = 0; n < steps; ++n) x = in.manakov_step(A, x, h);
  return x;
}

// Distance of states relative to the momentum's size (Pi part) and absolute for O (entries <= 1).
template <class T>
T relative_distance(const RigidBodyState<T>& a, const RigidBodyState<T>& b, const T& pi_size) {
  return std::max(T(max_abs((a.Pi - b.Pi).eval()) / pi_size), T(max_abs((a.O - b.O).eval())));
}

// The same for Manakov's (M, O), relative to the size of M.
template <class T>
T relative_distance(const ManakovState<T>& a, const ManakovState<T>& b, const T& m_size) {
  return std::max(T(max_abs((a.M - b.M).eval()) / m_size), T(max_abs((a.O - b.O).eval())));
}

// The verdict of a convergence run (1. at the top of this file): the log-log slope of the error at
// t against h must be at least the claimed order p - 0.1, or 1 - 0.1 without a claim; a run with
// fewer than three points above round-off must have converged. `hints` says what usually causes
// a failure in this case.
void judge_convergence(const std::string& integrator, const IntegratorClaims& c, const std::string& scalar,
                       const std::string& regime, const std::vector<double>& hs, const std::vector<double>& errs,
                       const std::vector<double>& floors, const std::string& inputs, const std::string& hints) {
  // The steps are fractions of the run's time t (t = 1 / |Omega|): h/t, not h.
  const auto fit = conv::loglog_slope(hs, errs, floors, "h/t");
  if (fit.used < 3) {
    // Exact in this regime (errors at round-off for every step), not measurable (one or two steps
    // above the round-off floor, the rest on it: an order cannot be read at this precision), or not
    // converging at all: an error that is large at every step is the last, and the claim's finding
    // says so first.
    const bool converged = errs.back() <= floors.back();
    const bool exact = conv::at_roundoff_everywhere(errs, floors);
    // At a precision coarser than the scalar (a float step), a regime whose truncation stands above
    // float's round-off at fewer than three steps (a slow special state) is no evidence either way:
    // said, not counted against the claim (the order rests on the checks that measure it).
    const bool coarse = current_step_precision().coarser_than<double>();
    const std::string stall = conv::stall_words(errs, floors.back());
    record_claim_finding(
        "order", c.order > 0, converged,
        exact ? integrator + ": at round-off in the regime '" + regime + "' (" + scalar + "): no order contradicted"
        : converged ? integrator + ": fewer than three step sizes above the round-off floor in the regime '" + regime +
                          "' (" + scalar + "): order not measurable at this precision"
                    : integrator + ": does not converge in the regime '" + regime + "' (" + scalar + "): " + stall,
        exact       ? std::string()
        : converged ? (coarse ? "not measurable at " + current_step_precision().name + "'s precision in this regime"
                              : std::string("not measurable (fewer than three step sizes above round-off)"))
                    : "does not converge",
        true);
    require(integrator + ": the error at t converges to 0 as h -> 0 (" + regime + ")", converged,
            stall + "\n" + fit.table + "  inputs, by the notes' names:\n" + inputs + hints);
    return;
  }
  const double needed = c.order > 0 ? c.order - 0.1 : 0.9;
  const bool holds = fit.slope >= needed;
  showing_inputs(
      [&] { return inputs + "  the error at t against h:\n" + fit.table + hints; },
      [&] {
        judge_claim(
            "order", c.order > 0, holds,
            integrator + fmt(": measured order %.3f in the regime '", fit.slope) + regime +
                (c.order > 0 ? fmt("', claimed %g", c.order) : std::string("', no order claimed: at least 0.9")) +
                " (" + scalar + ")",
            holds ? std::string() : fmt("order %.2f", fit.slope) + " in the regime '" + regime + "'");
      });
  require(integrator + ": in the regime '" + regime + "' the error at t converges at order >= " + fmt("%.1f", needed) +
              (c.order > 0 ? fmt(" (claimed order %g)", c.order) : std::string(" (any convergent method)")),
          holds,
          fmt("measured slope %.4f\n", fit.slope) + fit.table + "  inputs, by the notes' names:\n" + inputs + hints);
}

// A convergence run of a regime: the error at t_end for h = t/8 ... t/128 (hs as fractions of t,
// h_run the steps themselves), with the round-off floors judge_convergence uses (64 eps per step,
// eps the step's own). Where fewer than three of them stand above the floor (a step computed in
// float, whose truncation error at these steps sinks into float's round-off), the run is made again
// to t = 1 / |Omega| with h = t/4 ... t/128 by factors of about sqrt(2): the same motion, with the
// steps as large against its time scale as an order can be read at (`ladder` says which was run).
struct ConvergenceRun {
  std::vector<double> hs, h_run, errs, floors;
  std::string ladder = "h = t/8 ... t/128";
  double t = 0;
};

template <class T>
ConvergenceRun convergence_run_at(const Integrator<T>& in, const RigidBodyRegime<T>& r, const std::vector<int>& Ns) {
  const T pi_size = norm_inf(r.x0.Pi);
  const RigidBodyState<T> exact = flow_at_end(r);
  ConvergenceRun run;
  run.t = to_double(r.t_end);
  for (int N : Ns) {
    const T h = r.t_end / T(N);
    run.errs.push_back(to_double(relative_distance(run_steps(in, r.I, r.x0, h, N), exact, pi_size)));
    run.hs.push_back(to_double(T(h / r.t_end)));
    run.h_run.push_back(to_double(h));
    // 64 eps a step in the step's own scalar; 16 for a step judged at a coarser precision (a float
    // step), whose round-off is under one eps a step (measured: examples/integrators/float_cases.hpp),
    // as integrator_order's floor.
    run.floors.push_back((current_step_precision().coarser_than<T>() ? 16.0 : 64.0) * step_eps_double<T>() * N);
    if (!std::isfinite(run.errs.back())) break;
  }
  return run;
}

template <class T>
ConvergenceRun convergence_run(const Integrator<T>& in, const RigidBodyRegime<T>& r) {
  ConvergenceRun run = convergence_run_at(in, r, {8, 16, 32, 64, 128});
  if (conv::loglog_slope(run.hs, run.errs, run.floors).used >= 3 || conv::first_non_finite(run.hs, run.errs) > 0)
    return run;
  RigidBodyRegime<T> longer = r;
  const T rate = max_abs(Vec3<T>(r.x0.Pi.cwiseQuotient(r.I)));
  if (!(rate > T(0))) return run;
  longer.t_end = T(1) / rate;
  if (!(longer.t_end > r.t_end)) return run;  // already turning a radian: nothing to gain
  ConvergenceRun again = convergence_run_at(in, longer, {4, 6, 8, 11, 16, 23, 32, 45, 64, 91, 128});
  if (conv::loglog_slope(again.hs, again.errs, again.floors).used <=
      conv::loglog_slope(run.hs, run.errs, run.floors).used)
    return run;
  again.ladder = "h = t/4 ... t/128 by factors of about sqrt(2), t = 1/|Omega| = " + fmt("%.6g", again.t) +
                 " (at t = " + fmt("%.6g", run.t) + " fewer than three steps stood above the round-off floor)";
  return again;
}

// Whether a run passes judge_convergence's rule (the same slope and plateau rule, nothing recorded).
bool converges(const IntegratorClaims& c, const ConvergenceRun& run) {
  const auto fit = conv::loglog_slope(run.hs, run.errs, run.floors, "h/t");
  if (fit.used < 3) return run.errs.back() <= run.floors.back();
  return fit.slope >= (c.order > 0 ? c.order - 0.1 : 0.9);
}

// An experiment: the same check on a variant of the failing case. "passes", "fails" or "raised".
// It passes only when the variant converges at the failing steps (h = t/8 ... t/128) and at smaller
// ones (t/256 ... t/4096): a defect of order h can hide behind a larger h^2 term at the failing
// steps, and a cause confirmed there alone would be refuted at the next halving.
template <class T>
std::string experiment(const Integrator<T>& in, const IntegratorClaims& c, const RigidBodyRegime<T>& variant,
                       std::string& measured) {
  try {
    const ConvergenceRun x = convergence_run(in, variant);
    measured = fmt("error %.3g at h = t/128", x.errs.back());
    if (!converges(c, x)) return "fails";
    const ConvergenceRun smaller = convergence_run_at(in, variant, {128, 256, 512, 1024, 2048, 4096});
    measured += fmt(", %.3g at h = t/4096", smaller.errs.back());
    return converges(c, smaller) ? "passes" : "fails";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    measured = "the step raised: " + what.substr(0, std::min(what.find('\n'), std::size_t(200)));
    return "raised";
  }
}

// The same for a run of another kind (a Manakov frame): the variant's run at the failing steps only.
template <class Run>
std::string experiment(const IntegratorClaims& c, Run&& run, std::string& measured) {
  try {
    const ConvergenceRun x = run();
    measured = fmt("error %.3g at h = t/128", x.errs.back());
    return converges(c, x) ? "passes" : "fails";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    measured = "the step raised: " + what.substr(0, std::min(what.find('\n'), std::size_t(200)));
    return "raised";
  }
}

// The attitude turned by about 1/4 rad in space (R O, R the Cayley factor of hat(1/3, 2/3, 2/3) / 8):
// the motion is left invariant (Remark 2.1), so R O(t) is the flow from R O(0) with the same Pi(t), and
// the whole run of attitudes moves away from the identity and from a rotation by pi, not its start
// only.
template <class T>
Mat3<T> turned_off(const Mat3<T>& O) {
  const Vec3<T> axis(T(1) / T(3), T(2) / T(3), T(2) / T(3));
  Mat3<T> S;
  S << T(0), -axis(2), axis(1), axis(2), T(0), -axis(0), -axis(1), axis(0), T(0);
  S /= T(8);
  const Mat3<T> Id = Mat3<T>::Identity();
  return Mat3<T>((Id - S).inverse() * (Id + S) * O);
}

// The rotation angle of O, by atan2 of its skew and symmetric parts (accurate near 0 and near pi).
template <class T>
double rotation_angle(const Mat3<T>& O) {
  const Mat3<T> A = O - O.transpose();
  const double s = std::sqrt(to_double(T(A(2, 1) * A(2, 1) + A(0, 2) * A(0, 2) + A(1, 0) * A(1, 0)))) / 2;
  return std::atan2(s, to_double(T((O.trace() - T(1)) / T(2))));
}

// A body at rest (Pi = 0) with the attitude 2^-12 rad from the identity: a step must leave it where it
// is. How far it turns it in one step, at h = 1/4 and at h = 2^-10 (0 when it stays; NaN when the
// step raised).
template <class T>
std::pair<double, double> turn_at_rest(const Integrator<T>& in, const Vec3<T>& I) {
  const Vec3<T> a(gen::pow2<T>(-12), T(0), T(0));
  const Mat3<T> A = truth::skew_of(a), Id = Mat3<T>::Identity();
  const RigidBodyState<T> rest{Vec3<T>::Zero(), Mat3<T>((Id - A / T(2)).inverse() * (Id + A / T(2)))};
  const auto turn = [&](const T& h) {
    try {
      return to_double(T(max_abs(Mat3<T>(in.rigid_body_step(I, rest, h).O - rest.O))));
    } catch (const std::exception&) {
      current_step_raise().reset();
      return std::nan("");
    }
  };
  return {turn(T(1) / T(4)), turn(gen::pow2<T>(-10))};
}

// What a failure of integrator_converges_in_every_regime is due to, by experiment at the failing
// case itself (DESIGN.md, "A cause is an experiment"), after the step's own vector field against
// (3.8) and (2.10), which leads the failure (explaining_step in support/step_field.hpp); called
// only when that field names no cause. One cause, confirmed, or "cause not identified" with what
// was tried, in this order, each experiment passing at the failing steps and at smaller ones:
//   1. a scaled case run again unscaled: if that passes, the defect depends on the units;
//   2. an attitude that comes within 2^-6 rad of the identity (or of a rotation by pi), at the start
//      or along the run, turned about 1/4 rad in space (R O: the whole run moves away), all else the
//      same: if that passes, the step branches on the attitude's own angle (a small-angle series); a
//      body at rest near the identity that the step turns is said with it;
//   3. a special state (on a principal axis or near one, equal moments) moved off its special set
//      as a whole, the momentum given components of 2^-6 of its size off the axis (the moments made
//      distinct by 2^-6) and the attitude turned off the identity as in 2: if that passes, the step
//      branches at the special state.
template <class T>
std::string regime_evidence(const Integrator<T>& in, const RigidBodyRegime<T>& r, const IntegratorClaims& c) {
  std::string out, measured;
  if (r.lambda != T(1)) {
    RigidBodyRegime<T> u = r;
    u.lambda = T(1);
    u.x0.Pi /= r.lambda;
    u.t_end *= r.lambda;
    const std::string e = experiment(in, c, u, measured);
    if (e == "passes")
      return "  cause, by experiment: the same body and state unscaled (momentum divided by " +
             to_string_full(r.lambda) + ", time multiplied by it) converge (" + measured +
             "); scaled they do not: the defect depends on the units\n"
             "  what to look for (not confirmed): a cut-off on the size of the momentum (a body 'at rest' below some "
             "size), or an iteration stopped at an absolute tolerance such as eps (1 + |Pi|); make them relative "
             "to the momentum's size\n";
    out += "    the same body and state unscaled " + std::string(e == "fails" ? "fail as well" : "could not be run") +
           " (" + measured + "): the units are not the cause\n";
  }
  // The attitude near a branch point of the rotation group (the identity, a rotation by pi), at the
  // start or anywhere along the run (the flow at 64 times: a motion about an axis can pass through the
  // identity): the closest approach.
  double angle = rotation_angle(r.x0.O), from_pi = M_PI - angle;
  {
    std::vector<T> times;
    for (int k = 1; k <= 64; ++k) times.push_back(T(T(k) * r.t_end * r.lambda / T(64)));
    const RigidBodyState<T> drawn{(r.x0.Pi / r.lambda).eval(), r.x0.O};
    for (const auto& x : dyn::oracle_rigid_body(r.I, drawn, times)) {
      const double a = rotation_angle(x.O);
      angle = std::min(angle, a), from_pi = std::min(from_pi, M_PI - a);
    }
  }
  const bool near_identity = angle < std::ldexp(1.0, -6), near_pi = !near_identity && from_pi < std::ldexp(1.0, -6);
  const bool attitude_special = near_identity || near_pi;
  const std::string where = near_identity ? "the identity" : "a rotation by pi";
  if (attitude_special) {
    RigidBodyRegime<T> n = r;
    n.x0.O = turned_off(r.x0.O);
    const std::string e = experiment(in, c, n, measured);
    if (e == "passes") {
      std::string at_rest;
      if (near_identity) {
        const auto [big, small] = turn_at_rest(in, r.I);
        if (big > 0 && small > 0)
          at_rest =
              fmt("; besides, a body at rest 2^-12 rad from the identity is turned by %.3g at h = 1/4 and by ", big) +
              fmt("%.3g at h = 2^-10 (a step must leave it where it is)", small);
      }
      return "  cause, by experiment: the attitude comes within " + fmt("%.2g", near_identity ? angle : from_pi) +
             " rad of " + where +
             " along the run; turned in space by about 1/4 rad (the same body, momentum and time), "
             "the step "
             "converges (" +
             measured + "): the step branches on the attitude's own angle near " + where +
             " (a small-angle series or a threshold on the rotation angle, a quaternion's sign)" + at_rest + "\n";
    }
    out += "    with the attitude turned 1/4 rad in space, away from " + where + ", it " +
           std::string(e == "fails" ? "fails as well" : "could not be run") + " (" + measured +
           "): the attitude's angle is not the cause\n";
  }
  if (r.regime != 0) {
    RigidBodyRegime<T> n = r;
    std::string how;
    if (r.regime <= 2) {
      const T d = norm_inf(r.x0.Pi) * gen::pow2<T>(-6);
      n.x0.Pi += Vec3<T>(d, -d, d);
      how = "the momentum nudged off the axis by 2^-6 of its size";
    } else {
      n.I(0) *= T(1) + gen::pow2<T>(-6);
      n.I(1) *= T(1) - gen::pow2<T>(-6);
      how = "the moments made distinct by 2^-6";
    }
    if (attitude_special) {
      n.x0.O = turned_off(r.x0.O);
      how += " and the attitude turned 1/4 rad in space, away from " + where;
    }
    const std::string e = experiment(in, c, n, measured);
    if (e == "passes")
      return "  cause, by experiment: " + how + " (the same units and time), the step converges (" + measured +
             "); at the special state it does not: the step branches at this special state (a 'fast path' for steady "
             "rotation about a principal axis, a branch for equal moments)\n";
    out += "    with " + how + " it " + std::string(e == "fails" ? "fails as well" : "could not be run") + " (" +
           measured + "): the special state is not the cause\n";
  }
  return "  cause not identified; tried at this case:\n" +
         (out.empty() ? std::string("    nothing: a generic state in the drawn units, whose field the step follows\n")
                      : out);
}

template <class T>
void integrator_converges_in_every_regime(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const RigidBodyRegime<T> r = draw_rigid_body_regime<T>();
  const ConvergenceRun run = convergence_run(in, r);
  const std::string inputs = "    regime: " + regime_name(r) + "\n" + named("I", r.I) + named("Pi", r.x0.Pi) +
                             named("O", r.x0.O) + "    t = " + fmt("%.17g", run.t) + ", " + run.ladder + "\n";
  try {
    stepfield::explaining_step(
        in, r.I,
        [&] {
          return std::vector<RigidBodyState<T>>{r.x0, flow_at_end(r)};
        },
        run.h_run,
        [&] {
          judge_convergence(in.name, c, ScalarInfo<T>::name, regime_name(r), run.hs, run.errs, run.floors, inputs, "");
        });
  } catch (rc::detail::CaseResult& failure) {
    // A cause only on an experiment at this case, run now that it failed, and only when the step's
    // field named none (one cause per failure).
    if (stepfield::explanation_named_cause()) throw;
    const std::string evidence = regime_evidence(in, r, c);
    if (!failure.description.empty() && failure.description.back() != '\n') failure.description += '\n';
    failure.description += evidence;
    throw;
  }
}

// Manakov's (M, O) in other frames and units (1. at the top of this file, for (2.34)). The drawn
// case has A = diag(a), n = 3..4 (the oracle's body). In three cases of four it is seen in the
// frame of a rotation R of R^n (exact in rationals, generators.hpp): A' = R A R^T is not diagonal,
// and M' = R M R^T, O' = R O R^T solve (2.34) and dO/dt = O Omega for A', since Omega' = R Omega R^T
// solves A' Omega' + Omega' A' = M'. In three cases of four M is also scaled by lambda = 2^k,
// k = -64..64, and the time by 1/lambda ((2.34) is homogeneous of degree 2 in M, Omega linear in
// M). A step that uses only A's diagonal (Omega_ij = M_ij / (a_i + a_j), right for a diagonal A
// only) or has a cut-off on |M| fails here; every other Manakov check draws diagonal A and
// |M_ij| >= 1/8.
template <class T>
struct ManakovFrame {
  std::vector<T> a;
  ManakovState<T> x0;  // in the drawn frame, A = diag(a)
  MatX<T> R;           // the frame (the identity: not rotated)
  T lambda = T(1);     // the scale of M (1: not scaled)

  // A state of the drawn problem seen in the frame, in the scaled units.
  ManakovState<T> seen(const ManakovState<T>& x) const {
    const MatX<T> M = (R * x.M * R.transpose()).eval();
    return {((M - M.transpose()) * (lambda / T(2))).eval(), (R * x.O * R.transpose()).eval()};
  }
  MatX<T> A() const {
    const MatX<T> B = (R * dyn::diag_of(a) * R.transpose()).eval();
    return ((B + B.transpose()) / T(2)).eval();
  }
  std::string name() const {
    return std::string(R.isIdentity(T(0)) ? "A diagonal" : "A = R diag(a) R^T not diagonal") +
           (lambda == T(1) ? "" : ", M scaled by " + to_string_full(lambda) + " and time by its inverse");
  }
};

// A convergence run of a Manakov frame: the error at t = 1 / lambda for h = t/8 ... t/64.
template <class T>
ConvergenceRun manakov_convergence_run(const Integrator<T>& in, const ManakovFrame<T>& f) {
  const int n = static_cast<int>(f.a.size());
  const MatX<T> A = f.A();
  const ManakovState<T> x0 = f.seen(f.x0);
  const ManakovState<T> exact = f.seen(dyn::oracle_manakov(f.a, f.x0, {T(1)}).front());
  const T t_end = T(1) / f.lambda;
  const T size = norm_inf(x0.M);
  ConvergenceRun run;
  for (int N : {8, 16, 32, 64}) {
    const T h = t_end / T(N);
    const ManakovState<T> x = run_steps(in, A, x0, h, N);
    run.hs.push_back(1.0 / N);
    run.h_run.push_back(to_double(h));
    run.errs.push_back(
        to_double(std::max(T(max_abs((x.M - exact.M).eval()) / size), T(max_abs((x.O - exact.O).eval())))));
    run.floors.push_back(16.0 * step_eps_double<T>() * N * n);
  }
  return run;
}

// A failure in a scaled or rotated frame, by experiment at the failing case: unscaled first (if
// that passes, the defect depends on the units), then in the body's own principal frame, A
// diagonal, at the same scale (if that passes, the step is right only for a diagonal A).
template <class T>
std::string manakov_frame_evidence(const Integrator<T>& in, const ManakovFrame<T>& f, const IntegratorClaims& c) {
  std::string out, measured;
  if (f.lambda != T(1)) {
    ManakovFrame<T> u = f;
    u.lambda = T(1);
    const std::string e = experiment(
        c, [&] { return manakov_convergence_run(in, u); }, measured);
    if (e == "passes")
      return "  cause, by experiment: the same case unscaled converges (" + measured +
             "); scaled it does not: the "
             "defect depends on the units (a cut-off on |M|, an absolute tolerance); make them relative to |M|\n";
    out += "    the same case unscaled " + std::string(e == "fails" ? "fails as well" : "could not be run") + " (" +
           measured + "): the units are not the cause\n";
  }
  if (!f.R.isIdentity(T(0))) {
    ManakovFrame<T> d = f;
    d.R = MatX<T>::Identity(d.R.rows(), d.R.cols());
    const std::string e = experiment(
        c, [&] { return manakov_convergence_run(in, d); }, measured);
    if (e == "passes")
      return "  cause, by experiment: the same body in its principal frame (A diagonal) converges (" + measured +
             "); with A = R diag(a) R^T not diagonal it does not: the step is right only for a diagonal A (Omega_ij = "
             "M_ij / (A_ii + A_jj), or only A's diagonal read); Omega must solve A Omega + Omega A = M (2.34) for the "
             "whole A\n";
    out += "    in the principal frame (A diagonal) it " +
           std::string(e == "fails" ? "fails as well" : "could not be run") + " (" + measured +
           "): the frame is not the cause\n";
  }
  return "  cause not identified; tried at this case:\n" +
         (out.empty() ? std::string("    nothing: A diagonal, in the drawn units\n") : out);
}

template <class T>
void manakov_integrator_converges_in_every_frame(const Subject<T>&, const Integrator<T>& in,
                                                 const IntegratorClaims& c) {
  ManakovFrame<T> f;
  const int n = dyn::pick<T>(gen::uniform(3, 5), "n");
  f.a = dyn::draw_generic_manakov_a<T>(n);
  f.x0 = ManakovState<T>{dyn::draw_generic_skew<T>(n), dyn::pick<T>(gen::rotation<T>(n))};
  const bool rotated = dyn::pick<T>(gen::uniform(0, 4), "rotated frame (0: no)") != 0;
  f.R = rotated ? dyn::pick<T>(gen::rotation<T>(n), "R (A = R diag(a) R^T)") : MatX<T>::Identity(n, n);
  f.lambda = dyn::pick<T>(gen::motion_scale<T>(3, 4), "lambda (M scaled by it)");
  f.lambda = within_domain<T>(f.lambda, stepguard::rate_of(f.A(), ManakovState<T>{f.x0.M, f.x0.O}),
                              to_double(T(norm_inf(f.x0.M))), 1.0 / 64);  // inside the declared domain
  const MatX<T> A = f.A();
  const ManakovState<T> x0 = f.seen(f.x0);
  const ManakovState<T> exact = f.seen(dyn::oracle_manakov(f.a, f.x0, {T(1)}).front());
  const ConvergenceRun run = manakov_convergence_run(in, f);
  const std::string inputs = named("A", A) + named("M", x0.M) + named("O", x0.O) +
                             "    t = " + to_string_full(T(T(1) / f.lambda)) + ", h = t/8 ... t/64\n";
  try {
    stepfield::explaining_manakov_step(
        in, A,
        [&] {
          return std::vector<ManakovState<T>>{x0, exact};
        },
        [&] {
          judge_convergence(in.name, c, ScalarInfo<T>::name, "Manakov, n = " + std::to_string(n) + ", " + f.name(),
                            run.hs, run.errs, run.floors, inputs, "");
        });
  } catch (rc::detail::CaseResult& failure) {
    const std::string evidence = manakov_frame_evidence(in, f, c);
    if (!failure.description.empty() && failure.description.back() != '\n') failure.description += '\n';
    failure.description += evidence;
    throw;
  }
}

// The 50-digit floor (see the top of this file). Generic state, one step of h = 2^-40; the error
// relative to the state's size must be below 2^-60 (~8.7e-19): a first-order method's local
// error is ~C 2^-80 with C of the size of |Omega|^2 <= 64 here, and double round-off is 2^-53.
// The case of either kind is the local order's (draw_local_case); the rigid body's failure names
// its cause (probes_floor).
template <class Kind, class T>
void floor_claim(const Integrator<T>& in, const IntegratorClaims& c) {
  using State = typename Kind::template State<T>;
  const auto m = Kind::template draw_local_case<T>();
  const T h = gen::pow2<T>(-40);
  const State exact = Kind::oracle_at(m, {h}).front();
  const State step = Kind::step(in, m, m.x0, h);
  const T err = relative_distance(step, exact, Kind::momentum_size(m));
  const T bound = gen::pow2<T>(-60);
  // "computed in double" is said only on its evidence, the step's own vector field
  // agreeing with (3.8) and (2.10) to 50 digits while its error stalls; a wrong field is named instead.
  std::string cause;
  if constexpr (Kind::probes_floor) {
    if (!(err <= bound)) {
      // First what the step does on the variable that shows it (a precision below 50 digits
      // measured as such, a step that does not reduce to the identity), then its field.
      const std::string seen = stepfield::explain_rigid_body_step(in, m.I, std::vector<State>{m.x0}, {to_double(h)});
      const bool field_right = seen.find("your step's vector field is right") != std::string::npos;
      // Field right and no precision below 50 digits measured (explain_rigid_body_step tries that
      // first): nothing confirms a cause, and none is named.
      cause = field_right ? "the step's own vector field agrees with (3.8) and (2.10) to 50 digits (" + seen +
                                "), yet one step errs by far more than its truncation; the probe of the step's "
                                "precision did not find it computing below 50 digits: cause not identified"
                          : seen;
    }
  }
  const std::string one_step = in.name + ": one " + Kind::step_words + "step of h = 2^-40 in 50 digits";
  record_claim_finding("order", c.order > 0, err <= bound,
                       one_step + " errs by " + to_string_full(err) +
                           " of the state's size (at most 2^-60 for a 50-digit step of any order)",
                       err <= bound ? std::string() : "computed below 50 digits");
  // Failing, the cause leads: the first line is what every summary shows (Manakov's, without a
  // probe, keeps its passing words).
  require(err <= bound || !Kind::probes_floor ? one_step + " is accurate far below double round-off"
                                              : one_step + " is not accurate to 50 digits: " + cause,
          err <= bound,
          "the error of the step is " + to_string_full(err) +
              " of the state's size, where any method of order >= 1 has at most ~1e-24" +
              Kind::floor_bound_words(bound) + "\n  inputs, by the notes' names:\n" + Kind::case_names(m) +
              "    h = 2^-40\n");
}

template <class T>
void integrator_50_digit_floor(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  floor_claim<RigidBodyKind>(in, c);
}

// Manakov's (M, O), n = 3..4 (the oracle's cost grows like n^4), A = diag(a) (the oracle's body).
template <class T>
void manakov_integrator_50_digit_floor(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  floor_claim<ManakovKind>(in, c);
}

// The local order (3. at the top of this file).

// The exponents k of h = c 2^-k t_s, largest step first. In 50 digits 8, 12, ..., 28 for every
// order (a fourth-order local error at 2^-28 is ~2^-140 ~ 1e-42, far above round-off). In double
// the smallest step is where an error ~h^(p+1) is still ~2^-40 (~1e-12) of the state, at most
// 2^-10, and five steps up from there, never larger than 2^-3: second order (and no claim)
// 2^-6 ... 2^-10, fourth order 2^-4 ... 2^-8. A method of order 6 or more leaves fewer than three
// points above round-off in double; its slope is then measured in 50 digits only (noted).
template <class T>
std::vector<int> local_order_exponents(double claimed_order) {
  if constexpr (!std::is_same_v<T, double>) {
    return {8, 12, 16, 20, 24, 28};
  } else {
    const int p = std::max(1, static_cast<int>(claimed_order));
    const int last = std::min(10, 40 / (p + 1));
    std::vector<int> ks;
    for (int k = std::max(3, last - 4); k <= last; ++k) ks.push_back(k);
    return ks;
  }
}

// c = j / (3 2^6), j in [96, 192) not a multiple of 3: in [1/2, 1), exact in no binary format.
template <class T>
T draw_step_factor() {
  int j = dyn::pick<T>(gen::uniform(96, 192), "j (the step factor c = j / 192)");
  if (j % 3 == 0) ++j;
  return T(j) / T(3 * 64);
}

// One step's error is a few eps per operation of the step (an implicit solve converged to a few
// eps included), relative to the state: points at or below 2^10 eps are round-off, not truncation.
// A step judged at a coarser precision than its scalar (computed in float) has no such solves of a
// student's fixed tolerance to allow for (1e-12 is 4500 double eps, and nothing in float): its
// floor is 16 of its eps, where rounding its input and its arithmetic leave less than one (measured
// for the float midpoint rule and RK4 of examples/integrators/float_cases.hpp: 0.2-0.4 eps).
template <class T>
double local_error_floor() {
  return (current_step_precision().coarser_than<T>() ? 16.0 : 1024.0) * step_eps_double<T>();
}

// The steps of the local-order check, h = c 2^-k t_s for these k. A step judged at a coarser
// precision than its scalar reaches its floor at larger steps: h |Omega| from c/4 down by factors of
// sqrt(2) to c 2^-12 (the plateau rule ends the fit where the error meets the floor), as
// (k, halves) pairs: 2^-(k + halves/2).
template <class T>
std::vector<T> local_order_steps(double claimed_order, const T& factor, const T& t_s) {
  std::vector<T> steps;
  if (current_step_precision().coarser_than<T>()) {
    const T root2 = T(1.4142135623730951);  // a non-dyadic factor changes nothing: c is non-dyadic already
    T h = factor * gen::pow2<T>(-2) * t_s;
    for (int j = 0; j <= 20; ++j, h /= root2) steps.push_back(h);
  } else {
    for (int k : local_order_exponents<T>(claimed_order)) steps.push_back(T(factor * gen::pow2<T>(-k) * t_s));
  }
  return steps;
}

// Judges the slope of errs (one step, relative to the state's size) against hs (decreasing).
inline void judge_local_order(const std::string& integrator, const IntegratorClaims& c, const std::string& problem,
                              const char* scalar, const std::vector<double>& hs, const std::vector<double>& errs,
                              double floor, const std::string& inputs) {
  // The steps are relative to the motion's time scale t_s = 1 / |Omega|: h |Omega|, not h.
  const auto fit = conv::loglog_slope(hs, errs, std::vector<double>(hs.size(), floor), "h |Omega|");
  if (fit.used < 3) {
    // At round-off already at the larger steps (exact for this state, or of a high order), or not
    // decreasing at all.
    const bool converged = errs.back() <= floor;
    if (!converged)
      record_claim_finding("order", c.order > 0, false,
                           integrator + ": the error of one step" + problem + " does not go to 0 (" + scalar +
                               "): " + conv::stall_words(errs, floor),
                           "does not converge");
    require(integrator + ": the error of one step" + problem + " goes to 0 as h -> 0", converged,
            conv::stall_words(errs, floor) + "\n" + fit.table + "  inputs, by the notes' names:\n" + inputs);
    // At round-off at every step: exact for this state, no order contradicted. One or two steps
    // above the floor and the rest on it: the order cannot be read at this precision, said so; no
    // evidence either way (the order rests on the checks at a fixed time, which say NOT VERIFIED when
    // they cannot measure it).
    const bool exact = conv::at_roundoff_everywhere(errs, std::vector<double>(hs.size(), floor));
    // At a precision coarser than the scalar (a float step) one step's error of a high order stands
    // above that precision's round-off at one or two steps only (RK4 in float: only at h |Omega| >= 0.35,
    // where it is not yet h^5): not measurable here, and no evidence either way. The order is then
    // decided by the checks at a fixed time (integrator_order, integrator_converges_in_every_regime),
    // which measure it where truncation stands above the floor; said so, not counted against the claim.
    const bool coarse = current_step_precision().coarser_than<double>();
    record_note(integrator + ": the error of one step" + problem +
                " is at round-off from h = " + fmt("%.3g", hs[std::max(0, fit.used)]) +
                " on: fewer than three step sizes to measure its slope in " + scalar);
    judge_claim("order", c.order > 0, true,
                integrator + ": the error of one step" + problem +
                    (exact ? " is at round-off (" + std::string(scalar) + "): no order contradicted"
                           : " stands above the round-off floor at fewer than three step sizes (" +
                                 std::string(scalar) + "): order not measurable at this precision"),
                exact    ? std::string()
                : coarse ? "not measurable at " + current_step_precision().name +
                               "'s precision (one step's error stands above its round-off at fewer than three step "
                               "sizes): the order rests on the checks at a fixed time"
                         : "not measurable (fewer than three step sizes above round-off)",
                true);
    return;
  }
  const double needed = c.order > 0 ? c.order + 1 - 0.1 : 1.9;
  const bool holds = fit.slope >= needed;
  // Said only when the step's own field names no cause (support/step_field.hpp).
  // What to look for, by the slope measured: an error proportional to h is the mark of a slightly
  // wrong h; one that stops shrinking, of an iteration stopped at a fixed tolerance; other slopes
  // suggest neither.
  if (!holds && std::abs(fit.slope - 1) <= 0.2)
    stepfield::pending_advice() =
        "an error proportional to h at small steps is a step taken with a slightly wrong h (h stored in a float, a "
        "time step rescaled by a constant near 1, h rounded before use)";
  else if (!holds && fit.slope < 0.5)
    stepfield::pending_advice() = "an error that stops shrinking is an iteration stopped at a fixed tolerance";
  showing_inputs([&] { return inputs + "  the error of one step against h:\n" + fit.table; },
                 [&] {
                   judge_claim("order", c.order > 0, holds,
                               integrator + fmt(": the error of one step is ~ h^%.3f", fit.slope) + problem +
                                   (c.order > 0 ? fmt(", where order %g needs h^%g", c.order, c.order + 1)
                                                : std::string(", where any convergent method needs h^2")) +
                                   " (" + scalar + ")",
                               holds ? std::string() : fmt("one step's error ~ h^%.2f", fit.slope) + problem);
                 });
  require(integrator + ": the error of one step" + problem + " shrinks like h^" + fmt("%.1f", needed) + " or faster" +
              (c.order > 0 ? fmt(" (claimed order %g)", c.order) : std::string(" (any convergent method)")),
          holds, fmt("measured slope %.4f\n", fit.slope) + fit.table + "  inputs, by the notes' names:\n" + inputs);
}

// The local order of either kind (3. at the top of this file): the case, the time scale, the
// state's size, the floor and the words of the kind's trait (support/step_kind.hpp); the step
// factor is drawn after the case.
template <class Kind, class T>
void local_order_claim(const Integrator<T>& in, const IntegratorClaims& c) {
  using State = typename Kind::template State<T>;
  const auto m = Kind::template draw_local_case<T>();
  const T factor = draw_step_factor<T>();
  const T t_s = Kind::local_time_scale(m);
  std::vector<T> steps = local_order_steps<T>(c.order, factor, t_s);
  // Not below the smallest step the integrator declares it takes (its domain).
  std::erase_if(steps, [](const T& h) { return to_double(h) < current_step_domain().min_h; });
  // The oracle's times must increase; the steps decrease.
  std::vector<T> times(steps.rbegin(), steps.rend());
  std::vector<State> exact = Kind::oracle_at(m, times);
  std::reverse(exact.begin(), exact.end());
  const T size = Kind::local_size(m);
  std::vector<double> hs, errs, h_run;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    hs.push_back(Kind::local_h(steps[i], t_s));
    h_run.push_back(to_double(steps[i]));
    errs.push_back(to_double(relative_distance(Kind::step(in, m, m.x0, steps[i]), exact[i], size)));
  }
  Kind::explaining(
      in, m, [&] { return std::vector<State>{m.x0}; }, h_run,
      [&] {
        judge_local_order(in.name, c, Kind::local_where(m), ScalarInfo<T>::name, hs, errs,
                          Kind::local_floor(local_error_floor<T>(), m), Kind::local_inputs(m, factor, t_s));
      });
}

template <class T>
void integrator_local_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  local_order_claim<RigidBodyKind>(in, c);
}

// 4. at the top of this file: the exponents j of the turns h |Omega| = 2^-j, from 2^-10 down to two
// bits above the judged precision (at most 2^-58).
template <class T>
std::vector<int> small_turn_exponents() {
  const int bits = static_cast<int>(std::lround(-std::log2(step_eps_double<T>())));
  const int last = std::min(bits - 2, 58);
  std::vector<int> js;
  for (int j = 10; j < last; j += 4) js.push_back(j);
  js.push_back(last);
  return js;
}

template <class T>
void integrator_small_turns(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  const Vec3<T> I = dyn::draw_generic_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_generic_momentum<T>(), dyn::draw_attitude<T>()};
  const T rate = max_abs(Vec3<T>(x0.Pi.cwiseQuotient(I)));
  const T size = norm_inf(x0.Pi);
  constexpr int kSteps = 1024;
  const std::string inputs = named("I", I) + named("Pi", x0.Pi) + named("O", x0.O) +
                             "    h |Omega| = 2^-j, 1024 steps each, |Omega| = " + to_string_full(rate) + "\n";
  std::string table;
  int first_stuck = 0;  // the largest turn (smallest j) at which the state does not follow the flow
  double stuck_share = 0;
  std::vector<double> h_run;
  for (int j : small_turn_exponents<T>()) {
    const T h = T(gen::pow2<T>(-j) / rate);
    if (to_double(h) < current_step_domain().min_h) break;  // not below a declared smallest step
    h_run.push_back(to_double(h));
    auto steps = runs::rigid_body_steps(in, I, x0, h, kSteps);
    RigidBodyState<T> x = x0;
    for (int n = 0; n < kSteps; ++n) x = steps.next();
    const RigidBodyState<T> flow = dyn::oracle_rigid_body(I, x0, {T(h * T(kSteps))}).front();
    const T moved = relative_distance(flow, x0, size), off = relative_distance(x, flow, size);
    const double share = to_double(T(off / moved));
    table += fmt("    h |Omega| = 2^-%.0f: the flow moves the state by %.3g, the step leaves it %.3g from the flow", j,
                 to_double(moved), to_double(off)) +
             fmt(" (%.3g of the move)\n", share);
    if (!(share <= 0.5) && first_stuck == 0) first_stuck = j, stuck_share = share;
  }
  stepfield::explaining_step(
      in, I, [&] { return std::vector<RigidBodyState<T>>{x0}; }, h_run,
      [&] {
        showing_inputs(
            [&] { return inputs + table; },
            [&] {
              const bool holds = first_stuck == 0;
              judge_claim("order", c.order > 0, holds,
                          in.name +
                              (holds ? ": the state follows the flow when one step turns it by 2^-10 "
                                       "down to 2^-" +
                                           std::to_string(small_turn_exponents<T>().back()) + " rad"
                                     : ": the state does not follow the flow when one step turns it by 2^-" +
                                           std::to_string(first_stuck) +
                                           fmt(" rad: after 1024 steps it is %.3g of the flow's move "
                                               "away from the flow (a skip of small turns leaves all of "
                                               "it)",
                                               stuck_share)) +
                              judged_tag<T>(),
                          holds ? std::string()
                                : "does not turn for turns of 2^-" + std::to_string(first_stuck) + " rad a step");
              require(in.name + ": the state follows the flow at small turns per step (h |Omega| down to 2^-" +
                          std::to_string(small_turn_exponents<T>().back()) + ")",
                      holds, table + "  inputs, by the notes' names:\n" + inputs);
            });
      });
}

// Manakov's (M, O), n = 3..4, A = diag(a), |M_ij| <= 1 (the time scale 1).
template <class T>
void manakov_integrator_local_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  local_order_claim<ManakovKind>(in, c);
}

}  // namespace

GM_PROPERTY(integrator_local_order, integrator_scalars,
            {.spec = "s3.euler-flow",
             .title = "the error of one step from a generic state shrinks like h^(p+1) down to h ~ 2^-10 (double) and "
                      "2^-28 (50 digits), for steps that are not dyadic (a step taken with a slightly wrong h fails)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"midpoint_step_size_in_float"},
             .cases = {.d = 10, .mp = 3, .q = 0},
             .step = StepKind::RigidBody,
             .judges = {"order"}});

GM_PROPERTY(integrator_small_turns, integrator_scalars,
            {.spec = "s2.reconstruction",
             .title = "the state follows the flow of (2.20) when one step turns it by 2^-10 rad down to two bits above "
                      "the step's precision (a step that skips small rotations fails)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"midpoint_skips_small_turns"},
             .cases = {.d = 3, .mp = 1, .q = 0},
             .step = StepKind::RigidBody,
             .judges = {"order"}});

GM_PROPERTY(manakov_integrator_local_order, integrator_scalars,
            {.spec = "s2.manakov-flow",
             .title = "the error of one Manakov step shrinks like h^(p+1) down to h ~ 2^-10 (double) and 2^-28 "
                      "(50 digits), for steps that are not dyadic",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"midpoint_step_size_in_float"},
             .cases = {.d = 5, .mp = 2, .q = 0},
             .step = StepKind::Manakov,
             .judges = {"order"}});

GM_PROPERTY(integrator_converges_in_every_regime, integrator_scalars,
            {.spec = "s3.euler-flow",
             .title = "the step converges to the flow of (2.20) at its claimed order (at least order 1 if none) at "
                      "relative equilibria and near them, for symmetric and spherical tops, at every scale",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"principal_axis_fast_path", "symmetric_top_branch", "midpoint_at_rest_below_1e_10"},
             .cases = {.d = 60, .mp = 20, .q = 0},
             .step = StepKind::RigidBody,
             .judges = {"order"}});

GM_PROPERTY(manakov_integrator_converges_in_every_frame, integrator_scalars,
            {.spec = "s2.manakov-flow",
             .title = "the Manakov step converges to the flow of (2.34) at its claimed order (at least order 1 if "
                      "none) for a non-diagonal A (a diagonal body in a rotated frame) and at every scale of M",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"manakov_midpoint_diagonal_A_only", "midpoint_at_rest_below_1e_10"},
             .cases = {.d = 60, .mp = 12, .q = 0},
             .step = StepKind::Manakov,
             .judges = {"order"}});

GM_PROPERTY(integrator_50_digit_floor, integrator_mp50_scalars,
            {.spec = "s3.euler-flow",
             .title = "in 50 digits one step of h = 2^-40 is accurate far below double round-off (no part of the "
                      "step is computed in double)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"rk4_double_inside"},
             .cases = {.d = 0, .mp = 5, .q = 0},
             .step = StepKind::RigidBody,
             .judges = {"order"}});

GM_PROPERTY(manakov_integrator_50_digit_floor, integrator_mp50_scalars,
            {.spec = "s2.manakov-flow",
             .title = "in 50 digits one Manakov step of h = 2^-40 is accurate far below double round-off",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"rk4_double_inside"},
             .cases = {.d = 0, .mp = 3, .q = 0},
             .step = StepKind::Manakov,
             .judges = {"order"}});

}  // namespace properties_integrator_regimes
}  // namespace gm
