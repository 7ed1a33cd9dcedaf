// What a failing step does, measured on the variable that shows it, before its vector
// field is read (step_field.hpp): the causes a field made of round-off or of a wrong wrapper would
// hide. At one state x of the rigid body, each on its own evidence:
//   1. precision: step(x + delta, h) - step(x, h) follows delta (the step is near the identity)
//      down to the precision the step computes in; below it the outputs stop following (equal, or
//      a whole unit of the step's last place apart). The smallest relative delta still followed is
//      the step's round-off: about 6e-8 for a step computed in float, 1.1e-16 in double. A step
//      computing below the scalar checked is named so ("your step computes in single precision"),
//      and no vector field is shown (it would be round-off over h);
//   2. the identity: |step(x, h) - x| -> 0 as h -> 0 (a consistent step moves x by about
//      h |F(x)|); a step that moves x by a fixed amount however small h is (a wrapper converting a
//      frame and back the wrong way) does not reduce to the identity, said first, with
//      |step(x, h) - x| at the smallest h, at the state it was measured at;
//   3. a step that returns its input exactly below some h (a "nothing to do" guard): the largest h
//      at which it does, and the h at which it moves;
//   4. a cap: the field of (3.8) is quadratic in Pi, F(lambda x) = lambda^2 F(x); a step whose
//      field is a constant fraction of (3.8) beyond some |Pi| ("a max angular velocity") is named
//      with the fraction and where it starts.
// Each probe is a few dozen calls of the step, made only once a claim has failed.
#pragma once

#include "core/declared_step.hpp"
#include "core/subject.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/pow2.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/show.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace gm::stepprobe {

using gm::pow2;  // 2^k exactly, in any scalar (pow2.hpp)

// |Omega| = max |Pi_i / I_i|, the motion's rate (at least 2^-40: a body at rest has none).
template <class T>
T rate_of(const Vec3<T>& I, const Vec3<T>& Pi) {
  const T r = max_abs(Vec3<T>(Pi.cwiseQuotient(I)));
  return r > pow2<T>(-40) ? r : pow2<T>(-40);
}

template <class T>
T moved(const RigidBodyState<T>& a, const RigidBodyState<T>& b, const T& size) {
  return std::max(T(max_abs(Vec3<T>(a.Pi - b.Pi)) / size), T(max_abs(Mat3<T>(a.O - b.O))));
}

// 1. The relative round-off the step computes with, when it is coarser than the precision it is
// judged at (properties/support/step_precision.hpp: a step stated or detected to compute in float is
// judged at float's, and computes at it): 0 when it follows every delta down to a few units of that
// precision's last place (no finding).
template <class T>
double precision_of(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x) {
  if (!(max_abs(x.Pi) > T(0))) return 0;
  const T h = at_least_min_h<T>(T(pow2<T>(-6) / rate_of(I, x.Pi)));
  const double followed = stepprecision::precision_followed<T>(in, I, x, h);
  // Followed to within 2^10 units of the judged precision's last place: the step computes at it.
  return followed > 1024 * step_eps_double<T>() ? followed : 0;
}

// What a precision coarser than the judged one explains, said once the step's field was read and
// found right: what looks like a truncation error is the step's own round-off.
inline std::string precision_words(double followed, double judged_eps) {
  std::string name;
  if (stepprecision::is_float_followed(followed))
    name = "single precision (float: round-off ~6e-8 relative)";
  else if (followed > 1e-18 && followed < 1e-13)
    name = "double precision (round-off ~1.1e-16 relative)";
  else
    name = fmt("about %.0f significant digits (round-off ~%.1g relative)", -std::log10(followed), followed);
  return "your step computes in " + name + ", below the " + fmt("%.2g", judged_eps) +
         " it is judged at: step(x + delta, h) - step(x, h) follows delta down to " + fmt("%.1g", followed) +
         " of |Pi| and no further, and its vector field is right (read with steps whose round-off is small at that "
         "precision), so what looks like a truncation error is the step's own round-off; state its precision "
         "(precision = \"float\") to have it judged at it";
}

