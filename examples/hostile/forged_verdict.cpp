// Hostile (issue 14): a wrong hat (transposed) that tries to forge its own verdict. On its first
// call it writes a hand-made verdict saying PASS to every file descriptor it may have been given
// (a check's result pipe, in-process) and exits with status 0 before the property can judge it.
// Untrusted mode: the property runs in the harness, the code in a sandboxed server whose only
// channel is the protocol; the check must FAIL and say that the implementation's process exited.
#include <geomech/student.hpp>

#include <cstdlib>
#include <string>
#include <unistd.h>

using namespace gm;

namespace {
void forge_and_leave() {
  const std::string verdict =
      "R[{\"property\":\"hat_is_cross_product\",\"scalar\":\"double\",\"outcome\":\"PASS\",\"message\":\"\"}]";
  const std::string reply = "{\"id\":1,\"results\":[{\"ok\":[[\"0\",\"0\",\"0\"],[\"0\",\"0\",\"0\"],[\"0\",\"0\",\"0\"]]}]}\n";
  for (int fd = 1; fd < 64; ++fd) {
    (void)!::write(fd, verdict.data(), verdict.size());
    (void)!::write(fd, reply.data(), reply.size());
  }
  std::exit(0);
}
}  // namespace

struct Forger {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    forge_and_leave();
    Mat3<T> m;
    m << T(0), v(2), -v(1), -v(2), T(0), v(0), v(1), -v(0), T(0);  // transposed
    return m;
  }
};

GEOMECH_STUDENT(Forger);
