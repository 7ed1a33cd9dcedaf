// A step that raises: an integrator's step that throws (a C++ exception, a Python or
// Octave error behind the protocol) is told apart from a property that fails. The runner wraps each
// integrator it drives (guarded(), below): an exception of the step becomes StepRaised, which says
// where it was called (the state's size, |Omega| and h), and the runner records it with the case
// it ended. What the verdict then says depends on the claim the property judges: a claimed
// property FAILS (its claim could not be verified), an unclaimed one is NOT CHARACTERISED (nothing
// was promised, and nothing could be measured); the one finding "your step raises ..." is made
// once, by the integrator's domain check (properties/integrators/integrator_domain.cpp).
//
// A failure of the code's process (it died, answered out of step: gm::ProcessFailure) is not a
// raise and passes through: the check ends as the isolation reports it.
#pragma once

#include "core/subject.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/tolerance.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace gm {

// What the step raised, and where.
struct StepRaise {
  std::string message;  // the exception's message (the code under test's own words)
  std::string where;    // "|Pi| = 2.5e6, |Omega| = 3.1e6, h = 3.8e-08"
  double size = 0;      // |Pi| (|M|, max(|Q|, |P|)) of the state it was called at
  double rate = 0;      // |Omega| there (the motion's rate; 0 where there is none)
  double h = 0;
};

class StepRaised : public std::runtime_error {
 public:
  explicit StepRaised(StepRaise r)
      : std::runtime_error("your step raised at " + r.where + ": " + r.message), raise_(std::move(r)) {}
  const StepRaise& raise() const { return raise_; }

 private:
  StepRaise raise_;
};

// The raise of the case in progress on this thread: set by a guarded step, cleared by the runner
// at the start of each case.
std::optional<StepRaise>& current_step_raise();

// While set, a raise of the step discards its case instead of ending the check (the runner's second
// run of a claimed check that failed with a raise: what the cases that ran to their end found).
bool& discard_step_raises();

// The declared domain of the integrator whose property runs on this thread (set by the runner;
// none declared: no limit). Draws keep inside it (within_domain, below); a call of the step
// outside it throws OutsideDomain, and the runner discards that case: nothing outside is checked.
StepDomain& current_step_domain();

