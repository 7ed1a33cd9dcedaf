// A system-call filter (seccomp) for the sandbox: setsid() fails with EPERM inside it. A process
// that starts a session of its own gets a scheduling group of its own (the kernel's autogroup),
// with a whole share of the CPU beside its parent's: sixteen such children took a classmate's
// share of a core from 43% to 10%. In a sandbox kept in a control group of its own (root,
// harness/isolation/sandbox_cgroup.hpp) the autogroup does not apply; the filter keeps the share
// one wherever the harness runs. bubblewrap starts the sandbox's own session (--new-session) before
// it applies the filter, and hands it the program from a descriptor (--seccomp).
#pragma once

#include <string>

namespace gm::harness {

// The filter's compiled program, as bubblewrap reads it (struct sock_filter, 8 bytes each).
std::string no_new_session_filter();

}  // namespace gm::harness
