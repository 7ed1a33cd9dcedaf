// Buggy: (2.1) solved for I dOmega/dt instead of dOmega/dt (the division by I1, I2, I3 was
// forgotten). Caught by euler_form_2_1.
#include <geomech/student.hpp>

using namespace gm;

struct EulerWithoutDivision {
  template <class T>
  static Vec3<T> euler_2_1(const Vec3<T>& I, const Vec3<T>& W) {
    return Vec3<T>((I(1) - I(2)) * W(1) * W(2), (I(2) - I(0)) * W(2) * W(0), (I(0) - I(1)) * W(0) * W(1));
  }
};

GEOMECH_STUDENT(EulerWithoutDivision);
