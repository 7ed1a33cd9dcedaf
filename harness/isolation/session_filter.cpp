#include "harness/isolation/session_filter.hpp"

#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/syscall.h>
#include <cerrno>
#include <cstddef>
#include <vector>

namespace gm::harness {

std::string no_new_session_filter() {
  // The architecture a call is made in, then its number: setsid in this program's own
  // architecture (and, on x86-64, in its 32-bit and x32 forms, which a program may use as well)
  // fails with EPERM; every other call is let through.
  const unsigned arch_at = offsetof(struct seccomp_data, arch), nr_at = offsetof(struct seccomp_data, nr);
  const unsigned deny = SECCOMP_RET_ERRNO | (EPERM & SECCOMP_RET_DATA), allow = SECCOMP_RET_ALLOW;
  std::vector<sock_filter> p;
  auto stmt = [&](unsigned short code, unsigned k) { p.push_back(sock_filter{code, 0, 0, k}); };
  auto jump = [&](unsigned short code, unsigned k, unsigned char jt, unsigned char jf) {
    p.push_back(sock_filter{code, jt, jf, k});
  };
#if defined(__x86_64__)
  stmt(BPF_LD | BPF_W | BPF_ABS, arch_at);
  jump(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 0, 4);
  stmt(BPF_LD | BPF_W | BPF_ABS, nr_at);
  jump(BPF_JMP | BPF_JEQ | BPF_K, SYS_setsid, 6, 0);
  jump(BPF_JMP | BPF_JEQ | BPF_K, 0x40000000u | SYS_setsid, 5, 0);  // x32
  stmt(BPF_RET | BPF_K, allow);
  jump(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_I386, 0, 2);
  stmt(BPF_LD | BPF_W | BPF_ABS, nr_at);
  jump(BPF_JMP | BPF_JEQ | BPF_K, 66, 1, 0);  // setsid in i386's table
  stmt(BPF_RET | BPF_K, allow);
  stmt(BPF_RET | BPF_K, deny);
#else
  stmt(BPF_LD | BPF_W | BPF_ABS, nr_at);
  jump(BPF_JMP | BPF_JEQ | BPF_K, SYS_setsid, 0, 1);
  stmt(BPF_RET | BPF_K, deny);
  stmt(BPF_RET | BPF_K, allow);
  (void)arch_at;
#endif
  return std::string(reinterpret_cast<const char*>(p.data()), p.size() * sizeof(sock_filter));
}

}  // namespace gm::harness
