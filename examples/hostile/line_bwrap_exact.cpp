// Hostile: a file that compiles in double, whose exact-arithmetic piece alone does not, with its
// first diagnostic naming the sandbox's tool (`#line` sets the file name the compiler prints; the
// piece is told by the macro the suite compiles it with). A full check compiles that piece too:
// whether the sandbox started the compiler is bubblewrap's status, so the piece is the file's
// ("does not compile in exact"), the rest is checked and graded, never "the grader's machine".
#include <geomech/student.hpp>

#if defined(GEOMECH_STUDENT_ONLY) && GEOMECH_STUDENT_ONLY == 2
#line 1 "bwrap: Can't find source path /submission: No such file or directory"
#error this piece does not compile
#endif

using namespace gm;

struct LineBwrapExact {
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
};

GEOMECH_STUDENT(LineBwrapExact);
