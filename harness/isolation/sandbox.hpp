// Untrusted mode's sandbox: the command line that runs a program (a submission's
// protocol server, or the compiler on a submission's source) inside bubblewrap, a maintained
// Debian tool (package bubblewrap), with limits the kernel keeps.
//
// What the sandboxed program sees and may do:
//   - the system read-only (/usr, /etc and the /bin, /lib links), its own /proc and a minimal /dev;
//   - read-only: the paths listed in `read_only` (its program, its source), nothing else of this
//     machine: no home, no other submission, no report, no suite source beyond the headers named;
//   - writable: a private /tmp (tmpfs of `scratch_mb`), its working directory, and at most one
//     bound directory (`writable`: the compiler's output folder);
//   - no network (own network namespace with no interface up), no other process (own PID
//     namespace), a new session (no terminal), no capabilities, no user namespace of its own; when
//     started as root, it runs as nobody;
//   - no environment but the documented one, in its own processes and in the sandbox's (bubblewrap
//     is its PID 1: /proc/1/environ is empty but for PATH, /proc/1/cmdline names only the private
//     copy's temporary folder, harness/isolation/private_copy.hpp);
//   - limits: a number of tasks for the whole sandbox (RLIMIT_NPROC, which the kernel counts per user
//     namespace, so the sandbox's own processes alone; and a cgroup's pids.max as root), a memory
//     total for the whole sandbox (a cgroup, as root; else an address-space limit per process), one
//     share of the CPU (its own cgroup as root; setsid() refused everywhere, harness/isolation/
//     session_filter.hpp), CPU time, the size of any file written, open files.
//
// The chain that starts it, each step a program of the system:
//   dash PRELUDE (cgroups, descriptors) -> env -i -> [setpriv, as root] -> bwrap -> dash LIMITS -> argv
// Whether the sandbox started the program is bubblewrap's word (its status descriptor), never the
// program's output: see SandboxStart.
#pragma once

#include <sys/types.h>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

struct SandboxLimits {
  // The memory of the whole sandbox, its /tmp included: a cgroup's total as root; else each
  // process's writable memory (RLIMIT_DATA, which V8's WebAssembly reservations do not count; an
  // address-space limit would). 0: none (AddressSanitizer maps terabytes of shadow memory).
  long memory_mb = 4096;
  int cpu_seconds = 600;  // RLIMIT_CPU (the harness's own timeout stops a hang sooner)
  // Tasks (processes and threads) of the sandbox's program, its first process included; bubblewrap's
  // own init beside them is not counted.
  int processes = 32;
  int file_mb = 64;      // RLIMIT_FSIZE: the largest file it may write
  int open_files = 256;  // RLIMIT_NOFILE
  int scratch_mb = 64;   // size of its private /tmp
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
  // bubblewrap writes its status (whether it started the program, and its exit status) for
  // sandbox_start, under the pid of the process run_process or fork started with this command.
  bool report_start = false;
};

// What bubblewrap reported of a sandbox started with report_start: `started` when it executed the
// program (its status holds an exit code), with that exit code; not started when the sandbox itself
// (a wrapper before it, or bubblewrap's own set-up: a path it cannot bind, no namespaces) failed,
// whatever the output says. Read once: the report is removed.
struct SandboxStart {
  bool reported = false;  // the sandbox's first step opened the report (a command made with report_start)
  bool started = false;
  int exit_code = -1;
};
SandboxStart sandbox_start(pid_t first_process);

// The exit statuses of the sandbox's last wrapper, inside it, before the program runs: a limit it
// could not set (125), the program not found or not executable there (127, 126). A compiler exits
// with 0, 1 or 4, never these; a program under test may, so they are told only for the compiler.
constexpr int kSandboxLimitFailed = 125;
inline bool is_sandbox_wrapper_status(int status) { return status >= 125 && status <= 127; }

// The exit status of a command stopped by the grader's machine or set-up (a sandbox that cannot start,
// a cache or an interpreter out of its reach), not by the code under test; and the error that says so.
constexpr int kExitMachine = 3;
struct MachineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Empty when the sandbox can be used; otherwise why not (bwrap or prlimit missing or not working),
// with what to install. Checked once per process (it starts bwrap once).
std::string sandbox_unavailable();

// argv wrapped: dash PRELUDE ... -- env -i ... [setpriv ... --] bwrap ... -- dash LIMITS argv...
std::vector<std::string> sandboxed(const std::vector<std::string>& argv, const SandboxSpec& spec);

// The first folder on the way to `p` that the sandbox's user (nobody, when the harness runs as
// root) cannot pass, with " (does not exist)" if it is missing; empty when every folder lets it pass
// (bubblewrap binds as that user, so a folder under a 0700 one, as mktemp -d makes, is out of reach).
std::string sandbox_cannot_reach(const std::string& p);

// The limits in words, as this machine keeps them (for `geomech self-test` and docs/UNTRUSTED.md).
std::string sandbox_limits_in_words(const SandboxLimits& limits = SandboxLimits{});

// The uid the sandboxed program runs as (nobody when started as root, else ours): a directory it
// must write to is handed to it with this.
unsigned sandbox_uid();

}  // namespace gm::harness
