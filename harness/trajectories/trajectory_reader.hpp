// Trajectory files, the reader: how students who write Python, Julia or MATLAB hand in runs. Format, version 1
// (docs/TRAJECTORY_FORMAT.md has the full description):
//
//   # geomech-trajectory 1
//   # system: rigid_body
//   # inertia: 2 1.5 1
//   # step: 0.01
//   # method: implicit midpoint
//   0    0.4535961214255773 0 0.8912073600614354   1 0 0  0 1 0  0 0 1
//   0.01 ...
//
// Rows are t, Pi1, Pi2, Pi3 and optionally the 9 entries of O row by row, separated by spaces,
// tabs or commas. A file without the header is plain data; then --system, --inertia and --step
// must be given on the command line (they may also override nothing: a value given in both places
// must agree).
//
// The reader is strict and precise: every problem is reported as FILE:LINE:COLUMN: what is wrong,
// and nothing is guessed. NaN, Inf and absurd magnitudes are rejected.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace gm::harness {

class TrajectoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parameters given on the command line, for files without a header (or to confirm it).
struct TrajectoryParams {
  std::optional<std::string> system;
  std::optional<std::array<std::string, 3>> inertia;  // decimal strings, kept exact
  std::optional<std::string> step;
  bool allow_nonphysical = false;  // accept moments violating the triangle inequality (--allow-nonphysical)
};

struct TrajectoryRow {
  double t = 0;
  std::array<double, 3> Pi{};
  std::array<double, 9> O{};  // row by row
};

struct Trajectory {
  std::string path;
  std::string system;
  std::array<std::string, 3> inertia;  // as written (decimal strings)
  double step = 0;
  std::string method;
  bool has_O = false;
  std::vector<TrajectoryRow> rows;
  std::vector<std::string> first_row;  // the first row's fields as written (the initial state, exactly)
  int digits = 17;                     // significant digits the file prints its values with
  std::vector<std::string> warnings;
};

// Throws TrajectoryError ("FILE:LINE:COLUMN: ...") for anything malformed.
Trajectory read_trajectory(const std::string& path, const TrajectoryParams& params = {});
Trajectory parse_trajectory(const std::string& text, const std::string& name, const TrajectoryParams& params = {});

}  // namespace gm::harness
