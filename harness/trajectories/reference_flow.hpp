// The truth against which trajectories are judged: the free rigid body with its attitude,
//   dPi/dt = Pi x Omega,  dO/dt = O hat(Omega),  Omega = I^-1 Pi      ((2.20), (3.8), (2.10)),
// solved to about 1e-44 in 50-digit arithmetic by the project's Taylor oracle (oracle/taylor.hpp).
// Callers only ever see this function.
#pragma once

#include "core/subject.hpp"

#include <stdexcept>
#include <vector>

namespace gm::harness {

struct ReferenceLimits {
  double tolerance = 1e-44;  // local error per step, relative to the size of the state
  long max_steps = 100000;   // refuse (std::length_error) rather than run for minutes (about 0.5 ms a step)
};

// States at `times` (non-decreasing, all >= t0), starting from x0 at t0. O may be any 3x3
// matrix (it is transported linearly); use the identity when the attitude is not wanted.
// Throws std::invalid_argument for bad input (non-positive inertia, times before t0 or out of
// order) and std::length_error when the integration would need more than max_steps steps.
std::vector<RigidBodyState<Real50>> reference_rigid_body(const Vec3<Real50>& I, const RigidBodyState<Real50>& x0,
                                                         const Real50& t0, const std::vector<Real50>& times,
                                                         const ReferenceLimits& limits = {});

}  // namespace gm::harness
