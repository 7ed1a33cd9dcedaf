// Gradebook export for `geomech check-class --grades FILE.csv [--rubric FILE.json]`.
//
// Turns the per-student results of a class check into one CSV file that the
// gradebook import of Moodle or Canvas accepts. The grading policy lives in a
// small JSON rubric (see GRADEBOOK.md); everything here is pure: no file I/O,
// so the caller decides where the text goes and writes it atomically.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gm::harness {

struct ClaimResult {
  std::string integrator;  // e.g. "midpoint"
  std::string claim;       // e.g. "order", "casimir", "energy", "symmetric", "bounded_energy", ...
  std::string status;      // "verified", "FALSE CLAIM", "UNCHECKED", "not claimed"... (only "verified" earns credit)
};

// The status of a submission a class run has not checked yet (stopped before it): its gradebook
// row has no grade, and says so.
inline const std::string kNotCheckedYet = "not checked yet";
// The grader's machine or set-up failed the check (a sandbox that cannot start, a cache or an
// interpreter out of its reach, a check starved of CPU): no grade, and it is checked again.
inline const std::string kGraderError = "grader error";

struct StudentResult {
  std::string name;    // the implementation's name in the class (file stem or folder name); unique
  std::string status;  // "checked", "does not compile", "not checked", "no submission", kNotCheckedYet, kGraderError
  std::vector<std::string> provided;     // slot names the submission provides (any scalar) and a check exercised
  std::vector<std::string> unexercised;  // slots it provides that no check that ran called
  std::vector<std::string> wrong;        // provided slots the check found wrong, first fix first
  std::map<std::string, std::string> why_wrong;      // slot -> the line its first fix says
  std::map<std::string, std::pair<int, int>> areas;  // area name -> (checks passed, checks run)
  std::vector<ClaimResult> claims;                   // every claim an integrator made, with its verdict
  std::string first_fix;                             // one line, may be empty: what to fix first
  std::string report;                                // relative link to the student's report, e.g. "alice/report.md"
  bool left_to_lecturer = false;  // kGraderError, met in every run of this submission alone: the lecturer decides
};

// Which LMS import the CSV is shaped for; the two want different columns.
enum class LmsFormat { moodle, canvas };

// Area names a rubric may weight. A misspelt area would silently cost every
// student its share, so the rubric parser rejects names not listed here.
inline const std::vector<std::string> kKnownAreas = {"sec. 1", "sec. 2", "sec. 3", "momentum maps", "integrators"};

// The grading policy. A default-constructed Rubric is the documented default:
// partial credit per correct slot, out of 100, Moodle columns.
struct Rubric {
  std::string source = "(default rubric)";  // file name, quoted in error messages
  std::string item = "geomech";             // grade item / assignment column header
  double points = 100;                      // maximum grade
  LmsFormat format = LmsFormat::moodle;
  bool feedback = true;     // Moodle only: add a feedback column
  double slot_default = 1;  // credit per correct slot not named below
  std::map<std::string, double> slot_weights;
  std::optional<std::vector<std::string>> assignment;  // unset: every slot the class provides
  std::map<std::string, double> area_weights;          // absent area: weight 0
  double claims_weight = 0;                            // share of the grade for claims (0: claims ignored)
  double claim_default = 1;                            // relative weight of a claim not named below
  std::map<std::string, double> claim_weights;
  // When an autograder shows a slot's, a claim's or an area's test to the student (Gradescope's
  // test visibility; AUTOGRADERS.md, "Hidden tests"): one of kVisibilityLevels, by name.
  std::map<std::string, std::string> visibility;
  std::string visibility_default = "visible";
};

// Gradescope's words, in order of what a student sees: a test "visible" now, shown
// "after_due_date", "after_published" (when the lecturer publishes the grades), or "hidden" (never).
inline constexpr std::array<const char*, 4> kVisibilityLevels = {"visible", "after_due_date", "after_published",
                                                                 "hidden"};

// Parses rubric JSON. Throws std::runtime_error naming `source`, the offending
// key and what was expected (unknown key, wrong type, negative weight, ...).
Rubric parse_rubric(std::string_view json_text, const std::string& source);

