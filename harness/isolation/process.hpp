// Running other programs (the compiler, a student's check program) without a shell: argv in,
// exit status and everything written to stdout and stderr out.
#pragma once

#include <sys/types.h>
#include <string>
#include <vector>

namespace gm::harness {

struct ProcessResult {
  int exit_code = -1;  // when it exited
  int signal = 0;      // when a signal ended it
  bool timed_out = false;
  bool started = false;    // false: it could not be started (output says why)
  bool cancelled = false;  // stopped, or never started, because a decisive process failed
  std::string output;      // stdout and stderr, interleaved
  double seconds = 0;
  pid_t pid = -1;  // the process started (a sandbox's status is kept under it: harness/isolation/sandbox.hpp)
};

struct ProcessSpec {
  std::vector<std::string> argv;
  std::string output_file;    // when set, output goes (also) to this file instead of memory
  bool pass_through = false;  // let the child write to our stdout/stderr (nothing captured)
  // When it fails (exits non-zero, or a signal ends it), the others are stopped and those not yet
  // started are not: their results say `cancelled`. The compile in double is decisive: when the file
  // does not compile, the other scalars' compiles can teach nothing.
  bool decisive = false;
};

// Runs the processes, at most `jobs` at once; timeout_seconds <= 0 means none. A captured child
// runs in a process group of its own, so that a timeout or a cancellation stops what it started
// (the compiler proper behind the driver) and not only itself.
std::vector<ProcessResult> run_processes(const std::vector<ProcessSpec>& specs, int jobs, double timeout_seconds = 0);

ProcessResult run_process(const ProcessSpec& spec, double timeout_seconds = 0);

// A program started by a class run dies with the process that started it when
// $GEOMECH_DIE_WITH_PARENT is set (class mode sets it for each check): an interrupted or timed-out
// class leaves no check running behind it. The variable stays set, so that what this program starts
// (the check program a `geomech check` runs) does the same. False when the parent is already gone.
bool die_with_parent_when_asked();

// The command as a shell would need it typed (for messages and reproduce lines).
std::string shell_quote(const std::string& s);
std::string shell_join(const std::vector<std::string>& argv);

}  // namespace gm::harness
