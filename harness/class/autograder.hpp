// Autograders for the platforms where courses grade: Gradescope and PrairieLearn.
//
// `geomech autograder gradescope DIR` writes what Gradescope's autograder zip holds (setup.sh,
// run_autograder, the suite's source and the assignment's rubric) and the zip itself;
// `geomech autograder prairielearn DIR` writes the external grader's entrypoint and a Dockerfile for
// its image. Inside the grader, both run `geomech grade-submission`, which checks the submission as a
// class of one (check-class: sandboxed, its record kept) and renders the record as the platform's
// results.json. The formats, as their documentation gives them (docs/AUTOGRADERS.md cites it):
//   Gradescope   /autograder/results/results.json: score, output, output_format, visibility,
//                stdout_visibility, tests[] with name, score, max_score, status, output, output_format,
//                visibility (gradescope/autograder_samples, docs/specs.md);
//   PrairieLearn /grade/results/results.json: gradable, score in [0, 1], message, output, format_errors,
//                tests[] with name, description, points, max_points, message, output; at most 1 MB
//                (PrairieLearn/PrairieLearn, docs/externalGrading.md).
#pragma once

#include "harness/class/class_record.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace gm::harness {

enum class Platform { gradescope, prairielearn };
Platform platform_from_name(const std::string& name);  // throws std::runtime_error naming the two
std::string platform_name(Platform p);

struct AutograderOptions {
  Platform platform = Platform::gradescope;
  std::string out_dir;      // the autograder's folder (written; must be new or an earlier autograder)
  std::string rubric_file;  // required: a rubric with an "assignment" (one submission has no class to learn it from)
  std::vector<std::string> check_args;  // check options for every submission (--scalar, -p, --quick, --timeout ...)
  bool trusted = false;                 // in-process checks: only where the grader's sandbox cannot make namespaces
  double timeout_seconds = 540;         // one submission's build and check (PrairieLearn allows 600 s in all)
  std::string source_dir;               // the suite's source tree, packed into the autograder
  bool zip = true;                      // Gradescope: also write DIR.zip (Python's zipfile)
};
// Returns the exit status; throws std::runtime_error for a bad rubric or folder.
int write_autograder(const AutograderOptions& o);

struct GradeSubmissionOptions {
  Platform platform = Platform::gradescope;
  std::string submission;  // the folder the platform put the student's files in
  std::string results;     // the results.json to write
  std::string config;      // geomech-autograder.json written by write_autograder
  std::string work;        // scratch folder (default: a new one under $TMPDIR)
};
int grade_submission(const GradeSubmissionOptions& o);

// The renderers: one decided student (a class of one) as each platform's results. `report_md` is
// the student's report.md ("" when there is none). Pure: no I/O.
nlohmann::json gradescope_results(const StudentView& s, const std::string& report_md);
nlohmann::json prairielearn_results(const StudentView& s, const std::string& report_md);

// The implementation a submission folder holds, laid out as a class folder of one: `class_dir`/NAME
// (a file, or a folder with the submission's files). Returns NAME, or throws std::runtime_error
// saying what was found and what is expected. Links are copied as links (never followed).
std::string lay_out_submission(const std::string& submission, const std::string& class_dir);

}  // namespace gm::harness
