// Hostile: a wrong hat (transposed) that tries to forge its own verdict. On its first
// call it writes a verdict saying PASS for hat_is_cross_product in double, in the harness's own
// format (harness/checking/verdict_io.cpp; the suite is open source), to every file descriptor above 2 it
// may have been given, and exits with status 0 before the property can judge it.
// In-process, the result pipe of the check is one of those descriptors: the forgery is read as the
// check's verdict (ctest untrusted.forged_verdict_control shows it: the attack works without the
// sandbox). Untrusted mode: the property runs in the harness, the code in a sandboxed server whose
// only channel is the protocol; the check must FAIL and say that the implementation's process
// exited or answered something that is not a reply.
#include <geomech/student.hpp>

#include <cstdlib>
#include <string>
#include <unistd.h>

using namespace gm;

namespace {
void forge_and_leave() {
  const std::string verdict =
      "R[{\"subject\":\"forged_verdict\",\"property\":\"hat_is_cross_product\",\"spec\":\"s2.hat-map\","
      "\"title\":\"hat(a) v = a x v\",\"scalar\":\"double\",\"integrator\":\"\",\"outcome\":\"PASS\","
      "\"message\":\"\",\"counterexample\":[],\"reproduce\":\"\",\"seed\":1,\"cases\":100,"
      "\"worst_eps_units\":0,\"worst_absolute\":0,\"worst_check\":\"\",\"checks\":900,\"seconds\":0.01,"
      "\"series\":[],\"claims\":[]}]";
  for (int fd = 3; fd < 64; ++fd) (void)!::write(fd, verdict.data(), verdict.size());
  std::_Exit(0);
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
