// Buggy: the attitude reconstructed as dO/dt = hat(Omega) O. That is the right-invariant form,
// in which Omega would be the spatial angular velocity; the notes' (2.10) is dO/dt = O hat(Omega)
// with the body angular velocity. Caught by reconstruction_is_left_invariant.
#include <geomech/student.hpp>

using namespace gm;

struct ReconstructionOnTheLeft {
  template <class T>
  static Mat3<T> reconstruction_2_10(const Mat3<T>& O, const Vec3<T>& Omega) {
    Mat3<T> W;
    W << T(0), -Omega(2), Omega(1), Omega(2), T(0), -Omega(0), -Omega(1), Omega(0), T(0);
    return W * O;
  }
};

GEOMECH_STUDENT(ReconstructionOnTheLeft);
