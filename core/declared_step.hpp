// A step kept in a declared form (core/state_form.hpp: a quaternion, omega, pi, ...) as a step of
// the notes' (Pi, O), so that every property runs on it unchanged (DESIGN.md, "Real code keeps its
// own state"). The suite owns the conversions; the user writes none.
//
// The integrator's own state is kept along a run: each state the step returned is remembered with
// the (Pi, O) the properties were given for it, and a step from that (Pi, O) starts from the user's
// own state again, not from a conversion of it. So a run of steps is the user's run (its quaternion's
// sign and norm, its round-off) and the notes' form is only how the properties look at it. A state
// the properties made themselves (a drawn state, a rotated attitude) is converted.
#pragma once

#include "core/subject.hpp"

#include <array>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace gm {

namespace declared_step_detail {

// The last states a declared step returned, by the (I, Pi, O) the properties saw for them.
template <class T>
class Memory {
 public:
  const EngineState<T>* find(const Vec3<T>& I, const RigidBodyState<T>& x) {
    for (const Entry& e : entries_)
      if (e.used && e.I == I && e.x.Pi == x.Pi && e.x.O == x.O) return &e.u;
    return nullptr;
  }
  void remember(const Vec3<T>& I, const RigidBodyState<T>& x, const EngineState<T>& u) {
    Entry& e = entries_[next_++ % entries_.size()];
    e = Entry{true, I, x, u};
  }
  std::mutex mutex;

 private:
  struct Entry {
    bool used = false;
    Vec3<T> I;
    RigidBodyState<T> x;
    EngineState<T> u;
  };
  std::array<Entry, 16> entries_{};
  std::size_t next_ = 0;
};

// The notes' state of what the user's step returned. A declared part that is not finite (a NaN, an
// infinity: what a step computes after its energy overflowed) makes the whole state NaN, as a step
// in the notes' (Pi, O) would return it: the checks measure it ("H is not finite within 2503
// steps"), as they do for every step; it is not an error of the call. A zero quaternion is no
// attitude at all, and throws in the declared form's words.
template <class T>
RigidBodyState<T> from_declared(const EngineState<T>& u, const Vec3<T>& I) {
  const StateForm& f = u.form;
  const bool finite = (f.has_quaternion() ? u.q.allFinite() : u.O.allFinite()) && u.angular().allFinite();
  if (!finite) {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    return RigidBodyState<T>{Vec3<T>::Constant(nan), Mat3<T>::Constant(nan)};
  }
  if (f.has_quaternion() && u.q.squaredNorm() == T(0))
    throw std::runtime_error(your_attitude(f) + " returned by the step is zero");
  const Mat3<T> O = attitude_of(u);
  return RigidBodyState<T>{body_momentum_of(u, I, O), O};
}

}  // namespace declared_step_detail

// The declared state of a notes' state (I, x): the user's own, if a step of this integrator returned
// x, else the conversion (core/state_form.hpp).
template <class T>
class DeclaredStates {
 public:
  explicit DeclaredStates(StateForm f) : form_(f), memory_(std::make_shared<declared_step_detail::Memory<T>>()) {}
  EngineState<T> of(const Vec3<T>& I, const RigidBodyState<T>& x) const {
    {
      std::lock_guard lock(memory_->mutex);
      if (const EngineState<T>* u = memory_->find(I, x)) return *u;
    }
    return to_declared<T>(form_, I, x.O, x.Pi);
  }
  // The notes' state of a state the user's step returned (kept, with it, for the next step).
  RigidBodyState<T> notes(const Vec3<T>& I, EngineState<T> u) const {
    u.form = form_;
    const RigidBodyState<T> x = declared_step_detail::from_declared<T>(u, I);
    std::lock_guard lock(memory_->mutex);
    memory_->remember(I, x, u);
    return x;
  }
  const StateForm& form() const { return form_; }

 private:
  StateForm form_;
  std::shared_ptr<declared_step_detail::Memory<T>> memory_;
};

// Fills in.rigid_body_step (and rigid_body_run) from in.declared_step (and declared_run) in the
// integrator's declared form. A no-op for an integrator that keeps the notes' (Pi, O).
template <class T>
void adapt_declared_step(Integrator<T>& in) {
  if (!in.declared_step) return;
  const DeclaredStates<T> states(in.form);
  auto step = in.declared_step;
  in.rigid_body_step = [states, step](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return states.notes(I, step(I, states.of(I, x), h));
  };
  if (in.declared_run) {
    auto run = in.declared_run;
    in.rigid_body_run = [states, run](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h, int n) {
      const std::vector<EngineState<T>> us = run(I, states.of(I, x), h, n);
      std::vector<RigidBodyState<T>> out;
      out.reserve(us.size());
      for (const auto& u : us) out.push_back(states.notes(I, u));
      return out;
    };
  }
}

}  // namespace gm
