// Negative controls for Noether's theorem for the rigid body (Theorem 2.2, (2.29)-(2.30)).
#include "impl/euler.hpp"
#include "impl/momentum_map.hpp"
#include "impl/reconstruction.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_noether {

// A function that is trivially "conserved": constancy along the flow alone cannot tell it from
// pi = O Pi; noether_spatial_momentum_conserved also compares it with O(0) Pi(0).
GM_MUTANT(spatial_momentum_constant, "spatial momentum returning the constant vector (1, 0, 0)", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.spatial_momentum = [](const Mat3<T>&, const Vec3<T>&) -> Vec3<T> { return Vec3<T>(T(1), T(0), T(0)); };
});

}  // namespace mutants_noether
}  // namespace gm

namespace gm {
namespace mutants_noether {

// An error shared by the two systems of Remark 3.3: (3.8), (2.10) and (3.21) all with the
// opposite sign (the motion run backwards in time). The two flows still agree with each other
// (P x Q = Pi, Q = O^-1 Q(0)); only the comparison with the suite's oracle catches it.
GM_MUTANT(rigid_body_and_clebsch_time_reversed, "(3.8), (2.10) and (3.21) all with the opposite sign (motion reversed)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.euler_3_8 = [](const Vec3<T>& I, const Vec3<T>& Pi) -> Vec3<T> { return -ref::euler_3_8<T>(I, Pi); };
            s.reconstruction_2_10 = [](const Mat3<T>& O, const Vec3<T>& W) -> Mat3<T> {
              return -ref::reconstruction_2_10<T>(O, W);
            };
            s.clebsch_3_21 = [](const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) -> Vec3Pair<T> {
              const auto d = ref::clebsch_3_21<T>(I, Q, P);
              return {-d.first, -d.second};
            };
          });

}  // namespace mutants_noether
}  // namespace gm
