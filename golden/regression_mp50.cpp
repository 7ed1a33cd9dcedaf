// regress<Real50>: one scalar per translation unit.
#include "golden/regression_impl.hpp"

#include <cstdio>

namespace gm::golden {

template RegressionResult regress<Real50>(const Fixture&, const Problem&, const Subject<Real50>&);

std::string format_regression(const RegressionResult& r) {
  std::string s = r.fixture + " [" + r.scalar + "]: ";
  if (!r.missing_slots.empty()) {
    s += "NOT PROVIDED (missing slots:";
    for (const auto& m : r.missing_slots) s += " " + m;
    return s + ")";
  }
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s max |error| %.3g (tolerance %.3g), max %.3g eps*scale, RMS %.3g; %ld steps",
                r.pass ? "PASS" : "FAIL", r.max_error, r.tolerance, r.max_eps_units, r.rms_eps_units, r.steps);
  s += buf;
  s += "\n  tolerance: " + r.tolerance_rule;
  if (!r.worst.empty()) s += "\n  worst: " + r.worst;
  if (!r.failure.empty() && !r.pass) s += "\n  " + r.failure;
  return s;
}

}  // namespace gm::golden
