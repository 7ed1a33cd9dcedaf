// Buggy, and alone: the Lie-Poisson bracket (3.6) with the wrong sign, {f, h} = +Pi . df x dh.
// Minus a Poisson bracket is a Poisson bracket: bilinearity, skew-symmetry, Leibniz and Jacobi all
// hold, so the axioms pass; only the comparison with (3.6) itself fails.
#include <geomech/student.hpp>

using namespace gm;

struct BracketOnly {
  template <class T>
  static T lie_poisson_3_6(const Vec3<T>& Pi, const Vec3<T>& df, const Vec3<T>& dh) {
    return Pi.dot(df.cross(dh));
  }
};

GEOMECH_STUDENT(BracketOnly);
