// The work-precision diagram and the long-time energy curve of a subject's integrators,
// drawn against the suite's own methods in the same run: the picture a paper on an integrator
// shows. One problem per kind of step the subject has:
//   rigid body      (Pi, O), the motion of the portraits (portrait.hpp), against the 50-digit
//                   reference (harness/trajectories/reference_flow.hpp); suite: RK4, implicit midpoint,
//                   Lie-Poisson splitting;
//   Manakov n = 4   (M, O), against the Taylor oracle in 50 digits; suite: RK4, implicit midpoint,
//                   isospectral Cayley;
//   Clebsch (3.21)  (Q, P), against Q(t) = O(t)^-1 Q(0) (Remark 3.3); suite: RK4, the canonical
//                   midpoint rule, the splitting into rotation flows;
//   Clebsch (3.23)  (Q, P), n = 3, against Q(t) = Q(0) O(t); suite: RK4, the canonical midpoint rule;
// and for every problem Boost.Odeint's adaptive Dormand-Prince 5(4) (runge_kutta_dopri5) over
// tolerances 1e-2 ... 1e-13.
//
//   work-precision   the error at t = 4 against the cost: the number of steps, the vector-field
//                    evaluations where the method's cost in them is known, and the wall time;
//   long-time energy |H - H0| / H0 over 2^15 steps, both axes logarithmic, so a secular drift
//                    shows as a straight rising line and a bounded error as a plateau (each method
//                    stops after 10 s: an Octave step costs ~0.7 ms).
//
// Double only: the diagram is about cost, and 50-digit arithmetic measures the arithmetic.
// Wall times of an implementation in Python or Octave include the protocol's round trips. The
// figures illustrate; verdicts on claims come from the properties. The data is written beside
// the SVGs as figures/work-precision.csv (work_precision_csv).
#pragma once

#include "harness/checking/portrait.hpp"

#include <optional>
#include <string>

namespace gm::harness {

// The task (isolated like the portraits), when the subject has an integrator in double and the
// run draws pictures. Its verdict has property "work-precision" and no integrator.
std::optional<PortraitTask> work_precision_task(const SubjectSet& s, const CheckConfig& cfg);

// The diagram's data as CSV (problem, method, source, steps, vector-field evaluations, seconds,
// error),
// from the work-precision verdict's series; empty when there is none.
std::string work_precision_csv(const CheckResult& r);

}  // namespace gm::harness
