// Tests of what a lecturer reads and uploads: the class decided once (PASS by the
// assignment, "not written" apart from "double only", a roster student without a submission), and
// the Gradescope and PrairieLearn results rendered from that decision.
#include "harness/class/autograder.hpp"
#include "harness/class/class_html.hpp"
#include "harness/class/class_mode.hpp"
#include "harness/class/class_record.hpp"
#include "harness/class/feedback_files.hpp"
#include "harness/languages/language.hpp"

#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace gm::harness;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return gm::testing_support::scratch_folder("lecturer", name); }
using gm::testing_support::write_file;

// A checked row of a Python implementation whose report says `provided` (all exercised, all passing).
ClassRow checked_row(const std::string& name, const std::vector<std::string>& provided, int exit_code = 0) {
  ClassRow row;
  row.name = name;
  row.source = name + ".py";
  row.built = true;
  row.exit_code = exit_code;
  json report;
  report["language"] = "python";
  report["verdict"] = exit_code == 0 ? "PASS" : "FAIL";
  report["provided"] = {{"double", provided}, {"mp50", provided}};
  report["exercised"] = json::object();
  report["verdicts"] = json::array();
  for (const auto& s : provided) {
    report["exercised"][s] = {"definition_" + s};
    report["verdicts"].push_back(
        {{"property", "definition_" + s}, {"scalar", "double"}, {"outcome", "PASS"}, {"area", "sec. 2"}});
  }
  report["first_fix"] = json::array();
  report["counts"] = {{"FAIL", exit_code == 0 ? 0 : 1}};
  report["reproduce_prefix"] = "geomech check " + name + ".py";
  row.report = report;
  return row;
}

}  // namespace

// One slot of eleven, right, read as PASS; "n/p" mixed what was not written with what the
// language cannot compute. The assignment decides PASS, and the cells count the two apart.
TEST(ClassRecord, TheAssignmentDecidesPassAndNotProvidedIsSplit) {
  std::vector<ClassRow> rows{checked_row("frank", {"hat", "vee", "casimir"}),
                             checked_row("alice", {"hat", "vee", "casimir", "euler_3_8"})};
  rows[0].report["verdicts"].push_back({{"property", "definition_euler_3_8"},
                                        {"scalar", "double"},
                                        {"outcome", "NOT PROVIDED"},
                                        {"area", "sec. 2"},
                                        {"not_provided", "not written"}});
  rows[0].report["verdicts"].push_back({{"property", "definition_casimir"},
                                        {"scalar", "exact"},
                                        {"outcome", "NOT PROVIDED"},
                                        {"area", "sec. 2"},
                                        {"not_provided", "double only"}});
  const Rubric week = parse_rubric(R"({"assignment": ["hat", "vee", "casimir", "euler_3_8"]})", "week.json");
  const ClassView v = decide_class(rows, week);
  EXPECT_EQ(v.students[0].result, "INCOMPLETE");
  EXPECT_EQ(v.students[1].result, "PASS");
  EXPECT_EQ(cell_text(v.students[0].areas.at("sec. 2")), "3/3 +1 n/w +1 d/o");
  EXPECT_EQ(format_points(v.students[0].score.points), "75.00");
  // The control: with frank's three slots as the assignment, frank passes.
  const Rubric small = parse_rubric(R"({"assignment": ["hat", "vee", "casimir"]})", "small.json");
  EXPECT_EQ(decide_class(rows, small).students[0].result, "PASS");
  // A roster student without a submission is a row: 0 and "no submission".
  rows.push_back(no_submission_row("henry"));
  const ClassView w = decide_class(rows, week);
  EXPECT_EQ(w.students[2].result, "NO SUBMISSION");
  EXPECT_EQ(format_points(w.students[2].score.points), "0.00");
  EXPECT_EQ(w.students[2].score.feedback, "0.00 of 100: no submission");
  const std::string html = class_summary_html(w, ClassPage{"week3", "week.json", {}, false});
  EXPECT_NE(html.find("<td data-sort=\"0\" class=\"FAIL\">NO SUBMISSION</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("id=\"class-table\""), std::string::npos);
}

