// harness/languages/: a row carries its language. What the check, the reports and the slot listing
// used to ask by id now comes from the row; each statement with its failing side (a row without a
// reader, a language that is not one, the suite's own style against a row's).
#include "harness/checking/check.hpp"
#include "harness/checking/source_calls.hpp"
#include "harness/languages/language.hpp"
#include "harness/reports/report.hpp"
#include "properties/support/show.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace gm::harness {
namespace {

// Each served row has every reader and printer the rooms read; the suite's own row is the compiled one.
TEST(LanguageRows, EveryServedRowCarriesItsLanguage) {
  EXPECT_EQ(suite_language().route, Route::Compiled);
  EXPECT_EQ(&suite_language(), language_named("c++"));
  for (const auto& l : languages()) {
    if (l.route != Route::Served) continue;
    EXPECT_FALSE(l.function_noun.empty()) << l.id;
    EXPECT_FALSE(l.version_label.empty()) << l.id;
    EXPECT_GT(l.timeout_factor, 1) << l.id << ": an interpreter's checks get more than the default timeout";
    EXPECT_NE(l.function_names, nullptr) << l.id;
    EXPECT_NE(l.code_only, nullptr) << l.id;
    EXPECT_NE(l.definitions, nullptr) << l.id;
    EXPECT_NE(l.signature, nullptr) << l.id;
    EXPECT_NE(l.integrator_interface, nullptr) << l.id;
    EXPECT_FALSE(l.slots_heading.empty()) << l.id;
    EXPECT_NE(l.for_sandbox, nullptr) << l.id;
    EXPECT_FALSE(l.values.vector_type.empty()) << l.id << ": counterexample types in the language's words";
  }
  EXPECT_EQ(language_named("fortran"), nullptr);
}

// The value style is the row's: a matrix as Python's list of rows, as Octave's rows, as the suite's
// own; a column; 50 digits and a rational. Each is held against the default (the control).
TEST(LanguageRows, ValuesAreWrittenAsTheRowSays) {
  const Mat3<double> m = Mat3<double>::Identity();
  const Vec3<double> v(1, 2, 3);
  const ValueStyle before = value_style();
  value_style() = suite_language().values;
  EXPECT_EQ(show_value(v), "[1, 2, 3]");
  EXPECT_EQ(show_value(m), "[1, 0, 0; 0, 1, 0; 0, 0, 1]");
  EXPECT_EQ(show_value(Rational(1, 3)), "1/3");
  value_style() = language_named("python")->values;
  EXPECT_EQ(show_value(v), "[1, 2, 3]");
  EXPECT_EQ(show_value(m), "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]");
  EXPECT_EQ(show_value(Rational(1, 3)), "Fraction(1, 3)");
  EXPECT_EQ(show_value(Rational(2)), "Fraction(2)");
  EXPECT_EQ(show_value(Real50(1) / 2).rfind("mpf('", 0), 0u);
  value_style() = language_named("octave")->values;
  EXPECT_EQ(show_value(v), "[1; 2; 3]");
  EXPECT_EQ(show_value(m), "[1, 0, 0; 0, 1, 0; 0, 0, 1]");
  value_style() = language_named("javascript")->values;
  EXPECT_EQ(show_value(m), "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]");
  value_style() = before;
}

// Reports name a slot in the row's words; the suite's own row names the slot.
TEST(LanguageRows, ReportsNameTheFunctionInTheRowsWords) {
  SubjectInfo info;
  info.source = "/somewhere/mine.py";
  EXPECT_EQ(slot_named(info, "casimir", "`"), "slot `casimir`");
  info.language = language_named("python");
  EXPECT_EQ(slot_named(info, "casimir", "`"), "Python function `casimir` in mine.py");
  info.language = language_named("javascript");
  info.source = "/somewhere/engine.mjs";
  EXPECT_EQ(slot_named(info, "casimir", "`"), "JavaScript function `casimir` in engine.mjs");
  info.language = language_named("octave");
  EXPECT_EQ(timeout_factor(info), 6);
  info.language = &suite_language();
  EXPECT_EQ(timeout_factor(info), 1);
}

// The row's readers: what a file defines, for the did-you-mean; which slot calls which. A row without
// readers reads as no calls (the control: the same text through the row that reads it).
TEST(LanguageRows, SourceIsReadByItsRow) {
  const Language& py = *language_named("python");
  EXPECT_EQ(py.function_names("def energy(I, Pi):\n    pass\n\nclass A:\n    def inner(self):\n        pass\n"),
            (std::vector<std::string>{"energy"}));
  Language none = py;
  none.code_only = nullptr;
  const std::string text = "def euler_3_8(I, Pi):\n    return cross(Pi, omega_3_5(I, Pi))\n";
  EXPECT_TRUE(slot_calls_in_text(text, none).empty());
  EXPECT_EQ(slot_calls_in_text(text, py).at("euler_3_8"), (std::set<std::string>{"omega_3_5"}));
  // JavaScript: what a module exports (ES and CommonJS), not its inner helpers; a call in a comment
  // or a string is not a call.
  const Language& js = *language_named("javascript");
  EXPECT_EQ(js.function_names("export function energy(I, Pi) {}\nfunction helper() {}\nexport const hat = (v) => v;\n"
                              "exports.vee = function (m) {};\nmodule.exports = { casimir, euler_3_8: e };\n"),
            (std::vector<std::string>{"casimir", "energy", "euler_3_8", "hat", "vee"}));
  const std::string js_text =
      "export function euler_3_8(I, Pi) {\n  // not hat(Pi)\n  const s = \"vee(m)\";\n"
      "  return cross(Pi, omega_3_5(I, Pi));\n}\nexport const casimir = (Pi) => dot(Pi, Pi);\n";
  EXPECT_EQ(slot_calls_in_text(js_text, js).at("euler_3_8"), (std::set<std::string>{"omega_3_5"}));
  // The npm packages a file names for the sandbox: npm's spelling only (a path or a flag is no
  // package); the control: the same name off its own line is not named.
  ASSERT_NE(js.named_packages, nullptr);
  EXPECT_EQ(js.named_packages("// geomech: npm mujoco-js\n//geomech: npm @dimforge/rapier3d\n"
                              "// geomech: npm ../../etc\n// geomech: npm --prefix\nimport x from 'y';\n"),
            (std::vector<std::string>{"@dimforge/rapier3d", "mujoco-js"}));
  EXPECT_TRUE(js.named_packages("const s = 'x'; // geomech: npm mujoco-js\n").empty());
  EXPECT_EQ(language_named("python")->named_packages, nullptr);
}

// The files a served file names as its own, in its row's comment syntax; a path is the code's
// mistake, with its line; the controls: another language's comment, a line that only mentions it.
TEST(LanguageRows, BesideFilesAreNamedInTheRowsCommentSyntax) {
  const Language& py = *language_named("python");
  const Language& js = *language_named("javascript");
  EXPECT_EQ(beside_files(py, "# geomech: beside step_server.mjs\n#geomech: beside helpers.py\r\nimport os\n"),
            (std::vector<std::string>{"helpers.py", "step_server.mjs"}));
  EXPECT_EQ(beside_files(js, "// geomech: beside correct.mjs\nexport * from './correct.mjs';\n"),
            (std::vector<std::string>{"correct.mjs"}));
  EXPECT_TRUE(beside_files(js, "# geomech: beside correct.mjs\n").empty());
  EXPECT_TRUE(beside_files(py, "x = 1  # geomech: beside other.py\n# geomech: besides other.py\n").empty());
  for (const char* bad : {"import os\n# geomech: beside ../secret.py\n", "# geomech: beside /etc/passwd\n",
                          "# geomech: beside .hidden\n", "# geomech: beside sub/file.py\n"})
    EXPECT_THROW((void)beside_files(py, bad), std::invalid_argument) << bad;
  try {
    (void)beside_files(py, "import os\n# geomech: beside ../secret.py\n");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("line 2: `geomech: beside ../secret.py`"), std::string::npos) << e.what();
  }
}

// `geomech slots --<id>`: each row writes a slot's signature in its language.
TEST(LanguageRows, SignaturesAreWrittenInTheLanguage) {
  const SlotInfo* casimir = nullptr;
  for (const auto& s : subject_slots())
    if (std::string(s.name) == "casimir") casimir = &s;
  ASSERT_NE(casimir, nullptr);
  const std::string name = casimir->name, signature = casimir->signature;
  EXPECT_EQ(language_named("python")->signature(name, signature), "def casimir(Pi: 3-list) -> scalar");
  EXPECT_EQ(language_named("octave")->signature(name, signature), "function r = casimir(Pi %3x1)  % r: scalar");
  EXPECT_EQ(language_named("javascript")->signature(name, signature),
            "export function casimir(Pi)  // (Pi: vec3) -> number");
  EXPECT_EQ(suite_language().signature(name, signature), "casimir  " + signature);
}

}  // namespace
}  // namespace gm::harness
