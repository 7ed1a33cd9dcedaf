// Buggy: an off-by-one loop in vee reads past the end of a 3-vector. Eigen's bounds assertion
// aborts the process. Only the properties that call vee end in CRASH; the report still
// completes, with Eigen's message.
#include <geomech/student.hpp>

using namespace gm;

struct OffByOne {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    Vec3<T> v;
    const int row[] = {2, 0, 1, 2}, col[] = {1, 2, 0, 1};
    for (int i = 0; i <= 3; ++i) v(i) = m(row[i], col[i]);  // i = 3 is one too far
    return v;
  }
};

GEOMECH_STUDENT(OffByOne);
