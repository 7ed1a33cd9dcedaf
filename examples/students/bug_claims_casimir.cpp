// Buggy claims: the explicit Euler method, Pi <- Pi + h Pi x Omega, O <- O + h O hat(Omega), is
// first order and preserves neither |Pi|^2 (|Pi|^2 grows by h^2 |Pi x Omega|^2 every step) nor
// the orthogonality of O, yet it claims both. The integrator-claim properties report the
// Casimir and orthogonality claims as FALSE CLAIM; the order claim (1) holds.
#include <geomech/student.hpp>

using namespace gm;

struct ExplicitEuler {
  static constexpr const char* name = "explicit_euler";
  static constexpr gm::student::Claims claims{.order = 1, .casimir = true, .orthogonality = true};

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Vec3<T> Omega = x.Pi.cwiseQuotient(I);
    Mat3<T> W;
    W << T(0), -Omega(2), Omega(1), Omega(2), T(0), -Omega(0), -Omega(1), Omega(0), T(0);
    return {x.Pi + h * x.Pi.cross(Omega), x.O + h * x.O * W};
  }
};

struct Nothing {};

GEOMECH_STUDENT(Nothing, ExplicitEuler);
