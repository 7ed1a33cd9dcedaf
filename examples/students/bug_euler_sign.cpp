// Buggy: Euler's equations with the cross product reversed, dPi/dt = Omega x Pi (the notes'
// (3.8) is dPi/dt = Pi x Omega). Caught by euler_form_3_8.
#include <geomech/student.hpp>

using namespace gm;

struct EulerSignError {
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    const Vec3<T> Omega = Pi.cwiseQuotient(I);
    return Omega.cross(Pi);  // the order of the factors is the sign of the whole right-hand side
  }
};

GEOMECH_STUDENT(EulerSignError);
