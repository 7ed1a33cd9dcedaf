// geomech: cxxflags -I/root -B/tmp -wrapper,/bin/sh -fplugin=/tmp/plugin.so -specs=/tmp/evil.specs
// geomech: cxxflags @/etc/os-release -I/usr/include/../../root
// geomech: ldflags -L/root -Wl,--script=/tmp/evil.ld -l/etc/shadow
//
// A submission whose own `// geomech:` lines ask for compiler and linker flags that would read this
// machine's files or run its programs from inside the sandboxed compile. In untrusted and
// class mode each is refused, with its reason, and the file is not compiled; the same lines in your own
// file, checked in-process, would be passed on (harness/program/library_flags.hpp).
#include <geomech/student.hpp>

struct EscapeFlags {
  template <class T>
  static gm::Mat3<T> hat(const gm::Vec3<T>& v) {
    gm::Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
};

GEOMECH_STUDENT(EscapeFlags);
