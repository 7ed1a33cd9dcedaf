// The vector field a step follows (DESIGN.md "An integrator explains itself"): a
// consistent one-step method satisfies step(x, h) = x + h F(x) + O(h^2), and F is the equation it
// integrates. D(h) = (step(x, h) - x) / h is computed at h = 2^-k, k = kFirst..kFirst + 5, and
// extrapolated to h = 0 (Neville, in powers of h), for the body part (dPi/dt) and for the attitude
// (Omega_step = vee(O^T dO/dt), the body angular velocity the step turns O with). Compared with the
// notes' (3.8) dPi/dt = Pi x I^-1 Pi and (2.10), (3.5) dO/dt = O Omega_hat, Omega = I^-1 Pi at the
// failing state, it separates the classic causes of a failed claim: a wrong equation (a sign, Omega
// for Pi, the inertia applied in the wrong frame, the attitude turned from the wrong side) from a
// right equation used at the wrong order (the field right, the claim still false), and says so in
// the notes' terms. Every statement carries the vectors it compares.
//
// Accuracy: D(h) - F = O(h); round-off is eps / h. With h down to 2^-13 in double the extrapolated
// field is good to about 1e-10 relative, in 50 digits (h down to 2^-40) to far below any difference
// named here; differences are called "agrees" below kAgree (relative to |F| and |Pi|).
#pragma once

#include "core/subject.hpp"
#include "properties/integrators/support/step_probe.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/show.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace gm::stepfield {

template <class T>
struct Field {
  Vec3<T> Pi_dot;   // dPi/dt the step follows
  Vec3<T> Omega;    // the body angular velocity it turns O with
  T spread = T(0);  // the last two extrapolated estimates' difference: how well the field is known
};

// Neville's extrapolation to h = 0 of values v[k] at h[k] (polynomial in h).
template <class T, class V>
V extrapolate_to_zero(const std::vector<T>& h, std::vector<V> v, T* spread) {
  const std::size_t n = v.size();
  V previous = v.front();
  for (std::size_t m = 1; m < n; ++m) {
    for (std::size_t k = n - 1; k >= m; --k) {
      v[k] = (v[k] * h[k - m] - v[k - 1] * h[k]) / (h[k - m] - h[k]);
      if (k == m) break;
    }
    if (m + 1 == n) previous = v[m - 1];
  }
  if (spread) *spread = max_abs(V(v[n - 1] - previous));
  return v[n - 1];
}

// The first exponent of the steps, from the precision the step is judged at (step_probe.hpp: 8 in
// double, 3 in float, 24 in 50 digits, where far smaller steps cost nothing in accuracy).
template <class T>
int first_exponent() {
  return stepprobe::field_first_exponent<T>();
}

// The first of the six steps: h0 = 2^-first_exponent against the motion's own time scale 1 / rate,
// by powers of two. A state scaled by lambda turns lambda times faster: at h = 2^-8 a motion scaled
// by 2^18 turns many times within one step, and the extrapolated "field" is nothing the step
// follows; a motion scaled by 2^-30 moves so little in 2^-13 that (step(x, h) - x)/h is round-off.
// Motions with rate in [1/64, 2] (the unscaled states of every check) keep h0.
template <class T>
T first_step(const T& rate) {
  T h(1);
  for (int k = 0; k < first_exponent<T>(); ++k) h /= T(2);
  const T h0 = h;
  if (!(rate > T(0))) return h;  // at rest (or not a number): nothing to scale by
  while (h * rate > T(2) * h0) h /= T(2);
  while (h * rate < h0 / T(64)) h *= T(2);
  return h;
}

