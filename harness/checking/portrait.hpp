// Integrator portraits: pictures of each integrator of a subject, drawn whatever properties exist.
// For every rigid_body_step, in double and in 50 digits: the error at a fixed time against a
// high-accuracy reference as the step shrinks (log-log, with the claimed order drawn as a
// slope), and the residuals of |Pi|^2, the energy and O^T O - Id over a long run. Each
// (integrator, scalar) runs isolated like a property, so a crashing step cannot take the
// report down. Portraits illustrate; the verdicts on claims come from the properties.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/isolation/isolate.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gm::harness {

// The motion every portrait (and the work-precision diagram) shows: a triaxial body (a physical
// one: each moment below the sum of the other two) turning near, but not on, its stable axis;
// dyadic data, exact in every scalar.
template <class T>
Vec3<T> portrait_inertia() {
  return Vec3<T>(T(2), T(3) / T(2), T(1));
}
template <class T>
RigidBodyState<T> portrait_start() {
  return {Vec3<T>(T(3) / T(8), T(1) / T(4), T(7) / T(8)), Mat3<T>::Identity()};
}

struct PortraitTask {
  std::string integrator;
  std::string scalar;
  std::function<std::string()> run;   // runs in a child; returns a JSON verdict carrying the series
  std::string property = "portrait";  // what the carrier verdict is called
};

std::vector<PortraitTask> portrait_task_list(const SubjectSet& s, const CheckConfig& cfg);

// A verdict-shaped carrier (property "portrait", outcome PASS when the picture could be drawn,
// CRASH/TIMEOUT/ERROR otherwise) holding the series and, in its message, the measured figures.
Verdict portrait_from_task(const PortraitTask& task, const TaskResult& result);

}  // namespace gm::harness
