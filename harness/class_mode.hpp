// Class mode: a folder of implementations checked in parallel, one report per implementation and
// one summary table (implementation x area of the notes).
//
// Implementations are the *.cpp, *.py and *.m files directly in the folder (Python and Octave run
// through docs/PROTOCOL.md), and each sub-folder holding exactly
// one .cpp that uses GEOMECH_STUDENT (a student's own folder, with headers beside it). Each is
// built and checked in its own process, `jobs` at a time; a student whose code does not compile,
// crashes or hangs gets a row saying so, and the others are unaffected.
#pragma once

#include "harness/build.hpp"
#include "harness/cli.hpp"

#include <string>
#include <vector>

namespace gm::harness {

struct ClassOptions {
  std::string dir;
  std::string report_dir;          // default: geomech-reports/<folder name>
  int jobs = 2;                    // implementations at once
  double timeout_per_implementation = 1800;
  std::string front_door;          // how to call geomech in printed commands (e.g. "./geomech")
  CheckCliOptions check;           // forwarded to every implementation's check
  BuildOptions build;              // how each implementation is compiled (jobs is set to 1)
};

struct Implementation {
  std::string name;    // unique within the class (file stem, or folder name)
  std::string source;  // the .cpp to compile
};

// The implementations of a class folder, sorted by name; throws std::runtime_error when the
// folder cannot be read or holds none.
std::vector<Implementation> find_implementations(const std::string& dir);

int run_class(const ClassOptions& o, const Toolchain& tc);

}  // namespace gm::harness