// step(x, h) - x divided by h at six steps halving from first_step(rate) (above: small
// against the motion's time scale 1 / rate), extrapolated to h = 0. `difference(h)` returns
// step(x, h) - x as one matrix.
template <class T, class Difference>
MatX<T> rate_at_zero(Difference&& difference, T* spread, const T& rate = T(1)) {
  std::vector<T> hs;
  std::vector<MatX<T>> d;
  // The six steps stay at or above a declared smallest step: less accurate, never outside.
  T h = at_least_min_h<T>(T(first_step<T>(rate) / T(32))) * T(32);
  for (int k = 0; k < 6; ++k, h /= T(2)) {
    hs.push_back(h);
    d.push_back(MatX<T>(difference(h) / h));
  }
  return extrapolate_to_zero(hs, d, spread);
}

template <class T>
Field<T> rigid_body_field(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x) {
  Field<T> f;
  const MatX<T> D = rate_at_zero<T>(
      [&](const T& h) {
        const RigidBodyState<T> y = in.rigid_body_step(I, x, h);
        // h O^-1 dO/dt: h Omega_hat for (2.10). O^-1, not O^T: a step that lets O drift off SO(3)
        // (explicit Euler after 64 steps) still turns it with (2.10) exactly.
        const Mat3<T> W = (x.O.inverse() * (y.O - x.O)).eval();
        MatX<T> d(6, 1);
        d.topRows(3) = y.Pi - x.Pi;
        d.bottomRows(3) << (W(2, 1) - W(1, 2)) / T(2), (W(0, 2) - W(2, 0)) / T(2), (W(1, 0) - W(0, 1)) / T(2);
        return d;
      },
      &f.spread, T(max_abs(Vec3<T>(x.Pi.cwiseQuotient(I)))));  // the rate: |Omega| of (3.5)
  f.Pi_dot = D.topRows(3);
  f.Omega = D.bottomRows(3);
  return f;
}

// How close two vectors must be to "agree": relative to the size of what is compared, at the
// precision the step is judged at (step_probe.hpp).
template <class T>
T agree_tolerance() {
  return stepprobe::field_agree_tolerance<T>();
}

template <class T>
bool agrees(const Vec3<T>& a, const Vec3<T>& b, const T& size) {
  return max_abs(Vec3<T>(a - b)) <= agree_tolerance<T>() * size;
}

template <class T>
std::string v(const Vec3<T>& x) {
  return show_value(Vec3<double>(to_double(x(0)), to_double(x(1)), to_double(x(2))));
}

struct Diagnosis {
  bool field_right = false;  // both parts agree with the notes
  std::string text;          // the explanation, in the notes' terms (one or two sentences each)
};

