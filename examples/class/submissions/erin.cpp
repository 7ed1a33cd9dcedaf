// Week 3, the free rigid body, in C++: function templates on the scalar T (double, 50 digits and
// exact rationals are each checked). Euler's equation (3.8) is written with its cross product
// reversed, Omega x Pi: the first fix is euler_3_8. Manakov's part is not done.
#include <geomech/student.hpp>

using namespace gm;

struct Erin {
  static constexpr const char* description = "Erin: week 3 in C++, (3.8) reversed, no Manakov";

  // (2.11): hat(v) w = v x w, and its inverse.
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
    return m;
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
  // (3.5): Omega = I^-1 Pi.
  template <class T>
  static Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cwiseQuotient(I);
  }
  // (3.8): dPi/dt = Pi x Omega ... written the other way round.
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    return omega_3_5<T>(I, Pi).cross(Pi);
  }
  // (3.4) and the Casimir.
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.dot(omega_3_5<T>(I, Pi)) / T(2);
  }
  template <class T>
  static T casimir(const Vec3<T>& Pi) {
    return Pi.dot(Pi) / T(2);
  }
  // (2.10) and pi = O Pi.
  template <class T>
  static Mat3<T> reconstruction_2_10(const Mat3<T>& O, const Vec3<T>& Omega) {
    return O * hat<T>(Omega);
  }
  template <class T>
  static Vec3<T> spatial_momentum(const Mat3<T>& O, const Vec3<T>& Pi) {
    return O * Pi;
  }
};

GEOMECH_STUDENT(Erin);
