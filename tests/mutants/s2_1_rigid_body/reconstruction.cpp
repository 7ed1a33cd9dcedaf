// Negative controls for the reconstruction equation (2.10), dO/dt = O Omega_hat.
#include "impl/so3.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_reconstruction {

GM_MUTANT(reconstruction_2_10_right_trivialized, "(2.10) written dO/dt = Omega_hat O (spatial, not body, velocity)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.reconstruction_2_10 = [](const Mat3<T>& O, const Vec3<T>& W) -> Mat3<T> { return ref::hat<T>(W) * O; };
          });

}  // namespace mutants_reconstruction
}  // namespace gm