TEST(Autograder, ResultsRenderTheDecidedStudentInEachFormat) {
  std::vector<ClassRow> rows{checked_row("bob", {"hat", "vee", "casimir"}, 1)};
  rows[0].report["first_fix"] = json::array({{{"slot", "casimir"},
                                              {"property", "definition_casimir"},
                                              {"scalar", "mp50"},
                                              {"line", "Python function 'casimir' in bob.py is wrong: ..."}}});
  const Rubric r = parse_rubric(R"({"points": 20, "assignment": ["hat", "vee", "casimir", "euler_3_8"],
                                    "slots": {"casimir": 2}})",
                                "week.json");
  const ClassView v = decide_class(rows, r);
  const json gs = gradescope_results(v.students[0], "# report\n");
  EXPECT_EQ(gs.at("score"), 8.0);  // hat and vee, 2 of 5 weights of 20 points
  double sum = 0;
  int scored = 0;
  for (const auto& t : gs.at("tests"))
    if (t.contains("score")) sum += t["score"].get<double>(), ++scored;
  EXPECT_EQ(scored, 4);
  EXPECT_NEAR(sum, 8.0, 1e-9);
  EXPECT_EQ(gs["tests"][2]["name"].get<std::string>().rfind("slot casimir: ", 0), 0u);
  EXPECT_EQ(gs["tests"][2]["status"], "failed");
  EXPECT_EQ(gs["tests"][2]["max_score"], 8.0);
  const std::string missing = gs["tests"][3]["output"].get<std::string>();
  EXPECT_EQ(missing.rfind("not provided", 0), 0u);
  for (const auto& l : languages())  // the listings a student may ask for: every listed row's flag
    if (l.signature && &l != &suite_language()) {
      EXPECT_NE(missing.find("--" + l.id), std::string::npos) << missing;
    }
  EXPECT_EQ(gs["output"].get<std::string>().rfind("FAIL, 8.00 of 20: 2 of 4 slots correct (weight 2 of 5)", 0), 0u)
      << gs["output"];
  const json pl = prairielearn_results(v.students[0], "# report\n");
  EXPECT_EQ(pl.at("gradable"), true);
  EXPECT_NEAR(pl.at("score").get<double>(), 0.4, 1e-12);
  EXPECT_EQ(pl["tests"][2]["name"], "casimir");
  EXPECT_EQ(pl["tests"][2]["points"], 0.0);
  // A file that does not compile: no grade counted against the student on PrairieLearn (not
  // gradable, with the compiler's message), 0 on Gradescope with the message as a test.
  ClassRow bad;
  bad.name = "gina";
  bad.built = false;
  bad.build_message = "gina.cpp:11:5: error: expected ';' before 'return'";
  const std::vector<ClassRow> bad_rows{bad};  // the view points into its rows: they must outlive it
  const ClassView w = decide_class(bad_rows, r);
  const json pl2 = prairielearn_results(w.students[0], "");
  EXPECT_EQ(pl2.at("gradable"), false);
  EXPECT_FALSE(pl2.contains("score"));
  EXPECT_EQ(pl2["format_errors"][0], "does not compile: gina.cpp:11:5: error: expected ';' before 'return'");
  const json gs2 = gradescope_results(w.students[0], "");
  EXPECT_EQ(gs2.at("score"), 0.0);
  EXPECT_EQ(gs2["tests"].back()["name"], "it compiles");
}

