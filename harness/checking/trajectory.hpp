// Checking trajectory files: invariants, orthogonality and det of O, agreement with the 50-digit
// reference, and the convergence order over runs at several step sizes. The reader and the format
// are in harness/trajectories/trajectory_reader.hpp.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/trajectories/trajectory_reader.hpp"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

struct TrajectoryCheckOptions {
  TrajectoryParams params;
  int order = 0;                    // claimed order (0: none); needs runs at several step sizes
  std::set<std::string> preserves;  // claimed exact invariants: casimir, energy, orthogonality, spatial_momentum
  double tolerance = 0.05;          // allowed error against the reference, relative to |Pi(0)|: catches
                                    // wrong equations; accuracy itself is judged by the order
};

// Checks each file (invariants, orthogonality and det of O, agreement with the reference) and,
// given several files of the same motion at different step sizes, the convergence order.
// Throws TrajectoryError for unreadable or inconsistent input.
CheckResult check_trajectories(const std::vector<std::string>& files, const TrajectoryCheckOptions& options);

}  // namespace gm::harness
