// Regression against the golden fixtures: integrate a subject's own vector-field slots from a
// fixture's initial data, accurately, and compare with every sample of the fixture. The subject
// is anything filling the slots (the reference implementation, a student's), so the same check
// runs for both; nothing here knows impl/.
//
// Integration: Gragg-Bulirsch-Stoer extrapolation (golden/extrapolation.hpp) on the slots, in
// the subject's scalar T:
//   double   8 columns (order 16), local tolerance 1e-14;
//   Real50  12 columns (order 24), local tolerance 1e-44.
// Tolerance (max over samples and columns of |x_subject - x_fixture|):
//   double   the roundoff class, k eps scale with scale = max(1, |x|_max) * kappa, kappa the
//            fixture's condition (|dx(t)/dx(0)|_inf, so an error made at any time grows by at
//            most about kappa), and k = 16 (steps + 1): every step of the integration may add a
//            few roundings of size |x| in each of its 2K-substep midpoint sweeps and its
//            extrapolation, plus its local truncation error (tolerance 1e-14 ~ 45 eps, an
//            estimate for the order 2K-2 value, not the order 2K value kept);
//   Real50   1e-35 absolute.
// Errors are also reported as max and RMS in units of eps * scale, with the worst sample.
#pragma once

#include "core/subject.hpp"
#include "golden/fixture.hpp"
#include "golden/systems.hpp"

#include <string>
#include <vector>

namespace gm::golden {

struct RegressionResult {
  std::string fixture;
  std::string scalar;
  std::vector<std::string> missing_slots;  // not empty: NOT PROVIDED, nothing was run
  bool pass = false;
  std::string failure;   // why it failed (a thrown error, a non-finite value, ...)
  double max_error = 0;  // absolute
  double tolerance = 0;  // absolute
  std::string tolerance_rule;
  double max_eps_units = 0, rms_eps_units = 0;  // |error| / (eps * scale)
  std::string worst;                            // "t = 20, column Pi2: subject ..., fixture ..."
  long steps = 0, evaluations = 0;
};

template <class T>
RegressionResult regress(const Fixture& f, const Problem& pr, const Subject<T>& subject);

extern template RegressionResult regress<double>(const Fixture&, const Problem&, const Subject<double>&);
extern template RegressionResult regress<Real50>(const Fixture&, const Problem&, const Subject<Real50>&);

std::string format_regression(const RegressionResult& r);

}  // namespace gm::golden
