// A research group's implementation of a few slots, checked by the installed suite.
#include <geomech/student.hpp>

using namespace gm;

struct MyRigidBody {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
    return m;
  }
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.cross(Pi.cwiseQuotient(I));
  }
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.dot(Pi.cwiseQuotient(I)) / T(2);
  }
  template <class T>
  static T casimir(const Vec3<T>& Pi) {
    return Pi.dot(Pi) / T(2);
  }
};

GEOMECH_STUDENT(MyRigidBody);
