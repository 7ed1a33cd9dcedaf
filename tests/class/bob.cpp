// Class-mode test implementation: the hat map with a sign error (it is the transpose).
#include <geomech/student.hpp>

using namespace gm;

struct Bob {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), v(2), -v(1), -v(2), T(0), v(0), v(1), -v(0), T(0);
    return m;
  }
};

GEOMECH_STUDENT(Bob);
