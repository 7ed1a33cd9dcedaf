#include "harness/sandbox.hpp"

#include "harness/process.hpp"

#include <filesystem>
#include <mutex>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

constexpr unsigned kNobody = 65534;

std::string which(const std::string& tool) {
  for (const char* dir : {"/usr/bin", "/bin", "/usr/sbin", "/sbin"}) {
    const fs::path p = fs::path(dir) / tool;
    if (::access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

// RLIMIT_NPROC counts every process of the real user, so the limit is what runs now plus the
// sandbox's share.
long processes_of(unsigned uid) {
  long n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    struct stat st {};
    if (::stat(e.path().c_str(), &st) == 0 && st.st_uid == uid) ++n;
  }
  return n;
}

}  // namespace

unsigned sandbox_uid() { return ::geteuid() == 0 ? kNobody : ::geteuid(); }

std::vector<std::string> sandboxed(const std::vector<std::string>& argv, const SandboxSpec& spec) {
  // The sandbox's own processes (setpriv, bubblewrap, its init in the new PID namespace) start from
  // an empty environment (issue 34): inside, /proc/1/environ is bubblewrap's, and it must hold
  // nothing of the harness's (the lecturer's or CI's tokens and paths). --clearenv below does the
  // same for the submission itself.
  std::vector<std::string> cmd{which("env"), "-i", "PATH=/usr/bin:/bin"};
  if (::geteuid() == 0)
    cmd.insert(cmd.end(), {which("setpriv"), "--reuid=" + std::to_string(kNobody), "--regid=" + std::to_string(kNobody),
                           "--clear-groups", "--"});
  // Inside, /proc/1/cmdline is this command line: what it binds is a private copy under a fresh
  // temporary name (harness/private_copy.hpp), not the lecturer's folders (issue 34). bubblewrap
  // stays PID 1 (--as-pid-1 was tried: a server that is PID 1 ignores the signals the kernel sends
  // it, SIGXFSZ at the file-size limit among them, and reaps no orphan).
  cmd.insert(cmd.end(), {which("bwrap"), "--unshare-all", "--die-with-parent", "--new-session", "--clearenv"});
  for (const char* sys : {"/usr", "/etc"}) cmd.insert(cmd.end(), {"--ro-bind", sys, sys});
  for (const char* link : {"/bin", "/sbin", "/lib", "/lib64", "/lib32", "/libx32"}) {
    std::error_code ec;
    if (fs::is_symlink(link, ec))
      cmd.insert(cmd.end(), {"--symlink", fs::read_symlink(link, ec).string(), link});
    else if (fs::exists(link, ec))
      cmd.insert(cmd.end(), {"--ro-bind", link, link});
  }
  cmd.insert(cmd.end(), {"--proc", "/proc", "--dev", "/dev", "--size",
                         std::to_string(static_cast<long long>(spec.limits.scratch_mb) << 20), "--tmpfs", "/tmp"});
  for (const auto& p : spec.read_only) cmd.insert(cmd.end(), {"--ro-bind", p, p});
  for (const auto& [here, inside] : spec.mounts) cmd.insert(cmd.end(), {"--ro-bind", here, inside});
  if (!spec.writable.empty()) cmd.insert(cmd.end(), {"--bind", spec.writable, spec.writable});
  cmd.insert(cmd.end(), {"--setenv", "PATH", "/usr/bin:/bin", "--setenv", "HOME", "/tmp", "--setenv", "LANG", "C.UTF-8"});
  for (const auto& [k, v] : spec.env) cmd.insert(cmd.end(), {"--setenv", k, v});
  cmd.insert(cmd.end(), {"--chdir", spec.chdir.empty() ? "/tmp" : spec.chdir});
  const long nproc = processes_of(sandbox_uid()) + spec.limits.processes;
  const auto mb = [](int m) { return std::to_string(static_cast<long long>(m) << 20); };
  cmd.insert(cmd.end(), {"--", which("prlimit")});
  if (spec.limits.memory_mb > 0) cmd.push_back("--as=" + mb(spec.limits.memory_mb));
  cmd.insert(cmd.end(), {"--cpu=" + std::to_string(spec.limits.cpu_seconds),
                         "--nproc=" + std::to_string(nproc) + ":" + std::to_string(nproc),
                         "--fsize=" + mb(spec.limits.file_mb), "--nofile=" + std::to_string(spec.limits.open_files),
                         "--core=0", "--"});
  cmd.insert(cmd.end(), argv.begin(), argv.end());
  return cmd;
}

std::string sandbox_unavailable() {
  static std::once_flag once;
  static std::string why;
  std::call_once(once, [] {
    for (const char* tool : {"bwrap", "prlimit"})
      if (which(tool).empty()) {
        why = std::string("untrusted mode needs ") + tool + " (" +
              (std::string(tool) == "bwrap" ? "Debian package bubblewrap" : "Debian package util-linux") +
              "), which is not installed: `apt-get install bubblewrap`, or check with --trusted (in-process: only "
              "for code you trust)";
        return;
      }
    if (::geteuid() == 0 && which("setpriv").empty()) {
      why = "untrusted mode, started as root, needs setpriv (util-linux) to run submissions as nobody";
      return;
    }
    const ProcessResult r = run_process(ProcessSpec{sandboxed({"/usr/bin/true"}, SandboxSpec{}), {}, false}, 30);
    if (!r.started || r.exit_code != 0)
      why = "the sandbox (bubblewrap) does not work on this machine: " + r.output +
            " (user namespaces may be disabled: sysctl kernel.unprivileged_userns_clone=1)";
  });
  return why;
}

}  // namespace gm::harness
