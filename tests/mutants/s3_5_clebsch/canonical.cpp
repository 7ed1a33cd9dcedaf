// Negative controls for the canonical Poisson bracket on T*R^3 (section 3.5).
#include "impl/brackets.hpp"
#include "tests/mutants/mutants.hpp"

namespace gm {
namespace mutants_canonical {

GM_MUTANT(canonical_bracket_sign_flipped, "canonical bracket with {q_i, p_j} = -delta_ij", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  s.canonical_bracket = [](const Vec3<T>& fq, const Vec3<T>& fp, const Vec3<T>& hq, const Vec3<T>& hp) -> T {
    return -ref::canonical_bracket<T>(fq, fp, hq, hp);
  };
});

GM_MUTANT(canonical_bracket_symmetric, "canonical bracket written df/dq . dh/dp + df/dp . dh/dq (sign slip)",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.canonical_bracket = [](const Vec3<T>& fq, const Vec3<T>& fp, const Vec3<T>& hq, const Vec3<T>& hp) -> T {
              return fq.dot(hp) + fp.dot(hq);
            };
          });

GM_MUTANT(canonical_bracket_affine_in_df, "canonical bracket plus a stray term sum_j dh/dp_j that does not involve f",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            s.canonical_bracket = [](const Vec3<T>& fq, const Vec3<T>& fp, const Vec3<T>& hq, const Vec3<T>& hp) -> T {
              return ref::canonical_bracket<T>(fq, fp, hq, hp) + hp.sum();
            };
          });

}  // namespace mutants_canonical
}  // namespace gm
