// Integrator portraits: pictures of each integrator of a subject, drawn whatever properties exist.
// For every rigid_body_step, in double and in 50 digits: the error at a fixed time against a
// high-accuracy reference as the step shrinks (log-log, with the claimed order drawn as a
// slope), and the residuals of |Pi|^2, the energy and O^T O - Id over a long run. Each
// (integrator, scalar) runs isolated like a property, so a crashing step cannot take the
// report down. Portraits illustrate; the verdicts on claims come from the properties.
#pragma once

#include "harness/check.hpp"
#include "harness/isolate.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gm::harness {

struct PortraitTask {
  std::string integrator;
  std::string scalar;
  std::function<std::string()> run;  // runs in a child; returns a JSON verdict carrying the series
};

std::vector<PortraitTask> portrait_task_list(const SubjectSet& s, const CheckConfig& cfg);

// A verdict-shaped carrier (property "portrait", outcome PASS when the picture could be drawn,
// CRASH/TIMEOUT/ERROR otherwise) holding the series and, in its message, the measured figures.
Verdict portrait_from_task(const PortraitTask& task, const TaskResult& result);

}  // namespace gm::harness
