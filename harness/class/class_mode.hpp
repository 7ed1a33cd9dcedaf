// Class mode: a folder of implementations checked in parallel, one report per implementation and
// one summary (implementation x area of the notes, then each student in words), optionally a
// gradebook CSV. The summary is rewritten, atomically, as each implementation finishes, so an
// interrupted run leaves one for what is done, and a re-run resumes where it stopped.
//
// Implementations are the *.cpp, *.py and *.m files directly in the folder (Python and Octave run
// through docs/PROTOCOL.md), and each sub-folder holding exactly
// one .cpp that uses GEOMECH_STUDENT (a student's own folder, with headers beside it). Each is
// built and checked in its own process, `jobs` at a time; a student whose code does not compile,
// crashes or hangs gets a row saying so, and the others are unaffected.
//
// The class folder is a stranger's (harness/isolation/submission_intake.hpp): it is read without
// following a link or opening a FIFO or device, each submission is copied (a snapshot, within
// limits) into the compilers' cache (<cache>/class-<id>/submissions/<name>/) and what is checked,
// fingerprinted and compiled is that copy. A C++ file in a flat class folder sees only itself and the headers the lecturer shares on
// purpose (--shared), never a classmate's. A submission holding a link, a FIFO, a socket, a device
// or a hard link, or whose name cannot name a report, is NOT CHECKED with a row saying which file.
#pragma once

#include "harness/program/build.hpp"
#include "harness/program/cli.hpp"

#include <string>
#include <vector>

namespace gm::harness {

// The gradebook export (harness/class/gradebook.hpp, docs/GRADEBOOK.md): written with the summary when
// `csv` is set; the rubric and the roster are read before anything is checked.
struct GradeOptions {
  std::string csv;           // --grades FILE.csv
  std::string rubric;        // --rubric FILE.json (default: partial credit per correct slot)
  std::string roster;        // --roster FILE.csv (implementation name -> the LMS's identifiers)
  std::string feedback_dir;  // --feedback-dir DIR: one page per student, named for the LMS's bulk upload
};

struct ClassOptions {
  std::string dir;
  std::string report_dir;  // default: geomech-reports/<folder name>
  int jobs = 2;            // implementations at once
  double timeout_per_implementation = 1800;
  std::string front_door;  // how to call geomech in printed commands (e.g. "./geomech")
  std::string command;     // this run's command line without --fresh: what resumes it (said on Ctrl-C)
  CheckCliOptions check;   // forwarded to every implementation's check
  BuildOptions build;      // how each implementation is compiled (jobs is set to 1)
  // Untrusted mode (the default): every implementation is compiled and run in the
  // sandbox as its own process behind the slot protocol (`geomech check FILE --untrusted`).
  bool untrusted = true;
  // --shard K/N: only the K-th of N deterministic shares of the class (the implementations sorted
  // by name, every N-th from the K-th on); `merge_class` combines the shards' report folders.
  int shard_k = 1;
  int shard_n = 1;
  // Resuming: an implementation whose report is complete and whose source, options and
  // suite are unchanged since (class-row.json beside its report holds their fingerprint) is not
  // checked again; --fresh checks everyone.
  bool fresh = false;
  // A regrade (a lecturer's term): --regrade NAME (repeatable) checks those implementations again
  // whatever their last result; --not-checked checks again those whose last result is NOT CHECKED
  // (a timeout, a raise of the whole check). Every other follows the resume rule above, so the
  // summary and the gradebook still cover the whole class.
  std::vector<std::string> regrade;
  bool not_checked = false;
  GradeOptions grades;
  // --shared FILE: headers (or other files) given to every C++ submission of the class, on
  // purpose; nothing else of the class folder is shared.
  std::vector<std::string> shared;
};

// What the check of a submission depends on besides its files, for the fingerprint that decides
// whether a class run resumes it: the mode, the check's options and, for a C++ file, the libraries
// the command line adds (--pkg, --cxxflags, --ldflags, -I, -L, -l; its own `// geomech:` lines are
// in its text). `extension` is the submission's (".cpp", ".py", ".m", "" for a folder).
std::string check_conditions(const ClassOptions& o, const std::string& extension);

struct Implementation {
  std::string name;     // unique within the class (file stem, or folder name)
  std::string source;   // what is checked: the file (or Octave folder); in the snapshot once taken
  std::string origin;   // where it is in the class folder, relative to it: "bob.py", "bob/rigid.cpp", "bob"
  std::string refused;  // not empty: NOT CHECKED, and why (a link, a FIFO, a device, a bad name, a limit)
};

// The implementations of a class folder, sorted by name, read without following anything
// (harness/isolation/submission_intake.hpp); one that cannot be checked comes back with `refused` set.
// Throws std::runtime_error when the folder cannot be read or holds none.
std::vector<Implementation> find_implementations(const std::string& dir);

// The report folder of a class when none is given: geomech-reports/<the class folder's name>,
// the same however the folder is written ("week3", "week3/", "./week3", an absolute path).
std::string default_class_report_dir(const std::string& class_dir);

int run_class(const ClassOptions& o, const Toolchain& tc);

// The K-th of N shares of a class (1 <= K <= N): implementations i with i mod N = K - 1.
std::vector<Implementation> shard_of(const std::vector<Implementation>& all, int k, int n);

// `geomech merge-class OUT SHARD_DIR...`: the shards' results (class-shard.json and one report per
// implementation in each shard folder) as one class report in OUT, with the same summary table as
// an unsharded run. Throws std::runtime_error for a missing, repeated or foreign shard.
int merge_class(const std::vector<std::string>& shard_dirs, const std::string& out_dir,
                const GradeOptions& grades = {});

}  // namespace gm::harness
