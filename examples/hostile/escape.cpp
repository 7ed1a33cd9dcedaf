// Hostile (issue 14): code that reaches outside its sandbox. On every call of hat it tries to
// write into the suite's source tree (golden/, found from where it was compiled), into
// /tmp/geomech-hostile-victim (created by the test), into its working directory's parent, to read
// /etc/shadow and to open a network connection. Each attempt that is refused is collected, and
// hat then throws with the list: a submission that needs what the sandbox withholds fails that
// check, and nothing outside the sandbox changes (the test looks).
#include <geomech/student.hpp>

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <netinet/in.h>
#include <stdexcept>
#include <string>
#include <sys/socket.h>
#include <unistd.h>

using namespace gm;

namespace {
std::string attack() {
  std::string blocked;
  auto try_write = [&](const std::filesystem::path& p) {
    std::ofstream f(p);
    f << "pwned\n";
    if (!f.good()) blocked += " write " + p.string() + ";";
  };
  // Every folder above the place it was compiled in may be the suite's tree: try each one's golden/.
  int refused = 0, tried = 0;
  for (std::filesystem::path dir = std::filesystem::path(__FILE__).parent_path(); dir.has_relative_path();
       dir = dir.parent_path(), ++tried) {
    std::ofstream f(dir / "golden" / "pwned");
    f << "pwned\n";
    if (!f.good()) ++refused;
  }
  if (refused > 0) blocked += " write golden/pwned above the compile folder (" + std::to_string(refused) + " of " + std::to_string(tried) + ");";
  try_write("/tmp/geomech-hostile-victim/pwned");
  try_write("../pwned");
  std::ifstream shadow("/etc/shadow");
  if (!shadow.good()) blocked += " read /etc/shadow;";
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(53);
  ::inet_pton(AF_INET, "1.1.1.1", &a.sin_addr);
  if (s < 0 || ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0)
    blocked += std::string(" connect to 1.1.1.1:53 (") + std::strerror(errno) + ");";
  if (s >= 0) ::close(s);
  return blocked;
}
}  // namespace

struct Escaper {
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    if (const std::string blocked = attack(); !blocked.empty()) throw std::runtime_error("blocked:" + blocked);
    Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
};

GEOMECH_STUDENT(Escaper);
