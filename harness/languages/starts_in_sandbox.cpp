#include "harness/languages/starts_in_sandbox.hpp"

#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/sandboxed_interpreter.hpp"

#include <cctype>
#include <filesystem>

namespace gm::harness {

std::string interpreter_start_problem(const Language& language) {
  namespace fs = std::filesystem;
  if (!language.interpreter) return "";
  const std::string program = language.interpreter();
  std::error_code ec;
  if (!fs::path(program).is_absolute() || !fs::exists(program, ec))
    return "";  // not installed: each check says so in its own words (a missing interpreter is not a sandbox's fault)
  if (!language.for_sandbox) return "";
  const SandboxedInterpreter si = language.for_sandbox(program);
  if (!si.error.empty()) return si.error;
  if (language.start_probe.empty()) return "";  // its start is tried by its first check (Octave)
  SandboxSpec spec;
  spec.read_only = si.read_only;
  std::vector<std::string> argv{si.program};
  argv.insert(argv.end(), language.start_probe.begin(), language.start_probe.end());
  const ProcessResult r = run_process(ProcessSpec{sandboxed(argv, spec), {}, false}, 60);
  if (r.started && r.exit_code == 0) return "";
  const std::string who = sandbox_uid() == 65534 ? "nobody" : "this user";
  std::string said = r.output.substr(0, 600);
  while (!said.empty() && std::isspace(static_cast<unsigned char>(said.back()))) said.pop_back();
  return "the " + language.name + " interpreter " + si.program + " does not start in the sandbox (as " + who +
         "): " + said + ". Fix: " + language.interpreter_variable + "=" + language.system_interpreter +
         " (the system's), or an interpreter whose folders every user may read";
}

}  // namespace gm::harness
