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
#include "properties/support/scalar_text.hpp"
#include "properties/support/show.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace gm::stepprobe {

template <class T>
T pow2(int k) {
  T x(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) x = k < 0 ? x / T(2) : x * T(2);
  return x;
}

template <class T>
int mantissa_bits() {
  return std::numeric_limits<T>::digits;
}

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

// 1. The relative round-off the step computes with: 0 when it follows every delta down to a few
// units of T's own last place (no finding).
template <class T>
double precision_of(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x) {
  const T size = max_abs(x.Pi);
  if (!(size > T(0))) return 0;
  const T h = at_least_min_h<T>(T(pow2<T>(-6) / rate_of(I, x.Pi)));
  const RigidBodyState<T> y = in.rigid_body_step(I, x, h);
  // The delta goes to the largest component of Pi: a delta added to a zero component is held
  // exactly by any floating-point type (a float holds 1e-40 beside 0), and would be followed at
  // any precision.
  int j = 0;
  for (int i = 1; i < 3; ++i)
    if (abs_value(x.Pi(i)) > abs_value(x.Pi(j))) j = i;
  double followed = 0;  // the smallest relative delta followed so far
  for (int k = 8; k <= mantissa_bits<T>() - 6; k += 2) {
    const T delta = pow2<T>(-k) * size;
    RigidBodyState<T> xd = x;
    xd.Pi(j) += delta;
    const T response = max_abs(Vec3<T>(in.rigid_body_step(I, xd, h).Pi - y.Pi)) / delta;
    if (!(response > T(1) / T(4) && response < T(4))) break;  // no longer followed
    followed = to_double(pow2<T>(-k));
  }
  const double own = to_double(std::numeric_limits<T>::epsilon());
  // Followed to within 2^6 units of T's last place: the step computes in T.
  if (followed > 0 && followed <= 64 * own * 16) return 0;
  return followed > 0 ? followed : 1;  // not even 2^-8 followed: no precision at all
}

template <class T>
std::string precision_words(double followed) {
  const double own = to_double(std::numeric_limits<T>::epsilon());
  std::string name;
  if (followed > 1e-9 && followed < 1e-5)
    name = "single precision (float: round-off ~6e-8 relative)";
  else if (followed > 1e-18 && followed < 1e-13)
    name = "double precision (round-off ~1.1e-16 relative)";
  else
    name = fmt("about %.0f significant digits (round-off ~%.1g relative)", -std::log10(followed), followed);
  return "your step computes in " + name + ", below the " + fmt("%.2g", own) +
         " of the scalar it is checked in: step(x + delta, h) - step(x, h) follows delta down to " +
         fmt("%.1g", followed) +
         " of |Pi| and no further, so what looks like a truncation error below that is the "
         "step's own round-off (no vector field is read from it)";
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
  const double round = std::max(precision, to_double(std::numeric_limits<T>::epsilon()));
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
    const bool same = (y.Pi.array() == x.Pi.array()).all() && (y.O.array() == x.O.array()).all();
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
  if (first_still > 4) {
    const T h_still = pow2<T>(-first_still) / rate, h_moves = pow2<T>(-(first_still - 1)) / rate;
    s.returns_input = true;
    s.h_still = to_double(h_still);
    s.returns_input_text = "your step returns its input unchanged for h <= " + fmt("%.3g", to_double(h_still)) +
                           " (it moves x at h = " + fmt("%.3g", to_double(h_moves)) +
                           "; here |Omega| = " + fmt("%.3g", to_double(rate)) +
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
    // The field is read from (step(x, h) - x) / h with h |Omega| down to about 2^-20: its round-off
    // is eps |Pi| |Omega| amplified by up to 2^20. Where that is not small against the field, the
    // field cannot be read (double at a large scale with a small field): the scan ends there.
    const T noise = T(1 << 20) * std::numeric_limits<T>::epsilon() * max_abs(xl.Pi) * T(rate_of(I, xl.Pi));
    const T tolerance = T(1e-6) * n + T(4) * noise;
    if (!(max_abs(f) > T(0)) || max_abs(Vec3<T>(f - r * notes)) > tolerance || noise > T(1e-3) * max_abs(f)) {
      if (at.size() > here) break;
      return {};
    }
    at.push_back({lambda * size, r, abs_value(r) * n, noise});
  }
  const auto near = [](const T& a, const T& b, const T& noise) {
    return abs_value(T(a - b)) <= T(1e-6) * abs_value(b) + T(4) * noise;
  };
  std::size_t from = 0;
  while (from < at.size() &&
         near(at[from].ratio, T(1), T(at[from].noise / (at[from].force / abs_value(at[from].ratio)))))
    ++from;
  const std::size_t here = static_cast<std::size_t>(-kFirst / kStride);  // j = 0: the failing state
  if (from == 0 || from == at.size() || here >= at.size() || here < from) return {};
  // Constant from `from` on, each point within its own round-off (`scale(p)` turns |F|'s noise into
  // the quantity's).
  const auto constant = [&](auto get, auto scale) {
    const T c = get(at[from]);
    for (std::size_t k = from; k < at.size(); ++k)
      if (!near(get(at[k]), c, T(at[k].noise * scale(at[k])))) return false;
    return true;
  };
  const std::string range = " for every |Pi| >= " + fmt("%.3g", to_double(at[from].pi)) + ", this state's " +
                            fmt("%.3g", to_double(size)) +
                            " among them, and exactly (3.8) up to |Pi| = " + fmt("%.3g", to_double(at[from - 1].pi));
  if (constant([](const Point& p) { return p.ratio; }, [](const Point& p) { return T(abs_value(p.ratio) / p.force); }))
    return "a cap, by experiment: your step's field is " + fmt("%.4g", to_double(at[here].ratio)) + " x (3.8)" + range +
           ": (3.8) shrunk to a constant fraction beyond a size (a cap on the angular velocity or the momentum)";
  if (constant([](const Point& p) { return p.force; }, [](const Point&) { return T(1); }))
    return "a cap, by experiment: your step's field is (3.8) shrunk to the constant size |dPi/dt| = " +
           fmt("%.4g", to_double(at[here].force)) + " (here " + fmt("%.4g", to_double(at[here].ratio)) + " x (3.8))" +
           range + ": a cap on the size of the gyroscopic term";
  return {};
}

}  // namespace gm::stepprobe
