// SEAM(elliptic): see golden/elliptic_seam.hpp. Replace the body with the exact solution of
// oracle/elliptic.hpp (issue 4) at merge time.
#include "golden/elliptic_seam.hpp"

namespace gm::golden {

std::optional<ExactSamples> exact_free_rigid_body(const std::array<Real70, 3>& /*I*/,
                                                  const std::array<Real70, 3>& /*Pi0*/,
                                                  const std::vector<Real70>& /*times*/) {
  return std::nullopt;  // SEAM(elliptic): the exact solution is not merged yet
}

}  // namespace gm::golden