// The step's field at x against (3.8) and (2.10)/(3.5).
template <class T>
Diagnosis diagnose(const Field<T>& f, const Vec3<T>& I, const RigidBodyState<T>& x) {
  const Vec3<T> Omega = x.Pi.cwiseQuotient(I);    // (3.5)
  const Vec3<T> rhs = truth::cross(x.Pi, Omega);  // (3.8)
  const T size_pi = max_abs(rhs) + max_abs(x.Pi) * max_abs(Omega);
  const T size_om = max_abs(Omega);
  Diagnosis d;
  std::string pi_text, om_text;
  const bool pi_ok = agrees(f.Pi_dot, rhs, size_pi);
  const bool om_ok = agrees(f.Omega, Omega, size_om);
  if (!pi_ok) {
    const Vec3<T> I_Pi = I.cwiseProduct(x.Pi);
    if (agrees(f.Pi_dot, Vec3<T>(-rhs), size_pi))
      pi_text = "your step follows dPi/dt = Omega x Pi = " + v(f.Pi_dot) + "; (3.8) is Pi x Omega = " + v(rhs) +
                ": the cross product is reversed";
    else if (agrees(f.Pi_dot, truth::cross(x.Pi, I_Pi), size_pi + max_abs(x.Pi) * max_abs(I_Pi)))
      pi_text = "your step follows dPi/dt = Pi x (I Pi) = " + v(f.Pi_dot) +
                "; (3.8) is Pi x Omega with Omega = I^-1 Pi, " + v(rhs) +
                ": the inertia is applied instead of its inverse";
    else if (max_abs(f.Pi_dot) <= agree_tolerance<T>() * size_pi)
      pi_text = "your step leaves Pi unchanged (dPi/dt = 0); (3.8) gives dPi/dt = Pi x Omega = " + v(rhs);
    else
      pi_text = "your step follows dPi/dt = " + v(f.Pi_dot) + "; (3.8) gives Pi x Omega = " + v(rhs);
  }
  if (!om_ok) {
    const Vec3<T> space_with_body_inertia = Vec3<T>(x.O.transpose() * (x.O * x.Pi).cwiseQuotient(I));
    if (agrees(f.Omega, Vec3<T>(-Omega), size_om))
      om_text = "your step turns the body with Omega = " + v(f.Omega) +
                ", the opposite of (3.5)'s I^-1 Pi = " + v(Omega) +
                ": (2.10) is dO/dt = O Omega_hat, not O Omega_hat^T";
    else if (agrees(f.Omega, space_with_body_inertia, size_om + max_abs(space_with_body_inertia)))
      om_text = "your step turns the body with Omega = " + v(f.Omega) + " where (3.5) gives I^-1 Pi = " + v(Omega) +
                ": it applies the body's I^-1 to the spatial momentum O Pi (the inertia is not rotated into space, "
                "I_space = O I O^T, Remark 2.1); they agree only when I is spherical";
    else if (agrees(f.Omega, Vec3<T>(x.O.transpose() * Omega), size_om))
      om_text =
          "your step turns the body with dO/dt = Omega_hat O (body angular velocity applied on the left, as if it "
          "were the spatial one); (2.10) is dO/dt = O Omega_hat, with Omega = I^-1 Pi = " +
          v(Omega);
    else
      om_text = "your step turns the body with Omega = vee(O^-1 dO/dt) = " + v(f.Omega) +
                " where (2.10) and (3.5) give " + "I^-1 Pi = " + v(Omega);
  }
  d.field_right = pi_ok && om_ok;
  if (d.field_right)
    d.text =
        "your step's vector field is right: it follows (3.8) and (2.10) (the extrapolated (step(x, h) - x)/h "
        "agrees with Pi x I^-1 Pi = " +
        v(rhs) + " and Omega = I^-1 Pi = " + v(Omega) +
        "): the equation is not "
        "the cause, and this reading identifies no other (the measurement is the evidence)";
  else
    d.text = pi_text + (pi_text.empty() || om_text.empty() ? "" : "; ") + om_text;
  return d;
}

// Whether the last explanation of a failure on this thread named a cause confirmed by its
// experiment (a wrong field, a cap, a guard on h, a step that does not reduce to the identity, a
// precision): then no other cause may follow it (the regimes' experiments, generic advice); false
// when the field was read right and named nothing.
inline bool& explanation_named_cause() {
  thread_local bool named = false;
  return named;
}

// What to look for when a failure's experiments confirm a fact but no cause ("the defect depends on
// the units": a cut-off or an absolute tolerance are the usual ones): set by a judge before it fails,
// said after the failure only when the explanation named no cause, labelled as not confirmed.
inline std::string& pending_advice() {
  thread_local std::string advice;
  return advice;
}

