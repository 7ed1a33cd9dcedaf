// What the harness tests of several rooms share: a scratch folder, a verdict by name, a quick
// check configuration, a crowded core.
#pragma once

#include "harness/checking/check.hpp"

#include <gtest/gtest.h>

#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gm::harness::harness_testing {

// A machine busier than its cores: `n` processes spinning on the first CPU this process may use,
// with this process (and so the children it forks) pinned there too; undone at the end of scope.
class CrowdedCore {
 public:
  explicit CrowdedCore(int n) {
    ::sched_getaffinity(0, sizeof saved_, &saved_);
    cpu_set_t one;
    CPU_ZERO(&one);
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &saved_)) {
        CPU_SET(c, &one);
        break;
      }
    ::sched_setaffinity(0, sizeof one, &one);
    for (int i = 0; i < n; ++i) {
      const pid_t pid = ::fork();
      if (pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        for (unsigned long x = 0;; ++x) asm volatile("" : "+r"(x));  // spin, not optimised away
      }
      if (pid > 0) burners_.push_back(pid);
    }
  }
  ~CrowdedCore() {
    for (pid_t pid : burners_) ::kill(pid, SIGKILL);
    for (pid_t pid : burners_) ::waitpid(pid, nullptr, 0);
    ::sched_setaffinity(0, sizeof saved_, &saved_);
  }

 private:
  cpu_set_t saved_{};
  std::vector<pid_t> burners_;
};

inline std::filesystem::path temp_dir() {
  std::string t = (std::filesystem::temp_directory_path() / "geomech-harness-XXXXXX").string();
  EXPECT_NE(::mkdtemp(t.data()), nullptr);
  return t;
}

inline const Verdict* find(const CheckResult& r, const std::string& property, const std::string& scalar) {
  for (const auto& v : r.verdicts)
    if (v.property == property && v.scalar == scalar) return &v;
  return nullptr;
}

inline CheckConfig quick(std::vector<std::string> props) {
  CheckConfig c;
  c.properties = std::move(props);
  c.jobs = 3;
  c.timeout_seconds = 1;
  c.portraits = false;
  return c;
}

// An Octave folder in which manakov_Omega is wrong and manakov_2_34 calls it: the first fix is the
// callee (harness/checking/first_fix.hpp).
inline void write_omega_and_its_caller(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "manakov_Omega.m") << "function W = manakov_Omega(A, M)\n  W = -M;\nend\n";
  std::ofstream(dir / "manakov_2_34.m")
      << "function d = manakov_2_34(A, M)\n  W = manakov_Omega(A, M);\n  d = M * W - W * M;\nend\n";
}

}  // namespace gm::harness::harness_testing
