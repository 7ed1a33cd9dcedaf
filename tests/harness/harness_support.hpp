// What the harness tests of several rooms share: a scratch folder, a verdict by name, a quick
// check configuration.
#pragma once

#include "harness/engine/check.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gm::harness::harness_testing {

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
// callee (harness/engine/first_fix.hpp).
inline void write_omega_and_its_caller(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "manakov_Omega.m") << "function W = manakov_Omega(A, M)\n  W = -M;\nend\n";
  std::ofstream(dir / "manakov_2_34.m")
      << "function d = manakov_2_34(A, M)\n  W = manakov_Omega(A, M);\n  d = M * W - W * M;\nend\n";
}

}  // namespace gm::harness::harness_testing