// Runs `judge` (a claim's verdict); when it fails, `explanation()` (the step's own equation, measured
// only then) leads the failure and the evidence of every false claim it recorded: a false claim
// explains itself in the claims table as well as in its FIRST FIX.
template <class Explain, class Judge>
void explaining_claims(Explain&& explanation, Judge&& judge) {
  // Findings are kept one per claim (record_claim_finding merges cases): those this judge recorded
  // or replaced are the ones whose evidence is new.
  std::vector<std::pair<std::string, std::string>> before;
  for (const auto& f : recorded_claims()) before.emplace_back(f.claim, f.evidence);
  const auto is_new = [&](const ClaimFinding& f) {
    return std::find(before.begin(), before.end(), std::make_pair(f.claim, f.evidence)) == before.end();
  };
  pending_advice().clear();
  try {
    judge();
    pending_advice().clear();
  } catch (rc::detail::CaseResult& r) {
    // The explanation calls the step again, at states and steps of its own: what it raises there
    // explains nothing (and is not this case's raise), and a call outside a declared domain is not
    // made by it on purpose.
    const auto raise = current_step_raise();
    std::string why;
    explanation_named_cause() = false;
    try {
      why = explanation();
    } catch (const std::exception& e) {
      why = std::string("the step's own equation could not be read: ") + e.what();
      explanation_named_cause() = false;
    }
    current_step_raise() = raise;
    const std::string advice = explanation_named_cause() || pending_advice().empty()
                                   ? std::string()
                                   : "what to look for (not confirmed): " + pending_advice();
    pending_advice().clear();
    for (auto& f : recorded_claims())
      if (f.claimed && !f.holds && is_new(f))
        f.evidence = why + "; measured: " + f.evidence + (advice.empty() ? "" : "; " + advice);
    r.description = why + "\n" + r.description + (advice.empty() ? "" : "\n  " + advice);
    throw;
  }
}

// A false claim explains itself: the vector field the step follows at the state where
// the claim was judged, against (3.8) and (2.10) (above), leads the failure and the
// claims table's evidence.
// The field is looked at in each of the states `states()` returns (only once the claim failed) and
// the first where it is wrong is named (a state with O = Id, where a shrunk case ends, hides an
// inertia applied in the wrong frame).
template <class T, class States, class Diagnose, class Judge>
void explaining_at(States&& states, Diagnose&& diagnose_at, Judge&& judge) {
  stepfield::explaining_claims(
      [&] {
        stepfield::Diagnosis d;
        for (const auto& x : states()) {
          d = diagnose_at(x);
          if (!d.field_right) break;
        }
        return "the step's own equation: " + d.text + judged_tag<T>();
      },
      judge);
}

// The same reading in the integrator's own variables, leading this one, for a step kept in a declared
// form (a quaternion, omega, ...: step_field_form.hpp).
template <class T>
Diagnosis in_declared_form(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x,
                           const Diagnosis& notes);

