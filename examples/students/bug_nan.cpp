// Buggy: the energy computed through the direction of Pi, h = |Pi|^2 / 2 (u . I^-1 u) with
// u = Pi / |Pi|, which is 0/0 = NaN at Pi = 0. A NaN never passes: hamiltonian_3_3_is_3_4 fails
// and shrinks to Pi = 0. The square root has no exact rational value, so in rationals
// `geomech check` leaves hamiltonian_3_4 out (it does not compile for Rational) and says why.
#include <geomech/student.hpp>

using namespace gm;

struct EnergyThroughDirection {
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& Pi) {
    using std::sqrt;
    const T norm = sqrt(Pi.dot(Pi));
    const Vec3<T> u = Pi / norm;
    return norm * norm / T(2) * u.dot(u.cwiseQuotient(I));
  }
  template <class T>
  static T hamiltonian_3_3(const Vec3<T>& I, const Vec3<T>& Pi) {
    const Vec3<T> Omega = Pi.cwiseQuotient(I);
    return Pi.dot(Omega) / T(2);
  }
  template <class T>
  static Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cwiseQuotient(I);
  }
};

GEOMECH_STUDENT(EnergyThroughDirection);
