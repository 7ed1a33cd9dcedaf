// The options of a check, shared by `geomech check` (built-in subjects) and by the program that
// checks a student's implementation (tools/student_check_main.cpp), so both accept the same flags and a
// reproduce command printed by one works with the other.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/program/library_flags.hpp"
#include "harness/reports/report_formats.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gm::harness {

int default_jobs();  // the number of cores (at least 1)

struct CheckCliOptions {
  std::vector<std::string> properties;
  std::string spec_prefix;
  std::string scalar = "all";
  std::string integrator;
  std::uint64_t seed = 0;
  int cases = 0;
  double case_factor = 1.0;
  bool case_factor_given =
      false;  // --case-factor was given (else an implementation behind the protocol gets the matrix's)
  std::string reproduce;
  double timeout = 60;
  bool timeout_given = false;  // set by the parser: the replay command repeats --timeout only then
  double case_budget = -1;     // seconds after which no new case starts; < 0: 40 % of the timeout; 0: none
  int jobs = default_jobs();   // the cores of this machine
  long memory_limit_mb = 4096;
  std::string report_dir;  // write every format's file and figures/ here (harness/reports/report_formats.hpp)
  FormatFiles also;        // a format's own option -> its file ("--junit" -> "out.xml")
  bool no_isolation = false;
  bool no_portraits = false;
  bool quiet = false;  // only the summary line and the report's path
  // Only every slot's own definition check, in double, no report, no pictures: the first look
  // `geomech check FILE.cpp` takes while the other scalars compile.
  bool definitions_only = false;
  // The quick profile (harness/checking/quick_profile.hpp): only its checks.
  bool quick = false;
  // Also the costly 50-digit runs that an implementation behind the protocol otherwise leaves out
  // (harness/checking/thorough_only.hpp); nothing changes for an implementation linked in.
  bool thorough = false;

  // Its properties are a selection (by name, by catalogue entry, or a replay's one check), not all.
  bool selects_properties() const { return !properties.empty() || !spec_prefix.empty() || !reproduce.empty(); }
  // Narrowed: not the whole suite (a selection of properties, one scalar, one integrator, a replay).
  // A narrowed check writes its report only when asked, so that a replay never replaces the full one.
  bool narrowed() const { return selects_properties() || scalar != "all" || !integrator.empty(); }
};

void add_check_options(CLI::App& app, CheckCliOptions& o);

// Turns the options into a CheckConfig (throws CLI::ValidationError for a bad --scalar or an
// unknown --property).
CheckConfig config_from(const CheckCliOptions& o);

// The options again as command-line arguments (to hand them to a student's check program).
std::vector<std::string> to_args(const CheckCliOptions& o);

// The libraries a C++ file uses, as given on the command line of `geomech check` and `check-class`
// (harness/program/library_flags.hpp): --pkg NAME, --cxxflags FLAGS, --ldflags FLAGS, -I DIR, -L DIR, -l NAME.
struct LibraryCli {
  std::vector<std::string> pkg, cxxflags, ldflags, include, libdir, lib;
  LibraryRequest request() const;  // throws std::invalid_argument for flags that do not split
};
void add_library_options(CLI::App& app, LibraryCli& o);
// The request again as arguments of `geomech check` (class mode hands them to each check).
std::vector<std::string> library_args(const LibraryRequest& r);

// Runs the check, prints the console report, writes the report files; returns the exit status
// (0 all good, 1 something failed, 2 the report could not be written).
int run_check_cli(const SubjectSet& subject, const SubjectInfo& info, const CheckCliOptions& o);

}  // namespace gm::harness
