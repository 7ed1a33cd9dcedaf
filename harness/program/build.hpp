// Building a student's check program from one source file, without rebuilding anything of the
// suite: the file is compiled in five pieces in parallel (double in three: its slots in two halves
// and its integrators; mp50; exact; see WholeFile in student/geomech/student.hpp) and linked with the prebuilt driver
// object, the harness and the property library described by the build tree's
// student/toolchain.json.
//
// A scalar whose instantiation does not compile costs only that scalar's checks: the compiler's
// messages are read for the slots they name (gm::student::detail::slot_<name>), those slots are
// left out of that scalar (GEOMECH_SKIP_SLOTS) and it is compiled again; if that does not help,
// the scalar is dropped, with the compiler's first error as the reason. Only double must compile.
//
// Objects and the program are cached per source file (build tree, student-cache/) and rebuilt
// when the source, a header it includes, the toolchain or the prebuilt libraries change.
#pragma once

#include "harness/program/library_flags.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace gm::harness {

struct Toolchain {
  std::string path;  // where it was read from
  std::string cxx;
  std::vector<std::string> flags;       // compile flags (with the suite's sanitizer flags, if any)
  std::vector<std::string> link_flags;  // link flags (the sanitizer runtimes of a sanitized suite)
  std::vector<std::string> includes;
  std::map<std::string, std::string> opt;  // scalar -> optimisation flag
  std::string driver_object;
  std::string server_object;  // main() of the C++ protocol server (untrusted mode); may be absent
  std::string harness_library;
  std::string property_library;
  std::vector<std::string> other_libraries;
  std::string cache_dir;
  // geomech/student.hpp precompiled with the flags above (a .gch beside it); empty or missing:
  // the compiler parses the header, which only costs time.
  std::string precompiled_header;
  // geomech/detail/scalar_selection.hpp, found in the includes: makes a compile register the piece
  // of the file its macros name (GEOMECH_STUDENT_ONLY and the others listed there).
  std::string scalar_selection;
};

// Reads the toolchain description; throws std::runtime_error naming the file and the problem.
Toolchain load_toolchain(const std::string& path);

// The toolchain of the build tree this program belongs to (../student/toolchain.json relative
// to the executable, or $GEOMECH_TOOLCHAIN).
std::string default_toolchain_path();

struct BuildOptions {
  int jobs = 2;           // compilers at once
  std::string name;       // implementation name (default: the file's stem)
  std::string cache_dir;  // default: the toolchain's
  bool verbose = false;   // print each command
  bool force = false;     // ignore the cache
  bool mp50 = true;       // compile the 50-digit instantiation (double is always compiled)
  bool exact = true;      // compile the exact-rational instantiation
  // Why mp50 and exact are not compiled when they are not (the reports' words); empty: "--scalar".
  std::string scalars_left_out_because;
  bool integrators = true;   // compile the integrators (a first look, which checks the slots alone, does not)
  bool fast_link = false;    // link with lld or gold when found (a first look; see fast_linker_option)
  bool server = false;       // link the protocol server (untrusted mode) instead of the check program
  bool sandbox = false;      // compile and link inside the sandbox, from a copy of the source
  std::string program_name;  // the linked program's file name (default "check", or "server")
  // Every compile and link stops after this long (a file may include /dev/zero, or a
  // template recursion may not end); the message says so.
  double compile_timeout_seconds = 900;
  // Libraries from the command line (--pkg, --cxxflags, --ldflags, -I, -L, -l); the file's own
  // `// geomech:` lines are added to them (harness/program/library_flags.hpp). Vetted when sandboxed.
  LibraryRequest libraries;
};

struct BuildResult {
  bool ok = false;      // a program was produced
  std::string program;  // the check program
  std::string name;
  std::string source;   // absolute path of the source
  std::string message;  // when !ok: what went wrong, with the compiler's output
  // When !ok because the sandbox could not start the compiler or the linker (bubblewrap's own
  // error, such as a cache folder its user cannot reach): the grader's set-up, not the file; the
  // message says what and the fix. Empty otherwise.
  std::string machine_fault;
  bool does_not_compile = false;  // when !ok because the double instantiation does not compile
  nlohmann::json notes;           // scalar_unavailable, slot_notes, warnings (for --build-notes)
  std::string notes_file;         // where the notes were written
  double seconds = 0;
  bool cached = false;           // nothing needed compiling
  std::vector<std::string> log;  // one line per compiler run, for the user
};

BuildResult build_student(const std::string& source, const Toolchain& tc, const BuildOptions& options);

// Slots named in the instantiation backtraces of compiler errors, each with its first error
// message (exposed for tests).
std::map<std::string, std::string> slots_failing_in(const std::string& compiler_output);
bool integrators_failing_in(const std::string& compiler_output);
std::string first_error(const std::string& compiler_output);
std::string hint_for(const std::string& error, const std::string& scalar);

}  // namespace gm::harness
