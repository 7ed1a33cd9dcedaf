// The exact free-rigid-body solution (oracle/elliptic.hpp) as a third, independent check of the
// free_rigid_body fixtures: Jacobi elliptic functions evaluated in 70 digits, no integration.
#include "golden/elliptic_check.hpp"

#include "oracle/elliptic.hpp"

namespace gm::golden {

std::optional<ExactSamples> exact_free_rigid_body(const std::array<Real70, 3>& I, const std::array<Real70, 3>& Pi0,
                                                  const std::vector<Real70>& times) {
  const oracle::FreeRigidBodySolution<Real70> exact(I, Pi0);
  ExactSamples out;
  out.method = "elliptic";
  out.settings = {{"source", "oracle/elliptic.hpp"}, {"regime", oracle::regime_name(exact.regime())}};
  for (char& c : out.settings.back().second)
    if (c == ' ') c = '_';
  out.values.reserve(times.size());
  for (const Real70& t : times) {
    const auto p = exact(t);
    out.values.push_back({p[0], p[1], p[2]});
  }
  return out;
}

}  // namespace gm::golden
