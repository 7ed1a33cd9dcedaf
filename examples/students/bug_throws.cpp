// Buggy: a function left as a stub that throws. Its property fails with the exception's message
// (an exception is a failure, not a crash); the rest is checked.
#include <geomech/student.hpp>

#include <stdexcept>

using namespace gm;

struct Unfinished {
  template <class T>
  static T lagrangian_2_5(const Vec3<T>& I, const Vec3<T>& W) {
    return W.dot(I.cwiseProduct(W)) / T(2);
  }
  template <class T>
  static T lagrangian_2_13(const Vec3<T>&, const Mat3<T>&) {
    throw std::logic_error("lagrangian_2_13: not written yet");
  }
};

GEOMECH_STUDENT(Unfinished);