class OutsideDomain : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest lambda' <= lambda, by halving, for which the state scaled by lambda' (its rate and
// size multiplied by lambda') and the step h0 / lambda' stay in the current domain (a time scaled
// with the state: the same motion in other units). lambda itself when nothing is declared.
template <class T>
T within_domain(T lambda, double rate, double size, double h0) {
  const StepDomain& d = current_step_domain();
  for (int k = 0; k < 400; ++k) {
    const double l = to_double(lambda);
    const bool fast = d.max_omega > 0 && l * rate > d.max_omega;
    const bool big = d.max_pi > 0 && l * size > d.max_pi;
    const bool short_step = d.min_h > 0 && h0 / l < d.min_h;
    if (short_step && !fast && !big) {
      lambda /= T(2);  // a smaller scale means a longer step
      continue;
    }
    if (!fast && !big) break;
    lambda /= T(2);
  }
  return lambda;
}

// The smallest step >= h0 allowed in the current domain (h0 itself when nothing is declared): for
// diagnostics that probe small steps.
template <class T>
T at_least_min_h(const T& h0) {
  const double m = current_step_domain().min_h;
  if (!(m > 0) || to_double(abs_value(h0)) >= m) return h0;
  T h = h0;
  while (to_double(abs_value(h)) < m) h *= T(2);
  return h;
}

namespace stepguard {

template <class T>
double size_of(const RigidBodyState<T>& x) {
  return to_double(max_abs(x.Pi));
}
template <class T>
double size_of(const ManakovState<T>& x) {
  return to_double(max_abs(x.M));
}
template <class T>
double size_of(const Vec3Pair<T>& z) {
  return std::max(to_double(max_abs(z.first)), to_double(max_abs(z.second)));
}
template <class T>
double size_of(const MatXPair<T>& z) {
  return std::max(to_double(max_abs(z.first)), to_double(max_abs(z.second)));
}

// A state in a declared form (core/state_form.hpp): the size of its angular vector, |Pi| or |pi| for
// a momentum, |Omega| or |omega| for a velocity (a rotation keeps either's size).
template <class T>
double size_of(const EngineState<T>& u) {
  return to_double(max_abs(u.angular()));
}

// |Omega| = max |Pi_i / I_i| for the rigid body; for the others, the state's size over the
// smallest parameter (a bound on the rate, as the regime draws use).
template <class T>
double rate_of(const Vec3<T>& I, const RigidBodyState<T>& x) {
  return to_double(max_abs(Vec3<T>(x.Pi.cwiseQuotient(I))));
}
template <class T>
double rate_of(const Vec3<T>& I, const Vec3Pair<T>& z) {
  return to_double(max_abs(Vec3<T>(z.second.cross(z.first).cwiseQuotient(I))));
}
template <class T>
double rate_of(const Vec3<T>& I, const EngineState<T>& u) {
  const bool velocity = u.form.angular == Angular::Omega || u.form.angular == Angular::omega;
  return velocity ? size_of(u) : size_of(u) / to_double(I.minCoeff());  // |pi| / min I bounds |Omega|
}
template <class T, class X>
double rate_of(const MatX<T>& A, const X& x) {
  const double a = to_double(A.cwiseAbs().maxCoeff());
  return a > 0 ? size_of(x) / a : 0;
}

template <class P, class X, class T>
[[noreturn]] void rethrow_as_raise(const std::exception& e, const P& param, const X& x, const T& h) {
  StepRaise r;
  r.message = e.what();
  r.size = size_of(x);
  r.rate = rate_of(param, x);
  r.h = to_double(h);
  r.where = fmt("max |state_i| = %.3g, rate max |Omega_i| = %.3g, h = %.3g", r.size, r.rate, r.h);
  if (discard_step_raises())
    throw rc::detail::CaseResult(rc::detail::CaseResult::Type::Discard, "your step raised at " + r.where);
  current_step_raise() = r;
  throw StepRaised(std::move(r));
}

// Whether a call is in the current domain; the reason when not.
template <class P, class X, class T>
std::string outside(const P& param, const X& x, const T& h) {
  const StepDomain& d = current_step_domain();
  if (!d.declared()) return {};
  const double rate = rate_of(param, x), size = size_of(x), step = std::abs(to_double(h));
  if (d.max_omega > 0 && rate > d.max_omega) return fmt("max |Omega_i| = %.3g > max_omega = %.3g", rate, d.max_omega);
  if (d.max_pi > 0 && size > d.max_pi) return fmt("max |state_i| = %.3g > max_pi = %.3g", size, d.max_pi);
  if (d.min_h > 0 && step < d.min_h) return fmt("|h| = %.3g < min_h = %.3g", step, d.min_h);
  return {};
}

// One step function of an integrator, guarded.
template <class Slot>
void guard(Slot& slot) {
  if (!slot) return;
  auto f = slot.function();
  slot = [f](const auto& param, const auto& x, const auto& h) {
    if (const std::string why = outside(param, x, h); !why.empty())
      throw OutsideDomain("a call outside the integrator's declared domain (" + why + ")");
    try {
      return f(param, x, h);
    } catch (const StepRaised&) {
      throw;
    } catch (const OutsideDomain&) {
      throw;
    } catch (const ProcessFailure&) {
      throw;
    } catch (const SlotMissing&) {
      throw;
    } catch (const std::exception& e) {
      rethrow_as_raise(e, param, x, h);
    }
  };
}

}  // namespace stepguard

// The integrator with each of its steps guarded. Runs of steps (Integrator::rigid_body_run) are
// left as they are: properties/integrators/support/step_runs.hpp steps a run that raised again one call at a
// time, through the guarded step, so that the raise is told with the step and state it came from.
template <class T>
Integrator<T> guarded(Integrator<T> in) {
  stepguard::guard(in.rigid_body_step);
  stepguard::guard(in.declared_step);  // called directly in the declared form (integrator_quaternion.cpp)
  stepguard::guard(in.manakov_step);
  stepguard::guard(in.clebsch_step);
  stepguard::guard(in.manakov_clebsch_step);
  return in;
}

}  // namespace gm
