// summary.html: a class run as one page to read, beside summary.md, rendered from the same
// decided ClassView (harness/class/class_record.hpp). Self-contained: no network, inline style and script;
// the class table (student x area of the notes, with the result, the grade and the first fix) sorts
// by any column (click a heading, or open the page as summary.html#sort=COLUMN or #sort=-COLUMN);
// each student in words; each name links to the student's report.html (report.md as a page, with its
// figures inline, written by the student's own check).
#pragma once

#include "harness/class/class_record.hpp"

#include <string>
#include <vector>

namespace gm::harness {

struct ClassPage {
  std::string class_name;            // the class folder as given
  std::string rubric_source;         // the rubric the grades follow ("(default rubric)" or a file)
  std::vector<std::string> pending;  // not checked yet: the page of a run still going (or stopped)
  bool grades_withheld = false;      // a partial run: the gradebook was not written (say so)
};

std::string class_summary_html(const ClassView& view, const ClassPage& page);

// The column keys #sort= accepts, in table order: "name", "result", "grade", one per area
// ("sec-1", ..., "integrators"), "first-fix".
std::vector<std::string> class_table_columns();

}  // namespace gm::harness
