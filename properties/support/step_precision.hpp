// The precision an integrator's step computes in, and so the precision its checks judge it at
// (DESIGN.md, "Judged at the precision the code computes in"). Driving a float engine with doubles
// does not make it double: its round-off is about 6e-8 relative, so "within 32 eps" must mean
// float's eps for it, an order must be fitted where the truncation error stands above float's floor,
// and a random walk of a few float eps is noise.
//
// The precision is a fact of the integrator, set by the runner around each of its checks
// (current_step_precision(), as the declared domain is) and read by every tolerance of the
// integrator properties through step_eps<T>():
//   - stated: `precision = "float"` (alias "single") or "double", with its reason; a stated
//     precision is taken as it is;
//   - detected, when nothing is stated: step(x + delta, h) - step(x, h) follows delta down to the
//     precision the step computes in and no further (precision_followed, below). A step that follows
//     deltas only down to about 6e-8 of |Pi| computes in float, and is judged in float, said so.
//     Only float is detected this way: a step that computes in double when a 50-digit run asks for
//     more keeps its finding ("a cast to double"), since a template on the scalar is meant to
//     compute in it.
// The precision never goes below the scalar's own: step_eps<T>() is max(eps(T), the step's eps).
#pragma once

#include "core/subject.hpp"
#include "properties/support/pow2.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/tolerance.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gm {

struct StepPrecision {
  double eps = 0;    // the unit round-off the step is judged with: 2^-23 (float), 2^-52 (double); 0: T's own
  std::string name;  // "float" or "double"; empty: the scalar's own
  std::string how;   // "stated", "stated: <reason>", "detected: ..." (what the reports say of it)
  bool detected = false;
  // Whether the checks judge at a precision coarser than the scalar's own.
  template <class T>
  bool coarser_than() const {
    return eps > 0 && eps > eps_double<T>();
  }
};

// The precision of the integrator whose property runs on this thread (set by the runner).
StepPrecision& current_step_precision();

inline constexpr double kFloatEps = 1.1920928955078125e-07;  // 2^-23, std::numeric_limits<float>::epsilon()
inline constexpr double kDoubleEps = 2.220446049250313e-16;  // 2^-52

// A stated precision by its name: "float" and "single" are float, "double" is double; anything
// else is not a precision (nullopt), and the caller says so.
std::optional<StepPrecision> stated_precision(std::string_view name, std::string_view reason);

// The precision the integrator's checks judge at, in T's words: " (double, judged at float's
// precision: stated)" after a finding; scalar_tag<T>() when the step computes in T.
template <class T>
std::string judged_tag() {
  const StepPrecision& p = current_step_precision();
  if (!p.coarser_than<T>()) return scalar_tag<T>();
  return std::string(" (") + ScalarInfo<T>::name + ", judged at " + p.name + "'s precision, " +
         (p.detected ? "detected" : "stated") + ")";
}

// The unit round-off the integrator's checks use: the step's own, never below T's.
template <class T>
T step_eps() {
  const double e = current_step_precision().eps;
  if constexpr (is_exact_v<T>)
    return T(0);
  else
    return e > eps_double<T>() ? T(e) : eps<T>();
}
template <class T>
double step_eps_double() {
  const double e = current_step_precision().eps;
  return e > eps_double<T>() ? e : eps_double<T>();
}

// "eps" in the step's precision's name: "float eps" for a step judged in float, "eps" otherwise.
template <class T>
std::string eps_word() {
  const StepPrecision& p = current_step_precision();
  return p.coarser_than<T>() ? p.name + " eps" : std::string("eps");
}

// A residual in units of the step's eps times scale, "3.2 float eps * scale" (or "not finite").
template <class T>
std::string step_eps_units(const T& residual, const T& scale) {
  if (!is_finite(residual)) return "not finite";
  return fmt("%.3g ", to_double(T(residual / (step_eps<T>() * scale)))) + eps_word<T>() + " * scale";
}

// Whether a step returned its input x: exactly, for a step computing in its scalar; within the
// rounding of its own precision, for a step judged coarser (a float engine returns its input rounded to
// float and back, through the suite's conversions of its state form): every entry within 4 of its eps
// relative to the state's size.
template <class T>
bool returned_input(const RigidBodyState<T>& y, const RigidBodyState<T>& x) {
  if (!current_step_precision().coarser_than<T>())
    return (y.Pi.array() == x.Pi.array()).all() && (y.O.array() == x.O.array()).all();
  const T size = max_abs(x.Pi) > T(0) ? T(max_abs(x.Pi)) : T(1);
  const T allowed = T(4) * step_eps<T>();
  return max_abs(Vec3<T>(y.Pi - x.Pi)) <= allowed * size && max_abs(Mat3<T>(y.O - x.O)) <= allowed;
}

