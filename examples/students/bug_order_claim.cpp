// Buggy claims: a Lie-Trotter splitting (the three exact rotations of Pi_i^2 / (2 I_i), one
// after the other, each for the full step) is a first-order, non-symmetric Poisson integrator;
// it claims order 2 and symmetry. The integrator-claim properties report the order and
// symmetry claims as FALSE CLAIM; the Casimir, orthogonality and Poisson claims hold.
#include <geomech/student.hpp>

#include <cmath>

using namespace gm;

struct LieTrotter {
  static constexpr const char* name = "lie_trotter";
  static constexpr gm::student::Claims claims{
      .order = 2, .symmetric = true, .casimir = true, .orthogonality = true, .poisson = true};

  // Rotation by `angle` about coordinate axis `a`.
  template <class T>
  static Mat3<T> rotation(int a, const T& angle) {
    using std::cos;
    using std::sin;
    Mat3<T> R = Mat3<T>::Identity();
    const int j = (a + 1) % 3, k = (a + 2) % 3;
    R(j, j) = cos(angle);
    R(k, k) = cos(angle);
    R(j, k) = -sin(angle);
    R(k, j) = sin(angle);
    return R;
  }

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x0, const T& h) {
    RigidBodyState<T> x = x0;
    for (int a = 0; a < 3; ++a) {
      const T angle = h * x.Pi(a) / I(a);
      x.Pi = rotation<T>(a, -angle) * x.Pi;
      x.O = x.O * rotation<T>(a, angle);
    }
    return x;
  }
};

struct Nothing {};

GEOMECH_STUDENT(Nothing, LieTrotter);
