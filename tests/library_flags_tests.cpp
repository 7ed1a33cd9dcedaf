// The libraries of a C++ file (harness/program/library_flags.hpp, issue 48): the file's own `// geomech:`
// lines, pkg-config, the vetting of a stranger's flags (and its control: your own file's flags pass
// unvetted), and the hint for a missing header.
#include "harness/program/library_flags.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace gm::harness {
namespace {

TEST(LibraryFlags, AFileDeclaresItsLibrariesInCommentLines) {
  const LibraryRequest r = declared_in_source(
      "// geomech: pkg ode\n  //geomech: cxxflags -DFAST \"-DNAME=a b\"\n// geomech: ldflags -lm\nint x;  // geomech: pkg no\n",
      "mine.cpp");
  EXPECT_EQ(r.pkgs, (std::vector<std::string>{"ode"}));
  EXPECT_EQ(r.cxxflags, (std::vector<std::string>{"-DFAST", "-DNAME=a b"}));
  EXPECT_EQ(r.ldflags, (std::vector<std::string>{"-lm"}));
  try {
    declared_in_source("\n// geomech: link ode\n", "mine.cpp");
    FAIL() << "an unknown request was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mine.cpp:2: `// geomech: link` is not a request the suite knows"), std::string::npos)
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
  r.cxxflags = {"-DOK=1", "-I/usr/include/ode", "-Wall", "-I/root", "@/etc/os-release", "-B/tmp", "-wrapper,/bin/sh",
                "-fplugin=/tmp/p.so", "-specs=/tmp/s", "-I/usr/include/../../etc", "-include", "/etc/passwd"};
  r.ldflags = {"-lode", "-L/usr/lib/x86_64-linux-gnu", "-L/home", "-Wl,-T,/tmp/x.ld", "-l/etc/shadow"};
  try {
    resolve_library_flags(r, true);
    FAIL() << "a stranger's flags passed";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    for (const char* refused : {"'-I/root'", "'@/etc/os-release'", "'-B/tmp'", "'-wrapper,/bin/sh'", "'-fplugin=/tmp/p.so'",
                                "'-specs=/tmp/s'", "'-I/usr/include/../../etc'", "'-include'", "'-L/home'",
                                "'-Wl,-T,/tmp/x.ld'", "'-l/etc/shadow'"})
      EXPECT_NE(m.find(refused), std::string::npos) << refused << " was not refused:\n" << m;
    for (const char* passed : {"'-DOK=1'", "'-I/usr/include/ode'", "'-Wall'", "'-lode'", "'-L/usr/lib/x86_64-linux-gnu'"})
      EXPECT_EQ(m.find(passed), std::string::npos) << passed << " was refused:\n" << m;
  }
  // The control: the same flags for your own file (in-process, no sandbox) are passed on as given.
  const LibraryFlags mine = resolve_library_flags(r, false);
  EXPECT_EQ(mine.compile, r.cxxflags);
  EXPECT_EQ(mine.link, r.ldflags);
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
