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

// A Python interpreter (as a language's row chose it): asked where it lives (sys.prefix,
// sys.base_prefix, the real executable). `fix` ends the error when a folder is out of the sandbox's
// reach ("Set GEOMECH_PYTHON to ...").
SandboxedInterpreter python_for_sandbox(const std::string& interpreter, const std::string& fix);

// An interpreter that lives in an installation of its own (<prefix>/bin/program, as Octave's):
// that installation, `what` naming it in an error ("the Octave installation").
SandboxedInterpreter installation_for_sandbox(const std::string& interpreter, const std::string& what,
                                              const std::string& fix);

}  // namespace gm::harness
