// Buggy: the rigid-body Hamiltonian written h = (1/2) Pi . I Pi (I instead of I^-1); the
// Legendre transform (3.3) gives h = (1/2) Pi . I^-1 Pi (3.4). Caught by hamiltonian_3_3_is_3_4
// and hamiltonian_gradient_3_5.
#include <geomech/student.hpp>

using namespace gm;

struct HamiltonianWithI {
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.dot(I.cwiseProduct(Pi)) / T(2);
  }
  // (3.3): h = Pi . Omega - l(Omega), with Omega = I^-1 Pi: this one is right.
  template <class T>
  static T hamiltonian_3_3(const Vec3<T>& I, const Vec3<T>& Pi) {
    const Vec3<T> Omega = omega_3_5<T>(I, Pi);
    return Pi.dot(Omega) - Omega.dot(I.cwiseProduct(Omega)) / T(2);
  }
  template <class T>
  static Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cwiseQuotient(I);
  }
};

GEOMECH_STUDENT(HamiltonianWithI);
