// The end of every command that checks (geomech check, a student's check program, check-trajectory):
// the console's report, or under --quiet one line (the verdict, its counts, the costly runs left to
// --thorough, and each UNCHECKED reason, which is why it is not a pass); then the report folder and
// the files each format's own option asked for (harness/reports/report_formats.hpp), written.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/reports/report_formats.hpp"
#include "spec/catalogue.hpp"

#include <string>

namespace gm::harness {

struct ReportTail {
  bool quiet = false;
  std::string report_dir;  // every format's file and figures/ (empty: none)
  FormatFiles also;        // a format's option -> a file of its own ("--junit" -> "out.xml")
};

// The check's exit status; 2 when a file cannot be written (said on stderr, with the reason).
int finish_check(const CheckResult& r, const Catalogue* catalogue, const ReportTail& tail);

}  // namespace gm::harness
