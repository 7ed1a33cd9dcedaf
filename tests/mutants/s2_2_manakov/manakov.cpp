// Negative controls for Manakov's equations (2.34) and the Lagrangian of Proposition 2.4.
#include "impl/manakov.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_manakov {

GM_MUTANT(manakov_2_34_commutator_reversed, "(2.34) written dM/dt = [Omega, M]", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_2_34 = [](const MatX<T>& A, const MatX<T>& M) -> MatX<T> { return -ref::manakov_2_34<T>(A, M); };
});

GM_MUTANT(manakov_lagrangian_sign_flipped, "Manakov's Lagrangian written l = +(1/2) tr(Omega A Omega)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_lagrangian = [](const MatX<T>& A, const MatX<T>& W) -> T { return -ref::manakov_lagrangian<T>(A, W); };
});

GM_MUTANT(manakov_M_one_sided, "(2.34) with M = A Omega (the term Omega A forgotten)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.manakov_M = [](const MatX<T>& A, const MatX<T>& W) -> MatX<T> { return A * W; };
});

// The converse of Proposition 2.4 (stationary => solution of (2.34)) needs a Lagrangian that
// depends on Omega: with l constant every curve is stationary, so a curve that does not solve
// (2.34) has delta S = 0 for every variation. The forward direction still holds (delta S = 0 along
// the solution); only the converse assertion of manakov_variational_principle catches it.
GM_MUTANT(manakov_lagrangian_constant, "Manakov's Lagrangian returning a constant (every curve stationary)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.manakov_lagrangian = [](const MatX<T>& A, const MatX<T>&) -> T { return T(A.trace()); };
          });

}  // namespace mutants_manakov
}  // namespace gm
