#include "harness/isolation/sandboxed_interpreter.hpp"

#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"

#include <sys/stat.h>
#include <filesystem>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

// The sandbox shows /usr but for /usr/local (harness/isolation/sandbox.cpp).
bool in_system(const std::string& p) {
  return (p == "/usr" || p.rfind("/usr/", 0) == 0) && p != "/usr/local" && p.rfind("/usr/local/", 0) != 0;
}

void show(SandboxedInterpreter& r, const std::string& path, const std::string& what, const std::string& fix) {
  std::error_code ec;
  const std::string real = fs::weakly_canonical(path, ec).string();
  if (ec || real.empty() || in_system(real)) return;
  for (const auto& x : r.read_only)
    if (x == real) return;
  if (const std::string blocked = sandbox_cannot_reach(real); !blocked.empty()) {
    if (r.error.empty())
      r.error = what + " " + real + " cannot be shown to the sandbox: its user (" +
                std::string(sandbox_uid() == 65534 ? "nobody" : "this user") + ") cannot pass " + blocked +
                "; untrusted mode cannot run this interpreter. " + fix;
    return;
  }
  r.read_only.push_back(real);
}

}  // namespace

SandboxedInterpreter python_for_sandbox(const std::string& interpreter, const std::string& fix) {
  SandboxedInterpreter r;
  r.program = interpreter;
  const ProcessResult p =
      run_process(ProcessSpec{{interpreter, "-c",
                               "import os, sys; print(sys.executable); print(sys.prefix); print(sys.base_prefix); "
                               "print(os.path.realpath(sys.executable))"},
                              {},
                              false},
                  60);
  std::istringstream in(p.output);
  std::string executable, prefix, base, real;
  std::getline(in, executable);
  std::getline(in, prefix);
  std::getline(in, base);
  std::getline(in, real);
  if (!p.started || p.exit_code != 0 || executable.empty() || real.empty()) {
    r.error = "the Python interpreter " + interpreter + " could not be asked where it lives: " + p.output;
    return r;
  }
  r.program = executable;
  show(r, prefix, "the interpreter's folder (sys.prefix)", fix);
  show(r, base, "the interpreter's installation (sys.base_prefix)", fix);
  show(r, fs::path(real).parent_path().parent_path().string(), "the interpreter's installation", fix);
  return r;
}

SandboxedInterpreter installation_for_sandbox(const std::string& interpreter, const std::string& what,
                                              const std::string& fix) {
  SandboxedInterpreter r;
  r.program = interpreter;
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(interpreter, ec);
  if (!ec && real.is_absolute()) {
    r.program = real.string();
    show(r, real.parent_path().parent_path().string(), what, fix);
  }
  return r;
}

}  // namespace gm::harness
