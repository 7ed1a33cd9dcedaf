// A file in, a check out: the routes by which an implementation is checked.
//   - a C++ file, trusted: compiled with the suite into a check program (harness/program/build.hpp);
//   - a Python or Octave file: started as a protocol server (docs/PROTOCOL.md), checked from here;
//   - any of them, untrusted: in the sandbox, behind the protocol, a C++ file compiled there into a
//     server that links nothing of the judge (docs/UNTRUSTED.md);
//   - a built-in subject (the reference, a negative control): checked in this process.
#pragma once

#include "harness/engine/check.hpp"
#include "harness/program/build.hpp"
#include "harness/program/cli.hpp"

#include <string>

namespace gm::harness {

struct SubmissionRequest {
  std::string file;              // the implementation: a .cpp, .py or .m file, or a folder of .m files
  bool sandboxed = false;        // untrusted mode (--untrusted)
  CheckCliOptions check;         // what to check and how (harness/program/cli.hpp)
  BuildOptions build;            // how a C++ file is compiled
  std::string front_door = "geomech";  // how the user called us, for the commands we print
  std::string reproduce_prefix;  // the replay command the report prints ("" = the check's own command)
};

// Checks `r.file` by its route and prints what it found; the exit status of `geomech check`
// (0 every property holds, 1 one fails, 2 the file or an option, kExitMachine the grader's set-up).
int check_submission(const SubmissionRequest& r);

// A built-in subject, by the same report path: `name` is what the replay command names.
int check_builtin_subject(const SubjectSet& subject, const std::string& name, const SubmissionRequest& r);

}  // namespace gm::harness
