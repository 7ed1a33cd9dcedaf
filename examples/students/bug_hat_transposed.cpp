// Buggy: the hat map with the transposed convention, hat(v) w = w x v, and a vee that inverts
// it (so vee(hat(v)) = v still holds and hides the mistake). Caught by hat_is_cross_product and
// hat_is_lie_algebra_isomorphism: (2.11) fixes hat(v) w = v x w.
#include <geomech/student.hpp>

using namespace gm;

struct HatTransposed {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), v(2), -v(1),  //
        -v(2), T(0), v(0),   //
        v(1), -v(0), T(0);
    return m;
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(1, 2), m(2, 0), m(0, 1));
  }
};

GEOMECH_STUDENT(HatTransposed);
