// A fixture's own consistency, from its file alone: the t = 0 row is the exact initial data
// rounded to the fixture's digits, and every invariant of its system (golden/invariants.hpp)
// takes the same value at every sample. Evaluated in 70 digits.
#pragma once

#include "golden/fixture.hpp"
#include "golden/systems.hpp"

#include <string>
#include <vector>

namespace gm::golden {

struct InvariantDrift {
  std::string name;
  std::string value;     // at t = 0, from the exact initial data (6 digits)
  double max_drift = 0;  // max over samples of |I(x(t_i)) - I(x(0))|
  double allowed = 0;
  std::string worst_time;
};

struct ConsistencyReport {
  std::vector<InvariantDrift> invariants;
  std::vector<std::string> problems;  // each with file:line
  double max_drift = 0;               // over all invariants
  bool ok() const { return problems.empty(); }
};

// Invariant drift allowed for a fixture of `digits` digits: 10^(10 - digits) max(1, |I(0)|)
// (1e-40 for 50-digit fixtures of O(1) invariants: ten digits of room for the rounding of the
// values, amplified by the degree of the invariant, far below any real error).
ConsistencyReport check_consistency(const Fixture& f, const Problem& pr);

}  // namespace gm::golden
