// A long run of an integrator's steps, one state at a time, fetched in chunks.
//
// The long-time properties step an integrator 10^4-10^5 times. Behind the protocol each step is a
// round trip to another process (100-500 us), so such a run is one request per chunk of steps
// when the subject offers a run (Integrator::rigid_body_run / manakov_run, n steps at once, as n
// calls of the step would give). A chunk whose run raises is stepped again one step at a time,
// so that an error, or a state that is no longer finite, is met at the very step where single
// calls would meet it. In-process subjects have no run: next() is then one call of the step.
#pragma once

#include "core/subject.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace gm::runs {

template <class State, class Param, class T>
class StepStream {
 public:
  using Step = std::function<State(const Param&, const State&, const T&)>;
  using Run = std::function<std::vector<State>(const Param&, const State&, const T&, int)>;

  // `total` steps at most will be asked for; chunks never go beyond it.
  StepStream(Step step, Run run, Param p, State x, T h, int total, int chunk = 512)
      : step_(std::move(step)),
        run_(std::move(run)),
        p_(std::move(p)),
        x_(std::move(x)),
        h_(std::move(h)),
        left_(total),
        chunk_(chunk) {}

  // The state after the next step.
  const State& next() {
    if (at_ >= buffer_.size()) refill();
    x_ = buffer_[at_++];
    return x_;
  }

 private:
  void refill() {
    buffer_.clear();
    at_ = 0;
    const int n = std::max(1, std::min(chunk_, left_));
    if (run_ && n > 1 && single_ == 0) {
      try {
        buffer_ = run_(p_, x_, h_, n);
        if (static_cast<int>(buffer_.size()) == n) {
          left_ -= n;
          return;
        }
      } catch (const std::exception&) {
        // this chunk is stepped again one step at a time: the error comes from the step that raises it
      }
      buffer_.clear();
      single_ = n;
    }
    --left_;
    if (single_ > 0) --single_;
    buffer_.push_back(step_(p_, x_, h_));
  }

  Step step_;
  Run run_;
  Param p_;
  State x_;
  T h_;
  int left_;
  int chunk_;
  int single_ = 0;  // steps still to take one at a time (after a chunk whose run raised)
  std::vector<State> buffer_;
  std::size_t at_ = 0;
};

template <class T>
StepStream<RigidBodyState<T>, Vec3<T>, T> rigid_body_steps(const Integrator<T>& in, const Vec3<T>& I,
                                                           const RigidBodyState<T>& x, const T& h, int total) {
  return {in.rigid_body_step, in.rigid_body_run, I, x, h, total};
}

template <class T>
StepStream<ManakovState<T>, MatX<T>, T> manakov_steps(const Integrator<T>& in, const MatX<T>& A,
                                                      const ManakovState<T>& x, const T& h, int total) {
  return {in.manakov_step, in.manakov_run, A, x, h, total};
}

}  // namespace gm::runs
