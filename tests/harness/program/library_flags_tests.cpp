// The libraries of a C++ file (harness/program/library_flags.hpp): the file's own `// geomech:`
// lines, pkg-config, the vetting of a stranger's flags (and its control: your own file's flags pass
// unvetted), and the hint for a missing header.
#include "harness/program/library_flags.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

namespace gm::harness {
namespace {

namespace fs = std::filesystem;

TEST(LibraryFlags, AFileDeclaresItsLibrariesInCommentLines) {
  const LibraryRequest r = declared_in_source(
      "// geomech: pkg ode\n  //geomech: cxxflags -DFAST \"-DNAME=a b\"\n// geomech: ldflags -lm\nint x;  // geomech: "
      "pkg no\n",
      "mine.cpp");
  EXPECT_EQ(r.pkgs, (std::vector<std::string>{"ode"}));
  EXPECT_EQ(r.cxxflags, (std::vector<std::string>{"-DFAST", "-DNAME=a b"}));
  EXPECT_EQ(r.ldflags, (std::vector<std::string>{"-lm"}));
  try {
    declared_in_source("\n// geomech: link ode\n", "mine.cpp");
    FAIL() << "an unknown request was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mine.cpp:2: `// geomech: link` is not a request the suite knows"),
              std::string::npos)
        << e.what();
  }
}

TEST(LibraryFlags, PkgConfigGivesAPackagesFlagsAndNamesAnUnknownOne) {
  LibraryRequest r;
  r.pkgs = {"ode"};  // libode-dev, which ./geomech installs
  const LibraryFlags f = resolve_library_flags(r, true);
  EXPECT_NE(std::find(f.link.begin(), f.link.end(), "-lode"), f.link.end());
  r.pkgs = {"no-such-package-here"};
  try {
    resolve_library_flags(r, false);
    FAIL() << "an unknown package was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--pkg no-such-package-here: pkg-config does not know it"), std::string::npos)
        << e.what();
  }
}

TEST(LibraryFlags, AStrangersFlagsAreVettedYoursAreNot) {
  LibraryRequest r;
  r.cxxflags = {"-DOK=1",
                "-I/usr/include/ode",
                "-Wall",
                "-I/root",
                "@/etc/os-release",
                "-B/tmp",
                "-wrapper,/bin/sh",
                "-fplugin=/tmp/p.so",
                "-specs=/tmp/s",
                "-I/usr/include/../../etc",
                "-include",
                "/etc/passwd"};
  r.ldflags = {"-lode", "-L/usr/lib/x86_64-linux-gnu", "-L/home", "-Wl,-T,/tmp/x.ld", "-l/etc/shadow"};
  try {
    resolve_library_flags(r, true);
    FAIL() << "a stranger's flags passed";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    for (const char* refused : {"'-I/root'", "'@/etc/os-release'", "'-B/tmp'", "'-wrapper,/bin/sh'",
                                "'-fplugin=/tmp/p.so'", "'-specs=/tmp/s'", "'-I/usr/include/../../etc'", "'-include'",
                                "'-L/home'", "'-Wl,-T,/tmp/x.ld'", "'-l/etc/shadow'"})
      EXPECT_NE(m.find(refused), std::string::npos) << refused << " was not refused:\n" << m;
    for (const char* passed :
         {"'-DOK=1'", "'-I/usr/include/ode'", "'-Wall'", "'-lode'", "'-L/usr/lib/x86_64-linux-gnu'"})
      EXPECT_EQ(m.find(passed), std::string::npos) << passed << " was refused:\n" << m;
  }
  // The control: the same flags for your own file (in-process, no sandbox) are passed on as given.
  const LibraryFlags mine = resolve_library_flags(r, false);
  EXPECT_EQ(mine.compile, r.cxxflags);
  EXPECT_EQ(mine.link, r.ldflags);
}

// A library's flags are read, not pasted: pkg-config's language standard (a dependency's -std=c++11
// after the suite's -std=c++20 broke the suite's own headers), optimisation and warning switches are
// left out and said; a package asked twice (on the command line and in the file) gives its flags
// once; a stranger's folders reach the sandbox canonical. The control: your own flags as given.
TEST(LibraryFlags, APackagesFlagsAreReadNotPasted) {
  const fs::path dir = fs::temp_directory_path() / "geomech-pc-test";
  fs::create_directories(dir / "lib" / "pkgconfig");
  std::ofstream(dir / "lib" / "pkgconfig" / "engine.pc")
      << "prefix=/usr\nName: engine\nDescription: a library-shaped example\nVersion: 1\n"
         "Cflags: -std=c++11 -O2 -Wall -DENGINE=1 -I${pcfiledir}/../../../../usr/include/eigen3\nLibs: -lm -lm\n";
  ::setenv("PKG_CONFIG_PATH", (dir / "lib" / "pkgconfig").c_str(), 1);
  LibraryRequest r;
  r.pkgs = {"engine", "engine"};
  const LibraryFlags f = resolve_library_flags(r, true);
  ::unsetenv("PKG_CONFIG_PATH");
  EXPECT_EQ(std::set<std::string>(f.compile.begin(), f.compile.end()),
            (std::set<std::string>{"-DENGINE=1", "-I/usr/include/eigen3"}));
  EXPECT_EQ(f.link, (std::vector<std::string>{"-lm"}));
  ASSERT_EQ(f.dropped.size(), 3u);
  EXPECT_NE(f.dropped[0].find("'-std=c++11' from pkg-config --cflags engine: the suite compiles in its own standard"),
            std::string::npos)
      << f.dropped[0];
  // Two precisions of one library are alternatives: refused together, naming both.
  r.pkgs = {"engine", "engine-float64"};
  try {
    resolve_library_flags(r, false);
    FAIL() << "two builds of one library were accepted together";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--pkg engine and --pkg engine-float64 are two builds of one library"),
              std::string::npos)
        << e.what();
  }
  LibraryRequest mine;
  mine.cxxflags = {"-I/usr/include/../include", "-include", "a.h", "-include", "b.h"};
  EXPECT_EQ(resolve_library_flags(mine, false).compile, mine.cxxflags);
  fs::remove_all(dir);
}

TEST(LibraryFlags, AMissingHeaderSuggestsItsPackage) {
  // liboctave-dev (./geomech installs it) puts octave/oct.h under /usr/include/octave-X, which its
  // pkg-config name octinterp adds with -I (a missing octave fails this test, as it fails the Octave ones).
  const std::string hint = missing_header_hint("mine.cpp:3:10: fatal error: octave/oct.h: No such file or directory\n");
  EXPECT_NE(hint.find("--pkg octinterp"), std::string::npos) << hint;
  const std::string nowhere =
      missing_header_hint("mine.cpp:3:10: fatal error: no_such_engine/world.h: No such file or directory\n");
  EXPECT_NE(nowhere.find("--pkg NAME"), std::string::npos) << nowhere;
  EXPECT_EQ(missing_header_hint("mine.cpp:3:10: error: expected ';'\n"), "");
}

}  // namespace
}  // namespace gm::harness
