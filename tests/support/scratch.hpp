// A test's own scratch folder and files in it (the tests that write a class folder or a source).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace gm::testing_support {

// An empty folder <tmp>/geomech-<prefix>-<pid>-<name>, made anew on each call.
inline std::filesystem::path scratch_folder(const std::string& prefix, const std::string& name) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("geomech-" + prefix + "-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

// Writes `text` to `p`, making its folder first.
inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

}  // namespace gm::testing_support
