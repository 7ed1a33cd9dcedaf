// Hostile: a file that does not compile, whose first diagnostic names the sandbox's tool. `#line`
// sets the file name the compiler prints, so its first line of output reads
// "bwrap: Can't find source path ...: ...: error: ...", as bubblewrap's own error would. Whether the
// sandbox started the compiler is bubblewrap's status, not the compiler's words: "does not
// compile" (exit 2), never "the grader's machine" (exit 3).
#line 1 "bwrap: Can't find source path /submission: No such file or directory"
#include <geomech/student.hpp>

using namespace gm;

struct LineBwrap {
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0)) + not_declared_anywhere;
  }
};

GEOMECH_STUDENT(LineBwrap);
