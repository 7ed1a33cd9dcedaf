// A file in, a check out: the routes by which an implementation is checked.
//   - a C++ file, trusted: compiled with the suite into a check program (harness/program/build.hpp);
//   - a Python or Octave file: started as a protocol server (docs/PROTOCOL.md), checked from here;
//   - a Jupyter notebook: its code cells served by the row its kernel names, checked from here;
//   - any of them, untrusted: in the sandbox, behind the protocol, a C++ file compiled there into a
//     server that links nothing of the judge (docs/UNTRUSTED.md);
//   - a built-in subject (the reference, a negative control): checked in this process.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/program/build.hpp"
#include "harness/program/cli.hpp"

#include <optional>
#include <string>

namespace gm::harness {

struct SubmissionRequest {
  std::string file;                    // the implementation: a file of a language of the table, or a folder of .m files
  bool sandboxed = false;              // untrusted mode (--untrusted)
  CheckCliOptions check;               // what to check and how (harness/program/cli.hpp)
  BuildOptions build;                  // how a C++ file is compiled
  std::string front_door = "geomech";  // how the user called us, for the commands we print
  std::string reproduce_prefix;        // the replay command the report prints ("" = the check's own command)
  // The first look (a C++ file's definitions in double while the rest compiles, failures printed as
  // they come): for a check someone watches, not for a quiet one.
  bool first_look = true;
  std::string outcome_file;  // where the outcome is written (JSON), for a class row; "" = nowhere
};

// How a check ended, as a class row records it: whether the file was built (a C++ file), what
// the compiler said when not, the grader's fault when the set-up failed, the times.
struct SubmissionOutcome {
  int exit_code = 2;  // 0 every property holds, 1 one fails, 2 the file or an option, kExitMachine the set-up
  bool built = true;  // false: the file does not compile (build_message says why)
  std::string build_message;
  double build_seconds = 0;
  std::string machine_fault;  // the grader's machine or set-up, not the file; its fix
  double check_seconds = 0;
};

// Checks `r.file` by its route, prints what it found and writes the outcome to r.outcome_file;
// returns the exit status of `geomech check` (the outcome's exit_code).
int check_submission(const SubmissionRequest& r);

// The outcome a check wrote; nullopt when there is none (the check ended before writing it).
std::optional<SubmissionOutcome> read_outcome(const std::string& path);

// A built-in subject, by the same report path: `name` is what the replay command names.
int check_builtin_subject(const SubjectSet& subject, const std::string& name, const SubmissionRequest& r);

}  // namespace gm::harness
