// A class run as it is recorded on disk, and what every view of it says about each student,
// decided here once ("a verdict is decided once"). A class run keeps, for each
// implementation, <report>/<name>/class-row.json (how its build and check ended) beside the
// check's own verdicts.json; the shard's rows are also in <report>/class-shard.json. summary.md,
// summary.html, the gradebook CSV and the Gradescope and PrairieLearn results all render the
// ClassView made here and never decide again.
#pragma once

#include "harness/class/gradebook.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gm::harness {

// One implementation as its class run recorded it.
struct ClassRow {
  std::string name;           // the implementation's name in the class (file stem or folder name)
  std::string source;         // where it was read from
  bool submitted = true;      // false: a roster name with nothing in the class folder
  bool built = false;         // compiled (always true for Python and Octave)
  std::string build_message;  // the compiler's message when it did not compile
  double build_seconds = 0;
  int exit_code = -1;  // of the check: 0 every check passed, 1 some did not; else a problem
  double check_seconds = 0;
  std::string problem;  // the check itself could not run (a refusal, a crash of the harness...)
  // The grader's machine or set-up failed it, with the fix (a sandbox that cannot start the compiler,
  // a check starved of CPU): never graded, checked again by the next run.
  std::string machine_fault;
  nlohmann::json report;  // the check's verdicts.json; null unless it was checked
  // A machine's fault that only this submission meets is suspect: the faults of the runs before
  // this one, each of this same submission (unchanged source, options and suite) ending in a machine
  // fault of the same kind (same_machine_fault); `suspect` once such a run was checked again and
  // ended so again while classmates checked fine on the same machine, whose self-test passed. It is
  // then left to the lecturer, with that evidence, and a plain run does not check it again
  // (--regrade NAME does): never graded as the machine's nor as the code's by the tool alone.
  std::vector<std::string> earlier_faults;
  bool suspect = false;
};

// Whether two machine faults are of one kind (the kernel's accounting said starved both times; the
// sandbox could not start both times; ...).
bool same_machine_fault(const std::string& a, const std::string& b);

// The grader's fault in a row: its own, or that of a verdict of its report (verdicts.json's
// "machine_fault"); empty when none.
std::string grader_fault_of(const ClassRow& row);

// A row from its JSON (the "row" of class-row.json, or an entry of class-shard.json's "rows"), with
// the report of a checked implementation read from `report_dir`/<name>/verdicts.json.
ClassRow class_row_from_json(const nlohmann::json& row, const std::string& report_dir);
nlohmann::json class_row_to_json(const ClassRow& row);

// <report_dir>/<name>/class-row.json, or nothing when there is none or it cannot be read.
std::optional<ClassRow> read_class_row(const std::string& report_dir, const std::string& name);

// The row of a roster student who handed nothing in.
ClassRow no_submission_row(const std::string& name);

// How a row ended, in the words every view uses: "checked", "does not compile", "not checked",
// "no submission", kGraderError.
std::string status_of(const ClassRow& row);

// Checks of one area of the notes for one student. A NOT PROVIDED check is either "not written"
// (a slot or integrator it needs is not in the submission at all) or "double only" (what it needs is
// there, but not in that scalar: Octave is checked in double, numpy code computes in double).
struct AreaCell {
  int passed = 0, run = 0, bad = 0;  // bad: FAIL, CRASH, TIMEOUT or ERROR
  int not_written = 0, double_only = 0;
};
std::string cell_text(const AreaCell& c);  // "12/12", "3/4 (1 bad) +2 n/w +9 d/o", "-"

// The class, decided: the assignment, and each student's result, grade and cells.
struct StudentView {
  const ClassRow* row = nullptr;
  std::string status;    // status_of(row)
  std::string result;    // PASS, INCOMPLETE, FAIL, NOTHING CHECKED, DOES NOT COMPILE, NOT CHECKED, NO SUBMISSION,
                         // GRADER ERROR
  std::string language;  // "Python", "Octave", "C++", or "" when not checked
  StudentResult graded;  // what the gradebook reads
  Score score;           // the grade under the rubric
  std::map<std::string, AreaCell> areas;
  std::string report_link;  // "<name>/report.md", or "" when there is no report
};
// What the class got wrong (the lecture to repeat): a slot found wrong, or a claim found false, with
// how many of the students checked, who, and the most common first fix among them (its line as
// one of them was told; fixes are grouped with the student's own names and the numbers left out).
struct ClassMistake {
  std::string kind;              // "slot" or "claim"
  std::string what;              // "vee", or "midpoint casimir"
  int students = 0;              // how many got it wrong
  int checked = 0;               // of how many checked (compiled and run)
  std::vector<std::string> who;  // their names, sorted
  std::string common_fix;        // the most common first fix (one student's words), or ""
  int common_fix_students = 0;   // how many were told that fix
};

struct ClassView {
  std::vector<std::string> assignment;  // the slots the grades count (resolve_assignment)
  bool assignment_from_rubric = false;  // false: every slot a student of the class provides
  std::vector<StudentView> students;    // in the rows' order
  std::string no_grades;                // not empty: the rubric leaves this class nothing to grade (why)
  std::vector<ClassMistake> mistakes;   // most students first, then by name
};

// What the class got wrong, from its decided students (decide_class fills view.mistakes with it).
std::vector<ClassMistake> class_mistakes(const ClassView& view);

// `rows` must outlive the view. When the rubric leaves the class nothing to grade, every student
// gets no grade and `no_grades` says why.
ClassView decide_class(const std::vector<ClassRow>& rows, const Rubric& rubric);
// A temporary would leave the view pointing at freed rows (ASan caught one in a test): refused.
ClassView decide_class(std::vector<ClassRow>&& rows, const Rubric& rubric) = delete;

// One student in words, as plain text parts each renderer escapes and joins (summary.md, summary.html,
// an autograder's output): the result and grade first ("FAIL, 80.00 of 100: 3 of 4 slots correct"),
// then what is wrong or missing, the claims, the checks that fail, and the first fix last.
std::vector<std::string> words_of(const StudentView& s);

// The gradebook's view of one row (slots provided and exercised, wrong ones with their first fix,
// areas, claims).
StudentResult student_result(const ClassRow& row);

}  // namespace gm::harness