// LMS identifiers for one implementation, read from an optional roster CSV
// with a `name` column and any of the columns named in the comments.
struct RosterEntry {
  std::string full_name;     // full_name: Canvas "Student" (it matches by name last)
  std::string username;      // username: Moodle "Username"
  std::string email;         // email: Moodle "Email address"
  std::string id_number;     // id_number: Moodle "ID number"
  std::string canvas_id;     // canvas_id: Canvas "ID" (numeric Canvas user id)
  std::string sis_user_id;   // sis_user_id: Canvas "SIS User ID"
  std::string sis_login_id;  // sis_login_id: Canvas "SIS Login ID"
  std::string section;       // section: Canvas "Section"
};
using Roster = std::map<std::string, RosterEntry>;  // keyed by implementation name

// Parses a roster CSV (UTF-8, optional BOM, CRLF or LF). Throws
// std::runtime_error naming `source` on malformed CSV, a missing `name`
// column, an unknown column, an empty or duplicate name.
Roster parse_roster(std::string_view csv_text, const std::string& source);

// Roster problems worth telling the lecturer: students without a roster row
// (they fall back to their implementation name) and roster rows without a student.
std::vector<std::string> roster_warnings(const std::vector<StudentResult>& cls, const Roster& roster);

// The slots the assignment asks for: the rubric's list, or else every slot at
// least one student of the class provides (sorted).
std::vector<std::string> resolve_assignment(const Rubric& rubric, const std::vector<StudentResult>& cls);

// One part of a grade: an assignment slot, a weighted area, or a claim's share. Every view of a
// grade (the gradebook's feedback, the summaries, Gradescope's tests, PrairieLearn's) lists these.
struct ScoreItem {
  enum class Kind { Slot, Area, Claim };
  Kind kind = Kind::Slot;
  std::string name;                    // the slot, the area, or "<integrator> <claim>" ("claims" when none was made)
  double weight = 0;                   // its maximum in the rubric's weights (a claim: its share of claims_weight)
  double earned = 0;                   // of that weight
  double max_points = 0;               // weight scaled to the rubric's points (not rounded)
  double points = 0;                   // earned scaled to the rubric's points (not rounded)
  std::string state;                   // slot: correct, wrong, missing, not exercised; area: "k/n checks passed";
                                       // claim: its status; or the student's status when not graded
  std::string detail;                  // why, in words (a wrong slot: its first fix); may be empty
  std::string visibility = "visible";  // the rubric's, for its slot, claim or area (kVisibilityLevels)
};

struct Score {
  double points = 0;  // 0 .. rubric.points, rounded to 2 decimals
  // No grade at all (the grader's machine failed the check, or it is not checked yet): every view
  // shows none (an empty gradebook cell, "-" in a summary), never `points`.
  bool no_grade = false;
  double max_points = 0;               // rubric.points
  std::vector<ScoreItem> items;        // what the grade is made of; their points add up to `points` before rounding
  std::vector<std::string> breakdown;  // e.g. "slots 3/4", "sec. 1 5/6", "claims 2/3 verified"
  std::string headline;                // "80.00 of 100: 3 of 4 slots correct (weight 4 of 5)"
  std::vector<std::string> notes;      // "wrong: casimir (weight 1)", "missing: ...", "false claims: ..."
  std::string feedback;  // one line of at most 400 bytes: the grade, what it rests on, the first fix, the report
};

// Scores one student against an already resolved assignment. Throws
// std::runtime_error if the rubric's maximum is 0 for this assignment.
Score score_student(const StudentResult& student, const Rubric& rubric, const std::vector<std::string>& assignment);

// The exact header row for the rubric's format and item.
std::vector<std::string> gradebook_header(const Rubric& rubric);

// The whole class as CSV text: UTF-8 without BOM, CRLF line ends, rows sorted
// by implementation name. Throws std::runtime_error on duplicate names.
std::string write_gradebook_csv(const std::vector<StudentResult>& cls, const Rubric& rubric,
                                const std::optional<Roster>& roster = std::nullopt);

// CSV helpers (RFC 4180), public so tests and callers can check the shape.
std::string csv_field(std::string_view value);  // quotes only when needed
// A cell that a spreadsheet would read as a formula (it starts with =, +, -, @, a tab or a carriage
// return: OWASP's "CSV injection" guidance) made text by a leading apostrophe; a number such as
// "-1.5" stays a number. Every cell of the gradebook goes through it (a file named
// "=1+1.py" is a student named "=1+1").
std::string spreadsheet_safe(const std::string& cell);
// Strict parser: accepts CRLF or LF; throws std::runtime_error (with a line
// number) on an unbalanced quote, a quote inside an unquoted field, text after
// a closing quote or a bare CR.
std::vector<std::vector<std::string>> parse_csv(std::string_view text);
std::string format_points(double value);  // "75.00", independent of any locale

}  // namespace gm::harness
