// Untrusted mode's sandbox: the command line that runs a program (a submission's
// protocol server, or the compiler on a submission's source) inside bubblewrap, a maintained
// Debian tool (package bubblewrap), with limits set by prlimit (util-linux).
//
// What the sandboxed program sees and may do:
//   - the system read-only (/usr, /etc and the /bin, /lib links), its own /proc and a minimal /dev;
//   - read-only: the paths listed in `read_only` (its program, its source), nothing else of this
//     machine: no home, no other submission, no report, no suite source beyond the headers named;
//   - writable: a private /tmp (tmpfs of `scratch_mb`), its working directory, and at most one
//     bound directory (`writable`: the compiler's output folder);
//   - no network (own network namespace with no interface up), no other process (own PID
//     namespace), a new session (no terminal), no capabilities; when started as root, it runs as
//     nobody (so the process limit applies: root is exempt from RLIMIT_NPROC);
//   - no environment but the documented one, in its own processes and in the sandbox's (bubblewrap
//     is its PID 1: /proc/1/environ is empty but for PATH, /proc/1/cmdline names only the private
//     copy's temporary folder, harness/isolation/private_copy.hpp);
//   - limits: address space, CPU time, processes, size of any file written, open files.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

struct SandboxLimits {
  int memory_mb = 4096;   // RLIMIT_AS (0: none; AddressSanitizer reserves terabytes of address space)
  int cpu_seconds = 600;  // RLIMIT_CPU (the harness's own timeout stops a hang sooner)
  int processes = 32;     // RLIMIT_NPROC, beyond what the user already runs
  int file_mb = 64;       // RLIMIT_FSIZE: the largest file it may write
  int open_files = 256;   // RLIMIT_NOFILE
  int scratch_mb = 64;    // size of its private /tmp
};

struct SandboxSpec {
  std::vector<std::string> read_only;  // visible read-only, at the same path
  // Visible read-only at another path (path here, path inside): a submission and the suite's files
  // it needs are shown under neutral names (/submission, /geomech), so that nothing inside, not
  // even the program's own command line, names a folder of the machine.
  std::vector<std::pair<std::string, std::string>> mounts;
  std::string writable;                                  // a directory visible read-write at the same path (or empty)
  std::string chdir;                                     // working directory inside (default /tmp)
  std::vector<std::pair<std::string, std::string>> env;  // the environment inside (besides PATH, HOME, LANG)
  SandboxLimits limits;
};

// The exit status of a command stopped by the grader's machine or set-up (a sandbox that cannot start,
// a cache or an interpreter out of its reach), not by the code under test; and the error that says so.
constexpr int kExitMachine = 3;
struct MachineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Empty when the sandbox can be used; otherwise why not (bwrap or prlimit missing or not working),
// with what to install. Checked once per process (it starts bwrap once).
std::string sandbox_unavailable();

// argv wrapped: [setpriv ... --] bwrap ... -- prlimit ... -- argv...
std::vector<std::string> sandboxed(const std::vector<std::string>& argv, const SandboxSpec& spec);

// The first folder on the way to `p` that the sandbox's user (nobody, when the harness runs as
// root) cannot pass, with " (does not exist)" if it is missing; empty when every folder lets it pass
// (bubblewrap binds as that user, so a folder under a 0700 one, as mktemp -d makes, is out of reach).
std::string sandbox_cannot_reach(const std::string& p);

// The uid the sandboxed program runs as (nobody when started as root, else ours): a directory it
// must write to is handed to it with this.
unsigned sandbox_uid();

}  // namespace gm::harness
