// The exact elliptic solution of the free rigid body (oracle/elliptic.hpp) as a fixture check.
//
// golden/generate.cpp calls exact_free_rigid_body() for every free_rigid_body fixture and records
// the samples as one more independent check ("#: check elliptic regime=... max_abs_diff=..."),
// held to the same agreement rule as the others: the one check that integrates nothing.
#pragma once

#include "core/scalar.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gm::golden {

struct ExactSamples {
  std::string method;                                         // e.g. "elliptic"
  std::vector<std::pair<std::string, std::string>> settings;  // written to the check line
  std::vector<std::vector<Real70>> values;                    // Pi(t) at each sample time
};

// Pi(t) at `times` for dPi/dt = Pi x I^-1 Pi, Pi(0) = Pi0, in 70 digits. oracle/elliptic.hpp has a
// formula for every case (separatrix and tops included), so this always returns samples; the
// optional lets a future system without a closed form decline.
std::optional<ExactSamples> exact_free_rigid_body(const std::array<Real70, 3>& I, const std::array<Real70, 3>& Pi0,
                                                  const std::vector<Real70>& times);

}  // namespace gm::golden
