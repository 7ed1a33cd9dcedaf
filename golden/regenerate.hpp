// `geomech golden regenerate [--check]`: every fixture of golden/catalogue.cpp, regenerated.
// Without --check the files are written (each atomically: a temporary file in the same
// directory, then rename; SIGINT/SIGTERM/SIGHUP are held back while files are replaced, so an
// interrupted run leaves every fixture either old or new, never half written). Nothing is
// written unless every fixture was generated and verified.
// With --check nothing is written: each fixture is regenerated in memory and compared byte for
// byte with the committed file; every differing header line and value is listed.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace gm::golden {

struct RegenerateOptions {
  std::string dir;  // default: the source tree's golden/fixtures
  bool check = false;
  std::vector<std::string> only;  // fixture names; empty: all
  bool quiet = false;
  // Without the certificates (golden/certify.hpp): for timing them against the rest, and for a
  // directory other than the committed fixtures (which carry theirs: --check would then differ).
  bool no_certify = false;
};

// Exit status: 0 done (or all equal), 1 a fixture differs or could not be verified, 2 bad input
// (unknown fixture name, unreadable directory).
int regenerate(const RegenerateOptions& o, std::ostream& out, std::ostream& err);

// The differences between a committed fixture text and the regenerated one, one message per
// differing header line or value, each naming `path` and the line.
std::vector<std::string> fixture_differences(const std::string& path, const std::string& committed,
                                             const std::string& regenerated);

// Writes `text` to `path` through a temporary file in the same directory and rename(2); throws
// std::runtime_error (leaving `path` untouched) on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace gm::golden
