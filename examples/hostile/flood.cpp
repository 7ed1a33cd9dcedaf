// Hostile: hat prints without end to stdout and stderr; Euler's equations (3.8) fill
// the scratch disk with one ever-growing file. In untrusted mode the printing goes to a pipe the
// harness does not drain (it blocks: hat's properties end in TIMEOUT), the file stops at the
// sandbox's file-size limit (the server is killed by SIGXFSZ: FAIL, saying so), and vee, which is
// correct, still passes.
#include <geomech/student.hpp>

#include <cstdio>
#include <string>

using namespace gm;

struct Flood {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    const std::string block(1 << 20, 'x');
    for (;;) {
      std::fwrite(block.data(), 1, block.size(), stdout);
      std::fwrite(block.data(), 1, block.size(), stderr);
    }
    Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    const std::string block(1 << 20, 'x');
    if (std::FILE* f = std::fopen("/tmp/fill", "w")) {
      while (std::fwrite(block.data(), 1, block.size(), f) == block.size()) std::fflush(f);
      std::fclose(f);
    }
    return Pi.cross(Vec3<T>(Pi.cwiseQuotient(I)));
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
};

GEOMECH_STUDENT(Flood);
