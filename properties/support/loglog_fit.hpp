// The suite's one log-log fit of a convergence order (GeometricIntegrators.jl's verification idea),
// used by the integrator properties, the portraits and `geomech check-trajectory`: the error of a
// method of order p behaves like C h^p, so log(err) against log(h) is a line of slope p until the
// error reaches the round-off plateau, where it stops decreasing. One plateau rule: a point at or
// below its floor, or not finite, is excluded, and so is every point at a smaller h after it (once
// on the plateau, smaller steps only add round-off). The least-squares slope is taken over the rest.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::conv {

struct SlopeFit {
  double slope = 0;         // least-squares slope of log(err) against log(h) over the points used
  int used = 0;             // points used (above the plateau); the slope means something from 2 on
  std::vector<bool> point;  // point[i]: point i was used
  std::string table;        // every point, marked "used" or "plateau", for failure messages
  bool measured() const { return used >= 2; }
};

// `floor[i]` is the round-off plateau for point i (round-off grows with the number of steps):
// points whose error is at most their floor (or not finite and positive) are excluded, and so is
// every point at a smaller h than the first excluded one (once on the plateau, smaller steps only
// add round-off). `h` must be decreasing. `label` names the step column as it is measured: "h", or
// "h |Omega|" where the steps are relative to the motion's time scale (a table must say
// which).
inline SlopeFit loglog_slope(const std::vector<double>& h, const std::vector<double>& err,
                             const std::vector<double>& floor, const char* label = "h") {
  SlopeFit f;
  std::vector<double> X, Y;
  bool plateau = false;
  char line[160];
  for (std::size_t i = 0; i < h.size() && i < err.size(); ++i) {
    const bool finite = std::isfinite(err[i]);
    const bool at_floor = finite && err[i] <= floor[i];
    const bool usable = !plateau && finite && !at_floor && h[i] > 0;
    // Each excluded point says why, in words its numbers agree with.
    const char* why = usable     ? ""
                      : !finite  ? "(not finite, excluded)"
                      : at_floor ? "(at round-off, excluded)"
                                 : "(above round-off, excluded: after a point at round-off or not finite)";
    if (!usable) plateau = true;
    f.point.push_back(usable);
    std::snprintf(line, sizeof line, "    %s = %-12.6g error = %-12.6g %s\n", label, h[i], err[i], why);
    f.table += line;
    if (usable) {
      X.push_back(std::log(h[i]));
      Y.push_back(std::log(err[i]));
    }
  }
  f.used = static_cast<int>(X.size());
  if (f.used < 2) return f;
  double mx = 0, my = 0;
  for (int i = 0; i < f.used; ++i) mx += X[i], my += Y[i];
  mx /= f.used;
  my /= f.used;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < f.used; ++i) sxy += (X[i] - mx) * (Y[i] - my), sxx += (X[i] - mx) * (X[i] - mx);
  f.slope = sxx > 0 ? sxy / sxx : 0;
  return f;
}

}  // namespace gm::conv
