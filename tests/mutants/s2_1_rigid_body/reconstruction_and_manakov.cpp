// Negative controls for the pointwise reconstruction formula (2.10) and Manakov's Omega (2.34).
#include "impl/manakov.hpp"
#include "impl/reconstruction.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_reconstruction_and_manakov {

GM_MUTANT(reconstruction_right_invariant,
          "reconstruction written dO/dt = hat(Omega) O (right-invariant: Omega taken as the spatial angular velocity)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.reconstruction_2_10 = [](const Mat3<T>& O, const Vec3<T>& W) -> Mat3<T> { return ref::hat<T>(W) * O; };
          });

GM_MUTANT(manakov_Omega_as_if_commuting,
          "Omega recovered from M = A Omega + Omega A as A^-1 M / 2, as if A and Omega commuted", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.manakov_Omega = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> {
              return (A.fullPivLu().solve(M) / T(2)).eval();
            };
          });

}  // namespace mutants_reconstruction_and_manakov
}  // namespace gm
