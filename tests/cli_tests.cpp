// The geomech tool's own argument handling (bad input gets a clear error): nonsense arguments
// get a message naming the argument and exit status 2; nothing is written.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#ifndef GM_GEOMECH_BIN
#error "GM_GEOMECH_BIN must name the built geomech tool"
#endif

namespace {

struct Result {
  int status = -1;
  std::string output;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

Result run(const std::vector<std::string>& args) {
  std::string cmd = quote(GM_GEOMECH_BIN);
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " 2>&1";
  Result r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  while (std::fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

void expect_bad(const std::vector<std::string>& args, const std::string& says) {
  const Result r = run(args);
  std::string line;
  for (const auto& a : args) line += " " + a;
  EXPECT_EQ(r.status, 2) << "geomech" << line << "\n" << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << "geomech" << line << "\n" << r.output;
}

TEST(cli_arguments, NonsenseIsRefusedWithTheArgumentNamed) {
  expect_bad({}, "A subcommand is required");
  expect_bad({"frobnicate"}, "frobnicate");
  expect_bad({"check", "--scalar", "quad"}, "--scalar");
  expect_bad({"check", "--seed", "abc"}, "--seed");
  expect_bad({"check", "--cases", "-"}, "--cases");
  expect_bad({"check", "--property", "no_such_property"}, "no_such_property");
  expect_bad({"check", "--subject", "no_such_subject"}, "no_such_subject");
  expect_bad({"check", "/nonexistent/student.cpp"}, "/nonexistent/student.cpp");
  expect_bad({"check", "--reproduce", "%%%not-a-reproduce-string"}, "reproduce");
  {  // a file of no language is said to be one, not compiled as C++ (the link error it gave)
    const std::string notes = (std::filesystem::temp_directory_path() / "geomech-cli-notes.txt").string();
    std::ofstream(notes) << "notes\n";
    // (the table's extensions, as extensions_in_words() writes them, are held by LanguageTable.*)
    expect_bad({"check", notes}, notes + ": not a .cpp, .cc, .py, ");
    expect_bad({"check", notes}, " file, nor a folder of .m files");
    expect_bad({"check", "--untrusted", notes}, notes + ": not a .cpp, .cc, .py, ");
    std::filesystem::remove(notes);
  }
  expect_bad({"check-trajectory"}, "files");
  expect_bad({"check-trajectory", "/nonexistent/run.txt"}, "/nonexistent/run.txt");
  expect_bad({"check-class", "/nonexistent/folder"}, "/nonexistent/folder");
  expect_bad({"catalogue", "--file", "/nonexistent/catalogue.json"}, "/nonexistent/catalogue.json");
  expect_bad({"golden", "trajectory", "--system", "free_rigid_body", "--param", "I=2,1.5,1", "--initial", "Pi=1,0,0",
              "--times", "0:-1:5"},
             "--times");
}

TEST(cli_arguments, HelpIsNotAnError) {
  const Result r = run({"--help"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("check"), std::string::npos) << r.output;
}

}  // namespace