// What the rigid-body step does at the states `xs` (the first is the case's), in words:
// a precision below the scalar's, a step that does not reduce to the identity, one that returns its
// input below some h, a capped field (support/step_probe.hpp); only when none of these is found,
// its vector field against (3.8) and (2.10). Each is named only when its experiment at the failing
// input confirms it: "returns its input" only when the failing steps `hs` (in the units of xs; empty:
// not known) reach down to where the step does so; a cap only when the field at the failing state
// itself is (3.8) shrunk to a constant fraction or a constant size.
// (The failing step is tried at the state: T(failing_here) from a double is exact enough for that.)
template <class T>
std::string explain_rigid_body_step(const Integrator<T>& in, const Vec3<T>& I, const std::vector<RigidBodyState<T>>& xs,
                                    const std::vector<double>& hs = {}) {
  const RigidBodyState<T>& x0 = xs.front();
  // A step computing below the precision it is judged at (fewer digits than a float, or a float
  // nobody stated or detected) is read at its own: the field with steps whose round-off is small
  // there. Its round-off is named only once that field is right: a floor never explains an error far
  // above it (a missing term stays a missing term).
  const double precision = stepprobe::precision_of(in, I, x0);
  const std::string judged = judged_tag<T>();
  const double judged_eps = step_eps_double<T>();
  struct ReadAt {
    StepPrecision saved = current_step_precision();
    explicit ReadAt(double e) {
      if (e > 0) current_step_precision().eps = e, current_step_precision().name = "its own";
    }
    ~ReadAt() { current_step_precision() = saved; }
  } read_at(precision);
  // At each state, and at a generic attitude besides: O = Id, where a shrunk case ends, hides a
  // conversion of frames (O O^T Pi is Pi there).
  std::vector<RigidBodyState<T>> probed = xs;
  {
    const Vec3<T> a(T(1) / T(2), T(-1) / T(3), T(1) / T(4));
    const Mat3<T> A = truth::skew_of(a), Id = Mat3<T>::Identity();
    probed.push_back(RigidBodyState<T>{x0.Pi, Mat3<T>((Id - A / T(2)).inverse() * (Id + A / T(2)))});
    // ... and the same motion in units where |Omega| is about 1 (by a power of 2, exact): a step
    // that does nothing below some h shows it there, where the small steps are not all below it.
    T l(1);
    const T rate = stepprobe::rate_of(I, x0.Pi);
    while (rate * l > T(2)) l /= T(2);
    while (rate * l < T(1) / T(2)) l *= T(2);
    if (l != T(1)) probed.push_back(RigidBodyState<T>{Vec3<T>(x0.Pi * l), probed.back().O});
  }
  // The failing steps in the units of the k-th probed state (the last one is rescaled by l: the same
  // motion is run with steps h / l there).
  const double h_failing = hs.empty() ? 0.0 : *std::min_element(hs.begin(), hs.end());
  const double last_scale =
      probed.size() > xs.size() + 1 ? to_double(T(max_abs(probed.back().Pi) / max_abs(x0.Pi))) : 1.0;
  std::string guard_seen;  // a guard found below every failing step: evidence, not the cause
  for (std::size_t k = 0; k < probed.size(); ++k) {
    const auto& x = probed[k];
    const auto small = stepprobe::small_steps(in, I, x, precision);
    if (small.not_identity) {
      // In the integrator's own variables too, for a step kept in a declared form.
      const std::string own = in.form.is_notes()
                                  ? std::string()
                                  : "; " + in_declared_form(in, I, x, diagnose(rigid_body_field(in, I, x), I, x)).text;
      explanation_named_cause() = true;
      return small.not_identity_text + own + judged;
    }
    if (small.returns_input) {
      // The experiment: the step at this state with the smallest failing h returns its input.
      const double failing_here = h_failing / (k == xs.size() + 1 ? last_scale : 1.0);
      bool still = false;
      if (h_failing > 0) {
        const RigidBodyState<T> y = in.rigid_body_step(I, x, T(failing_here));
        still = returned_input(y, x);
      }
      explanation_named_cause() = still;
      if (still)
        return small.returns_input_text +
               fmt("; the failing runs use steps down to h = %.3g, where it returns its input too", failing_here) +
               judged;
      if (guard_seen.empty())
        guard_seen =
            "; besides, " + small.returns_input_text +
            (h_failing > 0
                 ? fmt(", but every failing step is larger (the smallest h = %.3g): not the cause here", failing_here)
                 : std::string(": the failing steps are not known here, so it is not named the cause"));
    }
  }
  stepfield::Diagnosis d;
  const RigidBodyState<T>* at = &x0;
  for (const auto& x : xs) {
    d = diagnose(rigid_body_field(in, I, x), I, x);
    if (!in.form.is_notes()) d = in_declared_form(in, I, x, d);  // the integrator's own variables lead
    at = &x;
    if (!d.field_right) break;
  }
  explanation_named_cause() = !d.field_right || precision > 0;
  if (!d.field_right) {
    const std::string cap =
        stepprobe::cap_of(I, *at, [&](const RigidBodyState<T>& y) { return rigid_body_field(in, I, y).Pi_dot; });
    if (!cap.empty()) return cap + judged;
  } else if (precision > 0) {
    return stepprobe::precision_words(precision, judged_eps) + judged;
  }
  return "the step's own equation: " + d.text + guard_seen + judged;
}

// The rigid body's explanation of a failed claim (explain_rigid_body_step, above); `hs` the steps of
// the judged runs, in the units of the states.
template <class T, class States, class Judge>
void explaining_step(const Integrator<T>& in, const Vec3<T>& I, States&& states, const std::vector<double>& hs,
                     Judge&& judge) {
  stepfield::explaining_claims([&] { return explain_rigid_body_step(in, I, states(), hs); }, judge);
}

}  // namespace gm::stepfield

#include "properties/integrators/support/step_field_form.hpp"