// Hidden tests: the rubric's visibility reaches each platform's tests, and nothing the
// student sees now names a hidden slot: not a test, not the overall words, not the whole report.
TEST(Autograder, HiddenTestsAreNotShownAndTheirPointsCount) {
  std::vector<ClassRow> rows{checked_row("bob", {"hat", "vee", "casimir"}, 1)};
  rows[0].report["first_fix"] = json::array({{{"slot", "casimir"},
                                              {"property", "definition_casimir"},
                                              {"scalar", "mp50"},
                                              {"line", "Python function 'casimir' in bob.py is wrong: ..."}}});
  const std::string assignment =
      R"("points": 20, "assignment": ["hat", "vee", "casimir", "euler_3_8"], "slots": {"casimir": 2})";
  const Rubric r = parse_rubric(
      "{" + assignment + R"(, "visibility": {"casimir": "after_due_date", "euler_3_8": "hidden"}})", "week.json");
  const ClassView v = decide_class(rows, r);
  const json gs = gradescope_results(v.students[0], "# report naming casimir\n");
  EXPECT_EQ(gs.at("score"), 8.0);  // the hidden tests count in the score
  EXPECT_EQ(gs["tests"][0]["visibility"], "visible");
  EXPECT_EQ(gs["tests"][2]["visibility"], "after_due_date");
  EXPECT_EQ(gs["tests"][3]["visibility"], "hidden");
  EXPECT_EQ(gs["tests"].back()["name"], "the whole report (report.md)");
  EXPECT_EQ(gs["tests"].back()["visibility"], "hidden");  // it names every check: withheld as the most withheld
  const std::string words = gs["output"].get<std::string>();
  EXPECT_EQ(words.find("casimir"), std::string::npos) << words;
  EXPECT_EQ(words.find("euler_3_8"), std::string::npos) << words;
  EXPECT_EQ(words.find("FAIL"), std::string::npos) << words;
  EXPECT_NE(words.find("The tests shown now: 2 of 2 passed (8.00 of 8.00 points)."), std::string::npos) << words;
  EXPECT_NE(words.find("2 tests are hidden from students; they count in the score."), std::string::npos) << words;
  const json pl = prairielearn_results(v.students[0], "# report naming casimir\n");
  // PrairieLearn has no visibility per test: hidden ones are left out, their points in one unnamed row.
  ASSERT_EQ(pl["tests"].size(), 3u);
  EXPECT_EQ(pl["tests"][2]["name"], "2 tests hidden from students");
  EXPECT_EQ(pl["tests"][2]["max_points"], 12.0);
  EXPECT_NEAR(pl.at("score").get<double>(), 0.4, 1e-12);
  EXPECT_EQ(pl.dump().find("casimir"), std::string::npos) << pl.dump();
  EXPECT_EQ(pl.dump().find("FAIL"), std::string::npos) << pl.dump();
  // The control: without "visibility" every test is visible, and the words name the wrong slot.
  const Rubric open_rubric = parse_rubric("{" + assignment + "}", "week.json");
  const ClassView o = decide_class(rows, open_rubric);
  const json gs_open = gradescope_results(o.students[0], "# report naming casimir\n");
  EXPECT_EQ(gs_open["tests"][2]["visibility"], "visible");
  EXPECT_NE(gs_open["output"].get<std::string>().find("casimir"), std::string::npos);
  EXPECT_EQ(prairielearn_results(o.students[0], "").at("tests").size(), 4u);
}