// The steps a vector field is read with (step_field.hpp): h |Omega| from 2^-k0 down to 2^-(k0 + 5).
// Their round-off is eps / h, amplified by the extrapolation: k0 is a sixth of the judged
// precision's bits (8 in double, 3 in float), at most 24 (50 digits).
template <class T>
int field_first_exponent() {
  const int bits = static_cast<int>(std::lround(-std::log2(step_eps_double<T>())));
  return std::max(2, std::min(24, bits / 6));
}

// How closely a read field must match to "agree", relative to its size: 1e-6 in double and 1e-20 in
// 50 digits, for a step computing in its scalar; for a step judged at a coarser precision, the
// same power of its eps as 1e-6 is of double's, eps^0.3833 (2.2e-3 in float). The reading's own
// error is eps / h at the smallest step read, amplified by the extrapolation, well below that; the
// differences named (a sign, a missing term, Omega for Pi) are of the size of the field itself.
template <class T>
T field_agree_tolerance() {
  if (current_step_precision().coarser_than<T>()) return T(std::pow(step_eps_double<T>(), 0.3833));
  return std::is_same_v<T, double> ? T(1e-6) : T(1e-20);
}

// 2b. A step kept in a quaternion, tried with the same attitude as q and as -q (w >= 0 and w <= 0):
// when it reduces to the identity with one sign and not with the other, the sign is the cause
// (code assuming w >= 0: |w|, w = sqrt(1 - |v|^2), a log map without the sign test). Empty otherwise.
template <class T>
std::string quaternion_sign_cause(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x, const T& h,
                                  const T& size, const T& expected) {
  if (!in.declared_step || !in.form.has_quaternion()) return {};
  T move[2];
  for (int sign = 0; sign < 2; ++sign) {
    EngineState<T> u = state_form::canonical_declared<T>(in.form, I, x.O, x.Pi);
    if (sign) u.q = -u.q;
    try {
      EngineState<T> v = in.declared_step(I, u, h);
      v.form = in.form;
      move[sign] = moved(declared_step_detail::from_declared<T>(v, I), x, size);
    } catch (const std::exception&) {
      current_step_raise().reset();
      return {};
    }
  }
  const T limit = T(1024) * expected;
  const bool plus_ok = move[0] <= limit, minus_ok = move[1] <= limit;
  if (plus_ok == minus_ok) return {};
  return std::string("your step treats q and -q as two attitudes, by experiment: given the same attitude as q with ") +
         (plus_ok ? "w <= 0 (-q)" : "w >= 0") + " it moves the state by " +
         fmt("%.3g", to_double(plus_ok ? move[1] : move[0])) + " however small h is, given it with " +
         (plus_ok ? "w >= 0" : "w <= 0 (-q)") + " by " + fmt("%.1g", to_double(plus_ok ? move[0] : move[1])) +
         ", as a consistent step does; q and -q are one attitude, so a part of the step assumes a sign of w (|w| "
         "where w is meant, w = sqrt(1 - |v|^2), a log map or an angle 2 acos(w) without the sign test)";
}

// 2. and 3.: the step as h -> 0.
struct SmallSteps {
  bool not_identity = false;
  std::string not_identity_text;
  bool returns_input = false;
  std::string returns_input_text;
  double h_still = 0;  // returns_input: the largest probed h at which the step returns its input
};

