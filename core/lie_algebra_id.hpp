#pragma once

namespace gm {

// The matrix Lie algebras the suite works with: the rigid body's so(3), so(4) with its R^6
// coordinates (SO(4) exercise, section 1), and the non-compact sl(2, R).
enum class LieAlgebraId { so3, so4, sl2 };

inline const char* lie_algebra_name(LieAlgebraId a) {
  switch (a) {
    case LieAlgebraId::so3:
      return "so(3)";
    case LieAlgebraId::so4:
      return "so(4)";
    case LieAlgebraId::sl2:
      return "sl(2,R)";
  }
  return "?";
}

}  // namespace gm
