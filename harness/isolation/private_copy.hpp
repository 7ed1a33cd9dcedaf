// A submission's private read-only copy for the sandbox.
//
// Untrusted mode shows a submission to its sandbox under neutral names: its file (or its folder of
// .m files) as /submission/<name>, and the suite's files it needs (the protocol server) as
// /geomech/<name>. They are copied first into a fresh folder that the sandbox's user can read, so
// that
//   - a class kept in a private folder (mode 0700, as `mktemp -d` makes it) is checked like any
//     other when the harness runs as root (the sandbox runs as nobody, who cannot enter it);
//   - nothing inside, not even the program's own command line, names a folder of this machine;
//   - every language gets the same treatment (a C++ submission's server program is copied too).
// The copy is removed when the object goes.
#pragma once

#include "harness/isolation/submission_intake.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

class PrivateCopy {
 public:
  // Throws std::runtime_error, naming the path, when a file cannot be read or copied.
  PrivateCopy();
  ~PrivateCopy();
  PrivateCopy(const PrivateCopy&) = delete;
  PrivateCopy& operator=(const PrivateCopy&) = delete;

  // Copies a file, or a folder's regular files and sub-folders, under `area` ("submission" or
  // "geomech"); returns the path inside the sandbox, /<area>/<file name>. The "submission" area is
  // a stranger's: read without following any link, never opening a FIFO or device, within limits
  // (harness/isolation/submission_intake.hpp; a refusal throws RefusedEntry naming the entry). The suite's
  // own files ("geomech") are copied as they are (a link among them is left out).
  // `max_bytes`: the largest file of the "submission" area (IntakeLimits::file_bytes; a program
  // built from a submission: IntakeLimits::program_bytes).
  std::string add(const std::string& path, const std::string& area,
                  std::uint64_t max_bytes = IntakeLimits{}.file_bytes);

  // The --ro-bind pairs for SandboxSpec::mounts: each area's folder here and its path inside.
  std::vector<std::pair<std::string, std::string>> mounts() const;

 private:
  std::filesystem::path folder_path(const std::string& area) const;
  std::string root_;  // the fresh folder here (mode 0711)
  std::vector<std::string> areas_;
};

}  // namespace gm::harness
