// The work-precision diagram and the long-time energy curve of a subject's integrators (issue 16),
// drawn against the suite's own methods in the same run: the picture a paper on an integrator
// shows.
//
//   work-precision   the error at t = 4 of the motion of portrait.cpp against the 50-digit reference
//                    (harness/reference_flow.hpp), against the cost: the number of steps, the
//                    vector-field evaluations where the method's cost in them is known, and the
//                    wall time. Suite methods: classical RK4, the implicit midpoint rule and the
//                    Lie-Poisson splitting (impl/integrators.hpp), and Boost.Odeint's adaptive
//                    Dormand-Prince 5(4) (runge_kutta_dopri5) over a range of tolerances.
//   long-time energy |H - H0| / H0 over 2^15 steps of h = 1/4 (t to 8192), both axes logarithmic,
//                    so a secular drift shows as a straight rising line and a bounded error as a
//                    plateau.
//
// Double only: the diagram is about cost, and 50-digit arithmetic measures the arithmetic.
// Wall times of an implementation in Python or Octave include the protocol's round trips. The
// figures illustrate; verdicts on claims come from the properties (integrator_structure.cpp).
// The data is written beside the SVGs as figures/work-precision.csv (work_precision_csv).
#pragma once

#include "harness/portrait.hpp"

#include <optional>
#include <string>

namespace gm::harness {

// The task (isolated like the portraits), when the subject has a rigid_body_step in double and
// the run draws pictures. Its verdict has property "work-precision" and no integrator.
std::optional<PortraitTask> work_precision_task(const SubjectSet& s, const CheckConfig& cfg);

// The diagram's data as CSV (method, source, steps, vector-field evaluations, seconds, error),
// from the work-precision verdict's series; empty when there is none.
std::string work_precision_csv(const CheckResult& r);

}  // namespace gm::harness
