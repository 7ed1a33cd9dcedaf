// The libraries a student's (or a researcher's) C++ file uses, and the compile and link flags they
// need: from the command line (`--pkg NAME`, `--cxxflags`, `--ldflags`, `-I`, `-l`,
// `-L`) and from the file itself, one comment line per request:
//
//   // geomech: pkg ode
//   // geomech: cxxflags -DUSE_FAST_PATH -I/usr/include/bullet
//   // geomech: ldflags -lm
//
// (`pkg` names are looked up with pkg-config: its --cflags and --libs.) In untrusted and class
// mode the file is a stranger's, so its flags (and what pkg-config gives for its package names)
// are vetted before a sandboxed compiler sees them: only -D, -U, -I/-isystem folders under the
// system's include folders (/usr/include), -L folders under the system's library folders (/usr/lib,
// /lib), or under a folder the grader trusts (GEOMECH_LIBRARY_ROOTS), -l, -pthread and warning switches (-W...) pass; anything else is refused with its reason
// (an @file reads the host's files, -B and -wrapper run programs of the host, -fplugin loads code
// into the compiler, -specs rewrites the driver's commands, a folder outside the system's is the
// host's). Your own file, checked in-process, may use any flag.
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

struct LibraryRequest {
  std::vector<std::string> pkgs;      // pkg-config names
  std::vector<std::string> cxxflags;  // compile flags, one word each
  std::vector<std::string> ldflags;   // link flags, one word each
  bool empty() const { return pkgs.empty() && cxxflags.empty() && ldflags.empty(); }
  void add(const LibraryRequest& other);
};

// The `// geomech: pkg|cxxflags|ldflags ...` lines of a source text. Throws std::invalid_argument
// naming the line for a `// geomech:` line that is none of these.
LibraryRequest declared_in_source(const std::string& text, const std::string& file_name);

// Splits a flag string as a shell would split words (quotes and backslashes; no expansion).
std::vector<std::string> split_flags(const std::string& text);

struct LibraryFlags {
  std::vector<std::string> compile;  // after the suite's compile flags
  std::vector<std::string> link;     // after the objects and the suite's libraries
  std::vector<std::string> pkgs;     // what was asked, for the report and the cache
  // What was left out of pkg-config's --cflags, each with why: a language standard (the suite
  // compiles in C++20: a -std=c++11 after it breaks the suite's own headers), an optimisation or a
  // warning switch (the suite sets its own). Said under --verbose.
  std::vector<std::string> dropped;
};

// The flags of a request: pkg-config's for each package, then the explicit ones. A package or a
// flag asked twice (on the command line and in the file) counts once; folders are given canonical
// (/usr/lib/x86_64-linux-gnu/pkgconfig/../../../include is /usr/include); pkg-config's standard,
// optimisation and warning switches are dropped (LibraryFlags::dropped). `stranger`: vet every flag
// (above). Throws std::invalid_argument with every refusal and its reason, or with
// pkg-config's message for a package it does not know.
LibraryFlags resolve_library_flags(const LibraryRequest& request, bool stranger);

// The folders a grader trusts for strangers' builds beside the system's: GEOMECH_LIBRARY_ROOTS, absolute
// folders separated by ':' (an engine installed for a class under /opt/engine). -I and -L under them
// pass the vetting, and the sandboxes of the compile and of the check show them read-only. Throws
// std::invalid_argument for a relative path, a folder that does not exist, or '/'.
std::vector<std::string> trusted_library_roots();
// The root to suggest for a refused folder: PREFIX for PREFIX/include/... or PREFIX/lib/...
std::string library_root_of(const std::string& dir);

// Why a compile that failed on a missing header might want a package: for "fatal error: X: No such
// file or directory", the packages whose include folders hold X ("--pkg eigen3"), or the general
// advice; empty when the compiler output names no missing header.
std::string missing_header_hint(const std::string& compiler_output);

}  // namespace gm::harness
