// Reports of a check: the console summary, Markdown for people, JUnit XML for CI, JSON for
// machines (and class mode), and SVG figures, written into one directory atomically (a report
// directory is either the previous one or the complete new one, never half of each).
#pragma once

#include "harness/checking/check.hpp"
#include "harness/checking/first_fix.hpp"
#include "spec/catalogue.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

// The area of the notes a property belongs to, for summary tables (class mode):
// "sec. 1", "sec. 2", "sec. 3", "momentum maps", "integrators".
std::string area_of(const Verdict& v, const Catalogue* catalogue);
const std::vector<std::string>& area_names();

// Every figure the verdicts and the portraits carry; series of the same property, integrator and figure are drawn together across
// scalars (double and 50 digits side by side).
struct Figure {
  std::string file;  // relative to the report directory: figures/<name>.svg
  std::string svg;
  std::string integrator;  // the integrator it belongs to, if any
};
std::vector<Figure> report_figures(const CheckResult& r);

// The first fixes (RootCauses, root_causes) are decided by the check (harness/checking/first_fix.hpp)
// and kept on the CheckResult (r.first_fixes); every view here renders them.

// How a report names a slot to fix: "slot 'x'" for C++; for another language, the function in the
// student's file ("Python function 'casimir' in mine.py").
std::string slot_named(const SubjectInfo& info, const std::string& slot, const char* quote);
// The first line of a message that says something (RapidCheck's "Exception thrown with message:"
// skipped).
std::string first_line(const std::string& s);
bool is_engine_wrapper(const CheckResult& r);  // integrators, and no slot of the notes

std::string console_report(const CheckResult& r, const Catalogue* catalogue, bool details = true);
std::string markdown_report(const CheckResult& r, const Catalogue* catalogue);
std::string junit_report(const CheckResult& r);
nlohmann::json json_report(const CheckResult& r, const Catalogue* catalogue);

// Writes every report format's file (report_formats.hpp) and figures/*.svg into `dir`, replacing a
// previous report there only once the new one is complete. Throws std::runtime_error on failure.
void write_report_dir(const CheckResult& r, const std::string& dir, const Catalogue* catalogue);

// Writes one file atomically (a temporary file in the same directory, then rename).
void write_file_atomically(const std::string& path, const std::string& content);

// The claims table of one integrator: for each claim, what was claimed and what the properties found.
// A claim's decision (harness/checking/integrator_verdicts.hpp) as the reports render it.
struct ClaimRow {
  std::string claim;
  std::string claimed;   // "2" for an order, "yes"/"no" otherwise
  std::string status;    // the decided word: "verified", "FALSE CLAIM", "NOT VERIFIED", "holds (not claimed)", ...
  std::string measured;  // "order 1.00 (double)", "loses energy: ..."
  std::string why;       // what kept it from being decided, or what contradicts it
  bool fails = false;    // a claim made and not shown true
  std::string evidence;
};
std::vector<ClaimRow> claim_rows(const CheckResult& r, const IntegratorInfo& integrator);

}  // namespace gm::harness
