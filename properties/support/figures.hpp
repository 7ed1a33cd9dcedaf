// Data series and notes a property can attach to its verdict, for the reports' pictures: a convergence
// study (error against step size, with the claimed slope), an invariant's residual over time in
// double and in 50 digits, ... The runner collects the series recorded while a property runs
// (on its final, passing or shrunk, case) and hands them to the report writers.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace gm {

struct Series {
  std::string figure;  // series with the same figure name are drawn together
  std::string name;    // legend entry
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<std::pair<double, double>> points;
  double reference_slope = 0;  // when non-zero, a line of this slope (log-log) is drawn through the data
};

// Series recorded during the current property run (the runner clears it before each case).
std::vector<Series>& recorded_series();

inline void record_series(Series s) { recorded_series().push_back(std::move(s)); }

// Remarks a property attaches to a passing verdict, e.g. "energy is preserved to round-off,
// although the integrator does not claim it" (cleared before each case, like the series).
std::vector<std::string>& recorded_notes();

inline void record_note(std::string note) { recorded_notes().push_back(std::move(note)); }

}  // namespace gm
