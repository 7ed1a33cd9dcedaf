// Hostile: Euler's equations (3.8) with a fork bomb inside. In untrusted mode the
// sandbox's process limit stops the forking, the property ends in TIMEOUT when the bomb's
// processes keep spinning, and all of them die with the sandbox; vee, which is correct, still
// passes.
#include <geomech/student.hpp>

#include <unistd.h>

using namespace gm;

struct ForkBomb {
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    for (;;) (void)::fork();
    return Pi.cross(Vec3<T>(Pi.cwiseQuotient(I)));
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
};

GEOMECH_STUDENT(ForkBomb);
