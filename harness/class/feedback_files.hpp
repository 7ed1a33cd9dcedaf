// Feedback where students read it: `--feedback-dir DIR` writes one file per student of a
// class run, named so that the LMS's bulk upload takes DIR as it is (zip its content):
//   - Moodle ("Upload multiple feedback files in a zip"): a folder per student, named as Moodle's
//     "Download all submissions" names it, "Full Name_12345_assignsubmission_file_", holding
//     geomech-feedback.html. A class folder made by unzipping that download has these names already
//     (one folder per student), so nothing is mapped by hand.
//   - Canvas ("Re-upload submissions"): a file that keeps the download's prefix, the student's name
//     and their user and submission ids, "lastfirst_12345_67890_geomech-feedback.html" (a late one's
//     "lastfirst_LATE_12345_67890_").
//   - any other name: NAME.html, and the run says which names are not an LMS's.
// The page is self-contained: the result and grade, what the grade rests on, what is wrong with its
// first fix, and the command that checks the file again; never the grader's paths.
#pragma once

#include "harness/class/class_record.hpp"

#include <string>
#include <vector>

namespace gm::harness {

struct FeedbackName {
  std::string path;  // relative to the feedback folder
  std::string lms;   // "Moodle", "Canvas" or "" (a name no LMS gave)
};

// The feedback file of the implementation called `name` in the class (its file stem or folder name).
FeedbackName feedback_name(const std::string& name);

// Writes every checked, uncompiled or unchecked student's page into `dir` (created; each file
// atomically); a roster student with nothing handed in gets none. Returns one line per kind of name
// for the console ("4 for Moodle's bulk upload (zip the folder's content)", ...).
std::vector<std::string> write_feedback_files(const ClassView& view, const std::string& dir);

}  // namespace gm::harness
