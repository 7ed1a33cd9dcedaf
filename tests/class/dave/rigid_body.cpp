// Class-mode test implementation in its own folder, with a header of its own.
#include "so3.hpp"

using namespace gm;

struct Dave {
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    return dave::cross<T>(Pi, Pi.cwiseQuotient(I));
  }
};

GEOMECH_STUDENT(Dave);
