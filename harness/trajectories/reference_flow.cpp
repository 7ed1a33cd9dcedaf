#include "harness/trajectories/reference_flow.hpp"

#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <cstdio>
#include <string>

namespace gm::harness {

namespace {

using R = Real50;

std::string estimate_text(const R& n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", n.convert_to<double>());
  return buf;
}

}  // namespace

// The project's Taylor oracle (oracle/taylor.hpp) on the attitude field of oracle/fields.hpp:
// state (Pi, O) with O row-major, local error below limits.tolerance * max(1, |x|_inf) per step.
std::vector<RigidBodyState<R>> reference_rigid_body(const Vec3<R>& I, const RigidBodyState<R>& x0, const R& t0,
                                                    const std::vector<R>& times, const ReferenceLimits& limits) {
  for (int i = 0; i < 3; ++i)
    if (!(I(i) > R(0))) throw std::invalid_argument("the moments of inertia must be positive");
  if (!all_finite(x0.Pi) || !all_finite(x0.O)) throw std::invalid_argument("the initial state is not finite");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (times[i] < (i == 0 ? t0 : times[i - 1]))
      throw std::invalid_argument("reference times must be non-decreasing and not before t0");

  std::vector<R> x(12);
  for (int i = 0; i < 3; ++i) x[i] = x0.Pi(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) x[3 + 3 * i + j] = x0.O(i, j);

  const oracle::RigidBodyAttitudeField<R> field(I(0), I(1), I(2));
  oracle::TaylorSolver<R, oracle::RigidBodyAttitudeField<R>> solver(field, 12, R(limits.tolerance));
  const R last = times.empty() ? t0 : times.back();
  // The step size barely changes along a free rigid body (|Omega| is bounded by the invariants):
  // refuse at once what would take too long, rather than after minutes.
  if (last > t0) {
    const R steps = (last - t0) / solver.step_size_at(x);
    if (steps > R(limits.max_steps))
      throw std::length_error("the reference solution would need about " + estimate_text(steps) +
                              " Taylor steps to reach t = " + to_string_full(last) + " (the limit is " +
                              std::to_string(limits.max_steps) + "); shorten the run or scale it down");
  }
  solver.set_limits(limits.max_steps, R(0));
  std::vector<std::vector<R>> samples;
  try {
    samples = solver.sample(x, t0, times);
  } catch (const std::runtime_error& e) {
    throw std::length_error(std::string("the reference solution: ") + e.what());
  }
  std::vector<RigidBodyState<R>> out;
  out.reserve(samples.size());
  for (const auto& y : samples) {
    RigidBodyState<R> s;
    for (int i = 0; i < 3; ++i) s.Pi(i) = y[i];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s.O(i, j) = y[3 + 3 * i + j];
    out.push_back(s);
  }
  return out;
}

}  // namespace gm::harness
