// Buggy, and alone: the momentum map written J = q x p (the notes' J = p x q has the opposite
// sign). Both equivariance statements hold for -J too; definition_momentum_map compares J with
// its definition and catches it.
#include <geomech/student.hpp>

using namespace gm;

struct MomentumMapOnly {
  template <class T>
  static Vec3<T> momentum_map(const Vec3<T>& q, const Vec3<T>& p) {
    return q.cross(p);
  }
};

GEOMECH_STUDENT(MomentumMapOnly);