template <class T>
SmallSteps small_steps(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x, double precision) {
  SmallSteps s;
  const T size = max_abs(x.Pi) > T(0) ? T(max_abs(x.Pi)) : T(1);
  const T rate = rate_of(I, x.Pi);
  const double round = std::max(precision, step_eps_double<T>());
  int first_still = -1;  // the first k from which on the step returns x exactly
  int smallest = -1;     // the smallest h (largest k) at which a consistent step visibly moves x
  RigidBodyState<T> at_smallest;
  // h |Omega| = 2^-k: a consistent step moves x by about 2^-k of its size; while that is far above
  // the step's round-off it must visibly move it.
  const double min_h = current_step_domain().min_h;
  for (int k = 4; to_double(pow2<T>(-k)) > 64 * round && k <= 200; ++k) {
    const T h = pow2<T>(-k) / rate;
    if (min_h > 0 && to_double(h) < min_h) break;  // not below a declared smallest step
    const RigidBodyState<T> y = in.rigid_body_step(I, x, h);
    const bool same = returned_input(y, x);
    if (same && first_still < 0) first_still = k;
    if (!same) first_still = -1;
    smallest = k;
    at_smallest = y;
  }
  if (smallest > 0 && first_still < 0) {
    // 2: a move of a fixed size however small h is.
    const T m = moved(at_smallest, x, size);
    const T expected = pow2<T>(-smallest);
    if (m > T(1024) * expected) {
      s.not_identity = true;
      if (std::string sign = quaternion_sign_cause<T>(in, I, x, T(expected / rate), size, expected); !sign.empty()) {
        s.not_identity_text = sign + "; measured at\n" + named("I", I) + named("Pi", x.Pi) + named("O", x.O);
        return s;
      }
      s.not_identity_text =
          "your step does not reduce to the identity as h -> 0: |step(x, h) - x| = " + fmt("%.3g", to_double(m)) +
          " of the state at h = " + fmt("%.3g", to_double(T(expected / rate))) + " (h |Omega| = 2^-" +
          std::to_string(smallest) + "), where a consistent step moves it by about " +
          fmt("%.1g", to_double(expected)) +
          ": something changes the state by a fixed amount however small h is (what, this "
          "measurement does not tell); measured at\n" +
          named("I", I) + named("Pi", x.Pi) + named("O", x.O);
    }
  }
  // Still at every step probed, down from h |Omega| = 2^-4: a guard on h that is absolute bites here
  // at larger turns too (a fast state, where the failing steps are short in seconds). The steps above
  // are tried, h |Omega| = 2^-3 up to 2^24, for the first that moves x; one that never moves is not a
  // guard on h (nothing is known).
  bool guard = first_still > 4;
  if (first_still == 4) {
    for (int k = 3; k >= -24 && !guard; --k) {
      const RigidBodyState<T> y = in.rigid_body_step(I, x, T(pow2<T>(-k) / rate));
      if (!returned_input(y, x)) first_still = k + 1, guard = true;
    }
  }
  if (guard) {
    const T h_still = pow2<T>(-first_still) / rate, h_moves = pow2<T>(-(first_still - 1)) / rate;
    s.returns_input = true;
    s.h_still = to_double(h_still);
    s.returns_input_text = "your step returns its input unchanged for h <= " + fmt("%.3g", to_double(h_still)) +
                           " (it moves x at h = " + fmt("%.3g", to_double(h_moves)) +
                           "; here max |Omega_i| = " + fmt("%.3g", to_double(rate)) +
                           "), where a consistent step moves it by about h |Omega| |Pi|, far above round-off: a guard "
                           "on h (\"nothing to do for a tiny step\")";
  }
  return s;
}

