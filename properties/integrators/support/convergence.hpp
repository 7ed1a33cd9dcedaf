// What a convergence run says besides its slope (the fit itself, conv::loglog_slope, is in
// properties/support/loglog_fit.hpp, the one fit of the suite): a stall in words, an error at
// round-off everywhere, the first step that blows up.
#pragma once

#include "properties/support/loglog_fit.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::conv {

// What a run that does not converge did, in words its numbers agree with: the error at the smallest
// step against its floor, and whether it fell at all from the largest step.
inline std::string stall_words(const std::vector<double>& err, double last_floor) {
  if (err.empty()) return "no error measured";
  char line[200];
  const double first = err.front(), last = err.back();
  if (!std::isfinite(last)) return "the error at the smallest step is not finite";
  if (std::isfinite(first) && last < first)
    std::snprintf(line, sizeof line,
                  "error %.3g at the smallest step, %.3g times its round-off floor, having fallen only %.3g times from "
                  "the largest step",
                  last, last / last_floor, first / last);
  else
    std::snprintf(
        line, sizeof line,
        "error %.3g at the smallest step, %.3g times its round-off floor, and not smaller than at the largest step",
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
