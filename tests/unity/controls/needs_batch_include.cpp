// Control for tests/unity/compiles_alone.py (must fail): this file calls the long-time energy
// classifier of properties/integrators/support/long_time.hpp without including it, as a file can when a file
// before it in its unity batch includes that header. Compiled alone, `longtime` is undeclared.
#include "properties/registry.hpp"

#include <vector>

namespace gm {
namespace controls_needs_batch_include {
namespace {

template <class T>
bool drifting(const std::vector<double>& t, const std::vector<T>& e) {
  return longtime::classify_energy_error(t, e, 0.0, 0.0).kind == longtime::EnergyKind::Gaining;
}

}  // namespace
}  // namespace controls_needs_batch_include
}  // namespace gm