// A refused rubric names every error, each with its key, not only the first.
TEST(Rubric, ARefusalNamesEveryError) {
  try {
    parse_rubric(
        R"({"points": -1, "slots": {"casimr": 1, "hatt": 2}, "visibility": {"casimir": "later"}, "colour": 1})",
        "week.json");
    FAIL() << "the rubric was accepted";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("rubric \"week.json\" has 5 errors:", 0), 0u) << m;
    for (const char* key : {"key \"points\"", "key \"slots.casimr\"", "key \"slots.hatt\"",
                            "key \"visibility.casimir\"", "key \"colour\""})
      EXPECT_NE(m.find(key), std::string::npos) << key << " in " << m;
    EXPECT_NE(m.find("did you mean \"casimir\""), std::string::npos) << m;
  }
  // One error reads as before: one line.
  try {
    parse_rubric(R"({"slots": {"casimr": 1}})", "week.json");
    FAIL() << "the rubric was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

TEST(Autograder, ASubmissionFolderIsLaidOutAsAClassOfOne) {
  const fs::path root = scratch("layout");
  write_file(root / "py" / "mine.py", "def hat(v): pass\n");
  write_file(root / "py" / "notes.txt", "x");
  EXPECT_EQ(lay_out_submission((root / "py").string(), (root / "c1").string()), "mine");
  EXPECT_TRUE(fs::is_regular_file(root / "c1" / "mine.py"));
  for (const char* f : {"hat.m", "vee.m"})
    write_file(root / "m" / "dave" / f, "function m = f()\nend\n");  // a zipped folder
  EXPECT_EQ(lay_out_submission((root / "m").string(), (root / "c2").string()), "submission");
  EXPECT_TRUE(fs::is_regular_file(root / "c2" / "submission" / "vee.m"));
  write_file(root / "cpp" / "erin.cpp", "#include \"so3.hpp\"\nGEOMECH_STUDENT(E);\n");
  write_file(root / "cpp" / "so3.hpp", "");
  fs::create_symlink("/etc/passwd", root / "cpp" / "secret.hpp");
  EXPECT_EQ(lay_out_submission((root / "cpp").string(), (root / "c3").string()), "erin");
  EXPECT_TRUE(fs::is_regular_file(root / "c3" / "erin" / "so3.hpp"));
  EXPECT_TRUE(fs::is_symlink(root / "c3" / "erin" / "secret.hpp"));  // copied as a link, never read through
  // A C++ file is C++ by either of its extensions, as in `geomech check` (the language table).
  write_file(root / "cc" / "fay.cc", "GEOMECH_STUDENT(F);\n");
  EXPECT_EQ(lay_out_submission((root / "cc").string(), (root / "c5").string()), "fay");
  EXPECT_TRUE(fs::is_regular_file(root / "c5" / "fay" / "fay.cc"));
  // A notebook uploaded alone is the submission, as a file of any language of the table.
  write_file(root / "nb" / "week3.ipynb", "{}");
  EXPECT_EQ(lay_out_submission((root / "nb").string(), (root / "c6").string()), "week3");
  EXPECT_TRUE(fs::is_regular_file(root / "c6" / "week3.ipynb"));
  write_file(root / "two" / "a.py", "");
  write_file(root / "two" / "b.py", "");
  try {
    lay_out_submission((root / "two").string(), (root / "c4").string());
    ADD_FAILURE() << "two Python files were taken as one implementation";
  } catch (const std::runtime_error& e) {
    // Every extension of the table counted (two .py files, none of the others), then what is expected.
    const std::string said = e.what();
    EXPECT_NE(said.find("the submission holds 0 .cpp, 0 .cc, 2 .py, "), std::string::npos) << said;
    for (const auto& l : languages())
      for (const auto& x : l.extensions) {
        EXPECT_NE(said.find((x == ".py" ? "2 " : "0 ") + x), std::string::npos) << x << ": " << said;
      }
    EXPECT_NE(said.find(" files; expected one .cpp or .cc file using GEOMECH_STUDENT"), std::string::npos) << said;
  }
  fs::remove_all(root);
}

// `check-class week3` and `check-class week3/` wrote to different folders (without the
// slash nothing resumed; with it, classes overwrote each other's summary). One class folder, one
// report folder, however it is written; the control: another class, another folder.
// A class run resumes a submission only if what its check depends on is unchanged: for a C++ file
// that includes the libraries the command line adds (a changed --pkg used to resume the old result).
TEST(ClassResume, LibraryFlagsCountForACppFileOnly) {
  ClassOptions plain;
  ClassOptions ode = plain;
  ode.build.libraries.pkgs = {"ode"};
  ClassOptions flags = plain;
  flags.build.libraries.cxxflags = {"-DdSINGLE"};
  ClassOptions link = plain;
  link.build.libraries.ldflags = {"-lode"};
  for (const auto* changed : {&ode, &flags, &link})
    EXPECT_NE(check_conditions(plain, ".cpp"), check_conditions(*changed, ".cpp"));
  // Python and Octave are not compiled: the same flags leave their checks as they were.
  EXPECT_EQ(check_conditions(plain, ".py"), check_conditions(ode, ".py"));
  EXPECT_EQ(check_conditions(plain, ""), check_conditions(ode, ""));
  // control: the same options, the same conditions; the mode and the check's options count for all
  EXPECT_EQ(check_conditions(plain, ".cpp"), check_conditions(ClassOptions{}, ".cpp"));
  ClassOptions trusted = plain;
  trusted.untrusted = false;
  EXPECT_NE(check_conditions(plain, ".py"), check_conditions(trusted, ".py"));
}

TEST(ClassRecord, OneClassFolderIsOneReportFolder) {
  const std::string a = default_class_report_dir("week3");
  EXPECT_EQ(a, "geomech-reports/week3");
  for (const std::string& same :
       std::vector<std::string>{"week3/", "./week3", "./week3//", (fs::current_path() / "week3").string() + "/"})
    EXPECT_EQ(default_class_report_dir(same), a) << same;
  EXPECT_EQ(default_class_report_dir("other/week3"), a);  // the folder's name, as before
  EXPECT_NE(default_class_report_dir("week4/"), a);
}

// What the class got wrong, decided once: per slot and per claim, how many of the students
// checked, who, and the most common first fix, grouped across the students' own names and numbers.
// The control: a class with nothing wrong has no mistake, and a student not checked counts in neither.
TEST(ClassRecord, WhatTheClassGotWrongCountsStudentsAndTheCommonFix) {
  std::vector<ClassRow> rows{checked_row("alice", {"hat", "vee"}, 1), checked_row("bob", {"hat", "vee"}, 1),
                             checked_row("carol", {"hat", "vee"}, 1), checked_row("dave", {"hat", "vee"})};
  auto wrong = [](ClassRow& r, const std::string& slot, const std::string& line) {
    r.report["first_fix"].push_back({{"slot", slot}, {"line", line}});
  };
  wrong(rows[0], "vee", "Python function 'vee' in alice.py is wrong: at m = [[0, -3, 2]] it returns -1.5");
  wrong(rows[1], "vee", "Python function 'vee' in bob.py is wrong: at m = [[0, -1, 7]] it returns 0.25");
  wrong(rows[2], "vee", "Python function 'vee' in carol.py returns a list of 2 entries");
  wrong(rows[2], "hat", "Python function 'hat' in carol.py is wrong: at v = [1, 2, 3] it returns 4");
  rows[1].report["integrators"] =
      json::array({{{"name", "midpoint"},
                    {"claims", json::array({{{"claim", "casimir"}, {"claimed", "yes"}, {"status", "FALSE CLAIM"}}})}}});
  ClassRow eve = checked_row("eve", {"hat"});
  eve.problem = "the check ran out of its time";
  wrong(eve, "vee", "not counted: eve was not checked");
  rows.push_back(eve);
  const ClassView v = decide_class(rows, Rubric{});
  ASSERT_EQ(v.mistakes.size(), 3u);
  EXPECT_EQ(v.mistakes[0].kind, "slot");
  EXPECT_EQ(v.mistakes[0].what, "vee");
  EXPECT_EQ(v.mistakes[0].students, 3);
  EXPECT_EQ(v.mistakes[0].checked, 4) << "eve was not checked: she counts in neither";
  EXPECT_EQ(v.mistakes[0].who, (std::vector<std::string>{"alice", "bob", "carol"}));
  EXPECT_EQ(v.mistakes[0].common_fix_students, 2) << "alice's and bob's fixes differ only in their names and numbers";
  EXPECT_NE(v.mistakes[0].common_fix.find("is wrong: at m = "), std::string::npos) << v.mistakes[0].common_fix;
  EXPECT_EQ(v.mistakes[1].what, "hat");  // one student each: by name
  EXPECT_EQ(v.mistakes[2].kind, "claim");
  EXPECT_EQ(v.mistakes[2].what, "midpoint casimir");
  // Rendered in the page, with its chart.
  const std::string html = class_summary_html(v, ClassPage{"class", "(default rubric)", {}, false});
  EXPECT_NE(html.find("What the class got wrong"), std::string::npos);
  EXPECT_NE(html.find("<svg role=\"img\" aria-label=\"students who got each wrong\""), std::string::npos);
  EXPECT_NE(html.find("3 of 4"), std::string::npos);
  // The control: nothing wrong, no section.
  std::vector<ClassRow> fine{checked_row("dave", {"hat", "vee"})};
  const ClassView f = decide_class(fine, Rubric{});
  EXPECT_TRUE(f.mistakes.empty());
  EXPECT_EQ(class_summary_html(f, ClassPage{"class", "(default rubric)", {}, false}).find("What the class got wrong"),
            std::string::npos);
}

// Feedback where students read it. A class folder unzipped from Moodle's download has a
// folder per student named "Full Name_12345_assignsubmission_file_": the page goes into a folder of
// that name; from Canvas's, files named "lastfirst_12345_67890_...": the page keeps that prefix. Any
// other name: NAME.html, said to be no LMS's. A roster student with nothing handed in gets no page.
TEST(FeedbackFiles, NamedForTheLmsBulkUploadAndSelfContained) {
  EXPECT_EQ(feedback_name("Ada Lovelace_657737_assignsubmission_file_").path,
            "Ada Lovelace_657737_assignsubmission_file_/geomech-feedback.html");
  EXPECT_EQ(feedback_name("Ada Lovelace_657737_assignsubmission_file_").lms, "Moodle");
  EXPECT_EQ(feedback_name("lovelaceada_12345_67890_rigid_body").path, "lovelaceada_12345_67890_geomech-feedback.html");
  EXPECT_EQ(feedback_name("lovelaceada_LATE_12345_67890_rigid").path,
            "lovelaceada_LATE_12345_67890_geomech-feedback.html");
  EXPECT_EQ(feedback_name("lovelaceada_LATE_12345_67890_rigid").lms, "Canvas");
  EXPECT_EQ(feedback_name("wrong_vee").path, "wrong_vee.html");  // the control: no LMS's name
  EXPECT_EQ(feedback_name("wrong_vee").lms, "");
  EXPECT_EQ(feedback_name("bob_2_3").lms, "")
      << "too short to be Canvas's: name, user id, submission id, then the file";

  std::vector<ClassRow> rows{checked_row("Ada Lovelace_657737_assignsubmission_file_", {"hat", "vee"}, 1),
                             checked_row("lovelaceada_12345_67890_rigid", {"hat", "vee"}), no_submission_row("carol")};
  rows[0].report["first_fix"].push_back(
      {{"slot", "vee"}, {"line", "Python function 'vee' in rigid.py is wrong: at m = ..."}});
  const ClassView v = decide_class(rows, Rubric{});
  const fs::path dir = scratch("feedback");
  const auto said = write_feedback_files(v, dir.string());
  ASSERT_EQ(said.size(), 2u);
  EXPECT_NE(said[0].find("1 in folders named as Moodle's"), std::string::npos) << said[0];
  const fs::path moodle = dir / "Ada Lovelace_657737_assignsubmission_file_" / "geomech-feedback.html";
  ASSERT_TRUE(fs::exists(moodle));
  ASSERT_TRUE(fs::exists(dir / "lovelaceada_12345_67890_geomech-feedback.html"));
  EXPECT_FALSE(fs::exists(dir / "carol.html")) << "nothing handed in, nothing to attach to";
  std::ifstream in(moodle);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("Python function &#39;vee&#39; in rigid.py is wrong"), std::string::npos) << page;
  EXPECT_NE(page.find("geomech check Ada Lovelace_657737_assignsubmission_file_.py"), std::string::npos)
      << "the command the student runs";
  EXPECT_EQ(page.find(dir.string()), std::string::npos) << "no grader path";
}
