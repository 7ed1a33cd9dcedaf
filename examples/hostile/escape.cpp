// Hostile: code that reaches outside its sandbox. On every call of hat it tries to
// write into the suite's source tree (golden/, found from where it was compiled), into
// /tmp/geomech-hostile-victim (created by the test) and into its working directory's parent; it
// reads /etc/shadow and looks for a network interface (sending nothing). Each attempt that is
// refused is collected, and hat then throws with the list: a submission that needs what the sandbox withholds fails that
// check, and nothing outside the sandbox changes (the test looks).
#include <geomech/student.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <net/if.h>
#include <stdexcept>
#include <string>
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
  // The network, without sending anything anywhere: the interfaces it can see. Any machine has one
  // besides loopback; a sandbox's own network namespace has only its private loopback.
  std::string interfaces;
  if (struct if_nameindex* ifs = ::if_nameindex()) {
    for (auto* i = ifs; i->if_index != 0; ++i)
      if (std::string(i->if_name) != "lo") interfaces += std::string(" ") + i->if_name;
    ::if_freenameindex(ifs);
  }
  if (interfaces.empty()) blocked += " network (no interface but a private loopback);";
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
