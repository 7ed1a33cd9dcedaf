#include "harness/class/grader_machine.hpp"

#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/sandboxed_interpreter.hpp"
#include "harness/languages/language.hpp"
#include "harness/remote/remote_subject.hpp"

#include <unistd.h>
#include <filesystem>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

std::string who() { return sandbox_uid() == 65534 ? "nobody" : "this user"; }

// The cache: the sandboxed compiler writes there, so every folder on the way must let the sandbox's
// user pass.
void try_cache(const std::string& cache_dir, std::vector<std::string>& problems) {
  std::error_code ec;
  const fs::path dir = fs::absolute(cache_dir, ec);
  fs::create_directories(dir, ec);
  if (ec) {
    problems.push_back("the compilers' cache " + dir.string() + " cannot be made: " + ec.message() +
                       ". Fix: --cache-dir DIR, a folder this user can write");
    return;
  }
  const std::string blocked = sandbox_cannot_reach(dir.string());
  if (blocked.empty()) return;
  problems.push_back("the compilers' cache " + dir.string() + " is out of the sandbox's reach: its user (" + who() +
                     ") cannot pass " + blocked +
                     " (a folder only its owner may enter, as mktemp -d makes). Fix: `chmod o+x " + blocked +
                     "`, or --cache-dir DIR in a folder every user may pass");
}

void try_interpreter(const Language& language, std::vector<std::string>& problems) {
  const std::string program = language.interpreter();
  std::error_code ec;
  if (!fs::path(program).is_absolute() || !fs::exists(program, ec))
    return;  // not installed: each check says so in its own words (a missing interpreter is not a sandbox's fault)
  if (!language.for_sandbox) return;
  const SandboxedInterpreter si = language.for_sandbox(program);
  if (!si.error.empty()) {
    problems.push_back(si.error);
    return;
  }
  if (language.start_probe.empty()) return;  // its start is tried by its first check (Octave)
  // Started inside the sandbox, as a check starts it.
  SandboxSpec spec;
  spec.read_only = si.read_only;
  std::vector<std::string> argv{si.program};
  argv.insert(argv.end(), language.start_probe.begin(), language.start_probe.end());
  const ProcessResult r = run_process(ProcessSpec{sandboxed(argv, spec), {}, false}, 60);
  if (!r.started || r.exit_code != 0)
    problems.push_back("the " + language.name + " interpreter " + si.program + " does not start in the sandbox (as " +
                       who() + "): " + r.output.substr(0, 600) + ". Fix: " + language.interpreter_variable + "=" +
                       language.system_interpreter +
                       " (the system's), or an interpreter whose folders every user may read");
}

}  // namespace

std::vector<std::string> grader_machine_problems(const GraderNeeds& needs) {
  std::vector<std::string> problems;
  if (!needs.untrusted) return problems;
  if (const std::string why = sandbox_unavailable(); !why.empty()) {
    problems.push_back(why);
    return problems;  // nothing else can be tried inside it
  }
  if (!needs.cache_dir.empty()) try_cache(needs.cache_dir, problems);
  for (const auto& l : languages())
    if (l.route == Route::Served && needs.served.count(l.id)) try_interpreter(l, problems);
  return problems;
}

std::string grader_machine_message(const std::vector<std::string>& problems) {
  std::string m = "the grader's machine cannot check submissions (nothing was checked, nobody was graded):";
  for (const auto& p : problems) m += "\n  - " + p;
  return m;
}

}  // namespace gm::harness
