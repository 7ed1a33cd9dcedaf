// SEAM for the exact elliptic solution of the free rigid body (issue 4, oracle/elliptic.hpp).
//
// golden/generate.cpp calls exact_free_rigid_body() for every free_rigid_body fixture and, when
// it returns samples, records them as one more independent check ("#: check elliptic ...
// max_abs_diff=..."), held to the same agreement as the others. Until the exact solution is
// merged it returns std::nullopt and the free-rigid-body fixtures carry two checks
// (extrapolation, and the closed form for the symmetric top).
//
// To connect it at merge time: implement the function in golden/elliptic_seam.cpp with
// oracle/elliptic.hpp, run `./geomech golden regenerate`, check that the new "#: check elliptic"
// lines show max_abs_diff far below 1e-40, and commit the fixtures together with the change.
#pragma once

#include "core/scalar.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gm::golden {

struct ExactSamples {
  std::string method;                          // e.g. "elliptic"
  std::vector<std::pair<std::string, std::string>> settings;  // written to the check line
  std::vector<std::vector<Real70>> values;     // Pi(t) at each sample time
};

// Pi(t) at `times` for dPi/dt = Pi x I^-1 Pi, Pi(0) = Pi0, in 70 digits; std::nullopt when not
// available (not yet merged, or a case the exact solution does not cover, e.g. exactly on a
// separatrix).
std::optional<ExactSamples> exact_free_rigid_body(const std::array<Real70, 3>& I, const std::array<Real70, 3>& Pi0,
                                                  const std::vector<Real70>& times);

}  // namespace gm::golden
