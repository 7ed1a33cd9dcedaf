// Buggy: a correct implementation whose integrator's step cannot be called as the slot expects
// (it takes Pi alone instead of the state {Pi, O}). Its claims cannot be checked, and a claim
// that could not be checked fails the check (UNCHECKED, exit status 1) instead of passing.
#include "correct.hpp"

struct ExplicitEulerPiOnly {
  static constexpr const char* name = "explicit_euler_pi_only";
  static constexpr gm::student::Claims claims{.order = 1};
  template <class T>
  static gm::Vec3<T> rigid_body_step(const gm::Vec3<T>& I, const gm::Vec3<T>& Pi, const T& h) {
    return Pi + h * course::RigidBody::euler_3_8<T>(I, Pi);
  }
};

GEOMECH_STUDENT(course::RigidBody, ExplicitEulerPiOnly);
