// Convergence orders from log-log slopes (GeometricIntegrators.jl's verification idea): the
// error of a method of order p behaves like C h^p, so log(err) against log(h) is a line of slope
// p until the error reaches the round-off plateau, where it stops decreasing. Points on the
// plateau are excluded before the least-squares fit.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::conv {

struct SlopeFit {
  double slope = 0;   // least-squares slope of log(err) against log(h) over the points used
  int used = 0;       // points used (above the plateau)
  std::string table;  // every point, marked "used" or "plateau", for failure messages
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

// What a run that does not converge did, in words its numbers agree with: the error at the smallest
// step against its floor, and whether it fell at all from the largest step.
inline std::string stall_words(const std::vector<double>& err, double last_floor) {
  if (err.empty()) return "no error measured";
  char line[200];
  const double first = err.front(), last = err.back();
  if (!std::isfinite(last)) return "the error at the smallest step is not finite";
  if (std::isfinite(first) && last < first)
    std::snprintf(line, sizeof line, "error %.3g at the smallest step, %.3g times its round-off floor, having fallen only %.3g times from the largest step",
                  last, last / last_floor, first / last);
  else
    std::snprintf(line, sizeof line, "error %.3g at the smallest step, %.3g times its round-off floor, and not smaller than at the largest step",
                  last, last / last_floor);
  return line;
}

// Every error finite and at or below its round-off floor: the method is exact for the problem at
// every step size tried (a first-order method on a spherical body, whose motion is a rotation
// about a fixed axis, for instance), and no slope can be measured or is needed.
inline bool at_roundoff_everywhere(const std::vector<double>& err, const std::vector<double>& floor) {
  if (err.empty()) return false;
  for (std::size_t i = 0; i < err.size(); ++i)
    if (!std::isfinite(err[i]) || i >= floor.size() || err[i] > floor[i]) return false;
  return true;
}

// The first step size at which the error is not finite (NaN or inf), or 0 when all are finite. A
// method that blows up at some step is not "at round-off": a claimed order is then false, and the
// slope fit (which treats points below the floor as a plateau) must not be left to decide.
inline double first_non_finite(const std::vector<double>& h, const std::vector<double>& err) {
  for (std::size_t i = 0; i < err.size() && i < h.size(); ++i)
    if (!std::isfinite(err[i])) return h[i];
  return 0;
}

}  // namespace gm::conv
