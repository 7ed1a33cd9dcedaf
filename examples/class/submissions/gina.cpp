// Week 3 in C++, handed in without compiling it: a semicolon is missing. The summary says DOES NOT
// COMPILE with the compiler's first error, the grade is 0, and the other students are unaffected.
#include <geomech/student.hpp>

using namespace gm;

struct Gina {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0)
    return m;
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
};

GEOMECH_STUDENT(Gina);