namespace stepprecision {

using gm::pow2;  // 2^k exactly, in any scalar (pow2.hpp)

// The smallest relative delta of the largest component of Pi that step(x + delta, h) - step(x, h)
// still follows (within a factor of 4: the step is near the identity at h |Omega| = 2^-6), or 0 when
// it follows every delta down to 2^6 units of T's own last place (the step computes in T), or 1
// when not even 2^-8 is followed. The delta goes to the largest component: a delta added to a zero
// component is held exactly by any floating-point type (a float holds 1e-40 beside 0).
template <class T>
double precision_followed(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  const T size = max_abs(x.Pi);
  if (!(size > T(0))) return 0;
  const RigidBodyState<T> y = in.rigid_body_step(I, x, h);
  int j = 0;
  for (int i = 1; i < 3; ++i)
    if (abs_value(x.Pi(i)) > abs_value(x.Pi(j))) j = i;
  double followed = 0;
  for (int k = 8; k <= std::numeric_limits<T>::digits - 6; k += 2) {
    const T delta = pow2<T>(-k) * size;
    RigidBodyState<T> xd = x;
    xd.Pi(j) += delta;
    const T response = max_abs(Vec3<T>(in.rigid_body_step(I, xd, h).Pi - y.Pi)) / delta;
    if (!(response > T(1) / T(4) && response < T(4))) break;
    followed = to_double(pow2<T>(-k));
  }
  if (followed > 0 && followed <= 64 * eps_double<T>() * 16) return 0;
  return followed > 0 ? followed : 1;
}

// Whether a followed delta is float's (2^-22 .. 2^-26 of |Pi|: float's 24 bits, give or take the
// step's own arithmetic).
inline bool is_float_followed(double followed) { return followed > 1e-9 && followed < 1e-5; }

// The fixed state the detection probes at (the same in every check, so that every check of a run
// judges at the same precision): a generic body and momentum, the identity attitude, h |Omega| =
// 2^-6.
template <class T>
std::optional<StepPrecision> detect_float(const Integrator<T>& in) {
  if (!in.rigid_body_step) return std::nullopt;
  const Vec3<T> I(T(7) / T(4), T(3) / T(2), T(5) / T(4));
  const RigidBodyState<T> x{Vec3<T>(T(21) / T(32), T(-19) / T(32), T(-3) / T(16)), Mat3<T>::Identity()};
  const T rate = max_abs(Vec3<T>(x.Pi.cwiseQuotient(I)));
  const double followed = precision_followed<T>(in, I, x, at_least_min_h<T>(T(pow2<T>(-6) / rate)));
  if (!is_float_followed(followed)) return std::nullopt;
  StepPrecision p;
  p.eps = kFloatEps;
  p.name = "float";
  p.detected = true;
  p.how = "detected: step(x + delta, h) - step(x, h) follows delta down to " + fmt("%.1g", followed) +
          " of |Pi| and no further, the round-off of a step computed in float";
  return p;
}

}  // namespace stepprecision

// The precision an integrator's checks judge it at: the one it states, else float when the step is
// seen to compute in float (stepprecision::detect_float), else the scalar's own. Detected once per
// integrator and scalar in a process, at a fixed state, so that every check of a run agrees.
template <class T>
StepPrecision precision_to_judge(const Integrator<T>& in, const IntegratorClaims* claims) {
  if (claims && !claims->precision.empty()) {
    if (auto stated = stated_precision(claims->precision, claims->precision_reason)) return *stated;
    return {};  // not a precision: the intake says so (a stated precision is float, single or double)
  }
  static thread_local std::vector<std::pair<std::string, StepPrecision>> detected;
  for (const auto& [name, p] : detected)
    if (name == in.name) return p;
  StepPrecision p;
  try {
    if (auto f = stepprecision::detect_float<T>(in)) p = *f;
  } catch (const std::exception&) {
    // A step that raises, or is called outside its domain, at the probe's state: nothing detected
    // (its checks meet the raise themselves, and say where).
  }
  current_step_raise().reset();
  detected.emplace_back(in.name, p);
  return p;
}

// The precision judged at while it lives (the runner, the pictures).
struct JudgedAt {
  StepPrecision saved = current_step_precision();
  explicit JudgedAt(const StepPrecision& p) { current_step_precision() = p; }
  ~JudgedAt() { current_step_precision() = saved; }
  JudgedAt(const JudgedAt&) = delete;
  JudgedAt& operator=(const JudgedAt&) = delete;
};

}  // namespace gm
