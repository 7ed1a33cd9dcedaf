// Buggy, but faithful to the notes: the spatial angular momentum exactly as printed in (2.30),
// pi = O^-1 Pi O, which for vectors reads pi = O^T Pi. (2.30) is a recorded erratum: what Noether's
// theorem conserves is pi = O Pi. The failure says that the result is the printed formula and
// names the erratum, so a student who followed the notes knows why.
#include <geomech/student.hpp>

using namespace gm;

struct NoetherAsPrinted {
  template <class T>
  static Vec3<T> spatial_momentum(const Mat3<T>& O, const Vec3<T>& Pi) {
    return O.transpose() * Pi;
  }
};

GEOMECH_STUDENT(NoetherAsPrinted);
