// Class-mode test implementation: does not compile (a missing semicolon).
#include <geomech/student.hpp>

using namespace gm;

struct Carol {
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0))
  }
};

GEOMECH_STUDENT(Carol);
