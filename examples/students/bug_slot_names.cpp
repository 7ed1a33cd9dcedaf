// Buggy: right formulas under the wrong names. `energy`, `euler` and `omega35` are not slot
// names, so nothing is checked; the check says NOTHING CHECKED (exit status 1) instead of PASS,
// and names the slot each function probably means.
#include <geomech/student.hpp>

using namespace gm;

struct WrongNames {
  template <class T>
  static T energy(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.dot(Pi.cwiseQuotient(I)) / T(2);
  }
  template <class T>
  static Vec3<T> euler(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cross(Pi.cwiseQuotient(I));
  }
  template <class T>
  static Vec3<T> omega35(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cwiseQuotient(I);
  }
};

GEOMECH_STUDENT(WrongNames);
