// The user's interpreter inside untrusted mode's sandbox. The sandbox shows the system
// (/usr) and nothing else of this machine; an interpreter outside it (a venv, pyenv, an Octave of
// one's own) is shown read-only at its own path, and nothing more: Python's sys.prefix and
// sys.base_prefix (a venv: both, its own folder and the installation it was made from), the folder
// of the real executable behind a link or a pyenv shim; Octave's installation folder. Asked of the
// interpreter itself, outside the sandbox (it is the checker's, not the submission's).
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

struct SandboxedInterpreter {
  std::string program;                 // what to run inside (a shim resolved to the real interpreter)
  std::vector<std::string> read_only;  // what the sandbox must show (SandboxSpec::read_only)
  std::string error;                   // why it cannot run in the sandbox (empty: it can)
};

// `language` "python" or "octave"; `interpreter` as server_command chose it.
SandboxedInterpreter interpreter_for_sandbox(const std::string& language, const std::string& interpreter);

}  // namespace gm::harness