// 4. A cap: the step's field at lambda x against (3.8) there, lambda = 2^j, j = -16, -14, ..., 24.
// `field(x)` is the extrapolated dPi/dt of the step (step_field.hpp). A cap is named only when the
// experiment confirms it at the failing state x itself (lambda = 1): the field is exactly (3.8) below
// some size and, from there on (x included), (3.8) shrunk to a constant fraction, or to a constant
// size (the clamp an engine's "max angular velocity" makes).
template <class T, class Field>
std::string cap_of(const Vec3<T>& I, const RigidBodyState<T>& x, Field&& field) {
  const T size = max_abs(x.Pi);
  if (!(size > T(0))) return {};
  struct Point {
    T pi;     // |lambda Pi|
    T ratio;  // F(lambda x) as a multiple of (3.8) at lambda x
    T force;  // |F(lambda x)|
    T noise;  // what round-off leaves uncertain in |F| there (below)
  };
  std::vector<Point> at;
  constexpr int kFirst = -16, kStride = 2;
  const StepDomain& domain = current_step_domain();
  for (int j = kFirst; j <= 24; j += kStride) {
    const T lambda = pow2<T>(j);
    RigidBodyState<T> xl = x;
    xl.Pi *= lambda;
    // Not beyond a declared domain: a cap there is the integrator's own business.
    if ((domain.max_omega > 0 && to_double(rate_of(I, xl.Pi)) > domain.max_omega) ||
        (domain.max_pi > 0 && to_double(T(max_abs(xl.Pi))) > domain.max_pi))
      break;
    const Vec3<T> notes = truth::cross(xl.Pi, Vec3<T>(xl.Pi.cwiseQuotient(I)));
    const T n = max_abs(notes);
    if (!(n > T(0))) return {};
    const Vec3<T> f = field(xl);
    // The step's field as a multiple of (3.8): only when it is one (parallel). Beyond the failing
    // state a field that is not (a step too fast to read, a guard on h reached by the small steps
    // the field is read with) ends the scan: nothing is known from there on.
    const T r = f.dot(notes) / notes.dot(notes);
    const std::size_t here = static_cast<std::size_t>(-kFirst / kStride);
    // The field is read from (step(x, h) - x) / h with h |Omega| down to 2^-(k0 + 5) (k0 =
    // field_first_exponent): its round-off is eps |Pi| |Omega| amplified by up to 2^(k0 + 12) with the
    // extrapolation. Where that is not small against the field, the field cannot be read (double at
    // a large scale with a small field): the scan ends there.
    const T noise =
        T(std::ldexp(1.0, field_first_exponent<T>() + 12)) * step_eps<T>() * max_abs(xl.Pi) * T(rate_of(I, xl.Pi));
    const T tolerance = field_agree_tolerance<T>() * n + T(4) * noise;
    // In double a reading whose round-off is above 1e-3 of the field is not read; in float every reading
    // carries about that much (float's field is known to a few 1e-3, its noise bound here), so the
    // bound is 1/16 of the field there, far below the difference a cap makes (a fraction of the field).
    const T unreadable = current_step_precision().coarser_than<T>() ? T(1) / T(16) : T(1e-3);
    if (!(max_abs(f) > T(0)) || max_abs(Vec3<T>(f - r * notes)) > tolerance || noise > unreadable * max_abs(f)) {
      if (at.size() > here) break;
      return {};
    }
    at.push_back({lambda * size, r, abs_value(r) * n, noise});
  }
  const auto near = [](const T& a, const T& b, const T& noise) {
    return abs_value(T(a - b)) <= field_agree_tolerance<T>() * abs_value(b) + T(4) * noise;
  };
  std::size_t from = 0;
  while (from < at.size() &&
         near(at[from].ratio, T(1), T(at[from].noise / (at[from].force / abs_value(at[from].ratio)))))
    ++from;
  const std::size_t here = static_cast<std::size_t>(-kFirst / kStride);  // j = 0: the failing state
  // Two sizes at least beyond the cap's start: with one, a constant fraction and a constant size are
  // the same thing, and neither is shown.
  if (from == 0 || from == at.size() || here >= at.size() || here < from || at.size() - from < 2) return {};
  // Constant from `from` on, each point within its own round-off (`scale(p)` turns |F|'s noise into
  // the quantity's).
  const auto constant = [&](auto get, auto scale) {
    const T c = get(at[from]);
    for (std::size_t k = from; k < at.size(); ++k)
      if (!near(get(at[k]), c, T(at[k].noise * scale(at[k])))) return false;
    return true;
  };
  const std::string range = " for every max |Pi_i| >= " + fmt("%.3g", to_double(at[from].pi)) + ", this state's " +
                            fmt("%.3g", to_double(size)) + " among them, and exactly (3.8) up to max |Pi_i| = " +
                            fmt("%.3g", to_double(at[from - 1].pi));
  if (constant([](const Point& p) { return p.ratio; }, [](const Point& p) { return T(abs_value(p.ratio) / p.force); }))
    return "a cap, by experiment: your step's field is " + fmt("%.4g", to_double(at[here].ratio)) + " x (3.8)" + range +
           ": (3.8) shrunk to a constant fraction beyond a size (a cap on the angular velocity or the momentum)";
  if (constant([](const Point& p) { return p.force; }, [](const Point&) { return T(1); }))
    return "a cap, by experiment: your step's field is (3.8) shrunk to the constant size max |dPi_i/dt| = " +
           fmt("%.4g", to_double(at[here].force)) + " (here " + fmt("%.4g", to_double(at[here].ratio)) + " x (3.8))" +
           range + ": a cap on the size of the gyroscopic term";
  return {};
}

}  // namespace gm::stepprobe
