// harness/submissions/: the language table and what reads it. Each statement has its failing
// side in the same test (an extension of no language, a file of no served language).
#include "harness/class/class_mode.hpp"
#include "harness/languages/language.hpp"

#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace gm::harness;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return gm::testing_support::scratch_folder("submissions", name); }
using gm::testing_support::write_file;

TEST(LanguageTable, EveryExtensionNamesOneLanguage) {
  std::set<std::string> seen;
  for (const auto& l : languages())
    for (const auto& e : l.extensions) {
      EXPECT_TRUE(seen.insert(e).second) << e << " is in two rows";
      EXPECT_EQ(language_of_extension(e), &l) << e;
    }
  EXPECT_EQ(language_of_extension(".txt"), nullptr);
  EXPECT_EQ(language_of_extension(""), nullptr);
  ASSERT_NE(language_of("mine.cc"), nullptr);
  EXPECT_EQ(language_of("mine.cc")->id, "c++");
  EXPECT_EQ(language_of("mine.cpp"), language_of("mine.cc"));
  EXPECT_EQ(language_of("notes.txt"), nullptr);
  EXPECT_EQ(extensions_in_words(), ".cpp, .cc, .py, .m, .mjs, .js or .ipynb");
}

TEST(LanguageTable, ServedLanguagesSayHowTheyStart) {
  for (const auto& l : languages()) {
    EXPECT_EQ(language_named(l.id), &l);
    if (l.route != Route::Served) continue;
    EXPECT_NE(l.interpreter, nullptr) << l.name;
    EXPECT_FALSE(l.interpreter_variable.empty()) << l.name;
    ASSERT_NE(l.server, nullptr) << l.name;
    std::string language, why;
    const auto cmd = server_command("mine" + l.extensions.front(), &language, &why);
    EXPECT_FALSE(cmd.empty()) << l.name;
    EXPECT_EQ(language, l.id);
    EXPECT_EQ(cmd.back(), "mine" + l.extensions.front()) << "the file is the server's last argument";
  }
  std::string language, why;
  EXPECT_TRUE(server_command("mine.cc", &language, &why).empty()) << "a compiled language is not served";
  EXPECT_EQ(why, "not a .py, .m, .mjs or .js file, nor a folder of .m files");
}

TEST(LanguageTable, AFolderOfFunctionFilesIsOneImplementation) {
  const fs::path root = scratch("folder");
  write_file(root / "dave" / "hat.m", "function m = hat(v)\nend\n");
  ASSERT_NE(language_of((root / "dave").string()), nullptr);
  EXPECT_TRUE(language_of((root / "dave").string())->folder_of_files);
  fs::create_directories(root / "empty");
  EXPECT_EQ(language_of((root / "empty").string()), nullptr);
  fs::remove_all(root);
}

TEST(LanguageTable, ClassModeFindsEveryLanguagesFiles) {
  const fs::path root = scratch("class");
  write_file(root / "ann.cpp", "GEOMECH_STUDENT(A);\n");
  write_file(root / "bob.cc", "GEOMECH_STUDENT(B);\n");
  write_file(root / "cat.py", "def hat(v): pass\n");
  write_file(root / "dan.m", "function m = hat(v)\nend\n");
  write_file(root / "readme.txt", "not a submission");
  write_file(root / "eve" / "main.cc", "GEOMECH_STUDENT(E);\n");
  write_file(root / "eve" / "helper.hpp", "");
  std::vector<std::string> names;
  for (const auto& i : find_implementations(root.string())) names.push_back(i.name);
  EXPECT_EQ(names, (std::vector<std::string>{"ann", "bob", "cat", "dan", "eve"}));
  fs::remove_all(root);
}

}  // namespace
