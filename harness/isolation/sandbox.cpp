#include "harness/isolation/sandbox.hpp"

#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox_cgroup.hpp"
#include "harness/isolation/session_filter.hpp"

#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>

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

// The bubblewrap to run: $GEOMECH_BWRAP (a site's own build, or a stand-in that fails as a
// container's seccomp profile makes it fail, for the suite's tests), else the system's.
std::string bwrap_program() {
  if (const char* b = std::getenv("GEOMECH_BWRAP"); b && *b && ::access(b, X_OK) == 0) return b;
  return which("bwrap");
}

// What of /etc a sandboxed program needs: the dynamic linker's cache and configuration, the
// alternatives (c++ is /etc/alternatives/c++), the time zone, the name-service switch (getpwuid),
// Octave's site startup file (/usr/share/octave/site/m/startup/octaverc links to /etc/octaverc) and
// Python's sitecustomize (a link into /etc/python3.N). Nothing else: not the accounts, the host's
// name, its network, its services' configurations.
const std::vector<std::string>& visible_etc() {
  static const std::vector<std::string> entries = [] {
    std::vector<std::string> out;
    std::error_code ec;
    for (const char* name :
         {"ld.so.cache", "ld.so.conf", "ld.so.conf.d", "alternatives", "localtime", "nsswitch.conf", "octaverc"})
      if (fs::exists(fs::path("/etc") / name, ec)) out.push_back((fs::path("/etc") / name).string());
    for (const auto& e : fs::directory_iterator("/etc", ec))
      if (e.path().filename().string().rfind("python3", 0) == 0) out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
  }();
  return entries;
}

// A folder of this process's sandboxes: their /etc/passwd and /etc/group (root, nobody and, when
// the harness does not run as root, its own user under a neutral name: programs look their user
// up; nothing of this machine's accounts), the system-call filter they load, and bubblewrap's status
// of each (status-PID). Made once per process, removed by the process that made it.
struct AccountsFolder {
  std::string path;
  pid_t owner = ::getpid();
  AccountsFolder() {
    std::error_code ec;
    std::string pattern = (fs::temp_directory_path(ec) / "geomech-sandbox-etc-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) return;
    path = pattern;
    fs::permissions(path,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
    const unsigned uid = ::geteuid(), gid = ::getegid();
    std::string passwd = "root:x:0:0:root:/tmp:/usr/sbin/nologin\nnobody:x:65534:65534:nobody:/tmp:/usr/sbin/nologin\n";
    std::string group = "root:x:0:\nnogroup:x:65534:\n";
    if (uid != 0 && uid != 65534)
      passwd += "geomech:x:" + std::to_string(uid) + ":" + std::to_string(gid) + "::/tmp:/usr/sbin/nologin\n";
    if (gid != 0 && gid != 65534) group += "geomech:x:" + std::to_string(gid) + ":\n";
    std::ofstream(path + "/passwd") << passwd;
    std::ofstream(path + "/group") << group;
    std::ofstream(path + "/no-new-session.bpf", std::ios::binary) << no_new_session_filter();
    for (const char* f : {"passwd", "group", "no-new-session.bpf"})
      fs::permissions(path + "/" + f,
                      fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read,
                      ec);
  }
  ~AccountsFolder() {
    std::error_code ec;
    if (!path.empty() && ::getpid() == owner) fs::remove_all(path, ec);
  }
};

const std::string& sandbox_accounts_folder() {
  static const AccountsFolder folder;
  return folder.path;
}

}  // namespace

unsigned sandbox_uid() { return ::geteuid() == 0 ? kNobody : ::geteuid(); }

namespace {

// $GEOMECH_SANDBOX_TAG when it is one word of at most 64 letters, digits, '-' or '_'; else empty.
std::string sandbox_tag() {
  const char* t = std::getenv("GEOMECH_SANDBOX_TAG");
  if (!t) return {};
  const std::string tag(t);
  if (tag.empty() || tag.size() > 64) return {};
  for (char c : tag)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return {};
  return tag;
}

}  // namespace

namespace {

// The sandbox's first step, outside it, as the harness's user (root makes the cgroups): each
// "cg=DIR" makes DIR/geomech-sandbox-PID (PID: this process, which becomes bubblewrap's monitor and
// lives as long as the sandbox), "set=FILE=VALUE" writes a limit there, "join" moves this process
// in (and with it everything the sandbox will run); "status=DIR" opens DIR/status-PID on descriptor
// 9 for bubblewrap's status, "filter=FILE" opens the system-call filter on descriptor 8 (dash redirects descriptors 0-9 only); after
// "--", the rest is run. A failure here is before bubblewrap: no status is written.
constexpr const char* kPrelude =
    "n=geomech-sandbox-$$\n"
    "while [ $# -gt 0 ] && [ \"$1\" != -- ]; do\n"
    "  case \"$1\" in\n"
    "    cg=*) d=\"${1#cg=}/$n\"; mkdir \"$d\" || exit 125 ;;\n"
    "    set=*) kv=\"${1#set=}\"; printf '%s\\n' \"${kv#*=}\" > \"$d/${kv%%=*}\" || exit 125 ;;\n"
    "    join) echo $$ > \"$d/cgroup.procs\" || exit 125 ;;\n"
    "    status=*) exec 9> \"${1#status=}/status-$$\" ;;\n"
    "    filter=*) exec 8< \"${1#filter=}\" ;;\n"
    "  esac\n"
    "  shift\n"
    "done\n"
    "shift\n"
    "exec \"$@\"\n";

// The sandbox's last step, inside it: the limits of each process (RLIMIT_NPROC is counted per user
// namespace: the sandbox's tasks alone, bubblewrap's init among them), then the program. A limit
// that cannot be set is 125; the program not found or not executable, 127 or 126 (dash's own).
std::string limits_script(const SandboxLimits& l) {
  std::ostringstream s;
  auto limit = [&](const char* flag, long long value) {
    s << "ulimit " << flag << ' ' << value << " || exit " << kSandboxLimitFailed << '\n';
  };
  limit("-p", l.processes + 1);
  limit("-t", l.cpu_seconds);
  limit("-f", (static_cast<long long>(l.file_mb) << 20) / 512);  // dash counts 512-byte blocks
  limit("-n", l.open_files);
  limit("-c", 0);
  // Without a cgroup, each process's writable memory (RLIMIT_DATA: its heap and private writable
  // mappings), not its address space: V8 reserves gigabytes of inaccessible address space for
  // WebAssembly memories (and Node died under a 4 GiB RLIMIT_AS), which RLIMIT_DATA does not count.
  if (l.memory_mb > 0 && !cgroup_keeps("memory")) limit("-d", static_cast<long long>(l.memory_mb) << 10);  // KiB
  s << "exec \"$@\"\n";
  return s.str();
}

}  // namespace

std::vector<std::string> sandboxed(const std::vector<std::string>& argv, const SandboxSpec& spec) {
  const std::string dash = which("dash");
  const std::string& folder = sandbox_accounts_folder();
  std::vector<std::string> cmd{dash, "-c", kPrelude, "geomech-sandbox"};
  // First the status file: a step that fails after it leaves a report saying "not started".
  if (spec.report_start && !folder.empty()) cmd.push_back("status=" + folder);
  // The whole sandbox's limits, where the kernel's control groups can keep them (as root): its
  // tasks (its program's, bubblewrap's init and monitor), its memory, one share of the CPU at the
  // weight of this process's nice value.
  CgroupLimits group;
  group.tasks = spec.limits.processes + 2;
  group.memory_mb = spec.limits.memory_mb;
  group.cpu_weight = cpu_weight_of_this_process();
  for (auto& a : cgroup_arguments(group)) cmd.push_back(std::move(a));
  const bool filtered = !folder.empty();
  if (filtered) cmd.push_back("filter=" + folder + "/no-new-session.bpf");
  cmd.push_back("--");
  // The sandbox's own processes (setpriv, bubblewrap, its init in the new PID namespace) start from
  // an empty environment: inside, /proc/1/environ is bubblewrap's, and it must hold
  // nothing of the harness's (the lecturer's or CI's tokens and paths). --clearenv below does the
  // same for the submission itself.
  cmd.insert(cmd.end(), {which("env"), "-i", "PATH=/usr/bin:/bin"});
  // The suite's own tests mark the processes of their check (GEOMECH_SANDBOX_TAG, an opaque word),
  // so that they judge only those, not a neighbour's sandbox run as the same user.
  const std::string tag = sandbox_tag();
  if (!tag.empty()) cmd.push_back("GEOMECH_SANDBOX_TAG=" + tag);
  if (::geteuid() == 0)
    cmd.insert(cmd.end(), {which("setpriv"), "--reuid=" + std::to_string(kNobody), "--regid=" + std::to_string(kNobody),
                           "--clear-groups", "--"});
  // Inside, /proc/1/cmdline is this command line: what it binds is a private copy under a fresh
  // temporary name (harness/isolation/private_copy.hpp), not the lecturer's folders. bubblewrap
  // stays PID 1 (--as-pid-1 was tried: a server that is PID 1 ignores the signals the kernel sends
  // it, SIGXFSZ at the file-size limit among them, and reaps no orphan). No user namespace inside
  // (--disable-userns): the task count is the sandbox's user namespace's.
  cmd.insert(cmd.end(), {bwrap_program(), "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent",
                         "--new-session", "--clearenv", "--hostname", "geomech-sandbox"});
  if (spec.report_start && !folder.empty()) cmd.insert(cmd.end(), {"--json-status-fd", "9"});
  if (filtered) cmd.insert(cmd.end(), {"--seccomp", "8"});
  // The visible system, minimised: /usr without /usr/local (what was installed on this
  // machine by hand: tools, tokens in scripts), and of /etc only what the dynamic linker, the
  // compiler's alternatives, Python and Octave read, with an account file naming root and nobody.
  cmd.insert(cmd.end(), {"--ro-bind", "/usr", "/usr", "--tmpfs", "/usr/local"});
  for (const auto& e : visible_etc()) cmd.insert(cmd.end(), {"--ro-bind", e, e});
  if (!folder.empty())
    for (const char* f : {"passwd", "group"})
      cmd.insert(cmd.end(), {"--ro-bind", folder + "/" + f, std::string("/etc/") + f});
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
  cmd.insert(cmd.end(),
             {"--setenv", "PATH", "/usr/bin:/bin", "--setenv", "HOME", "/tmp", "--setenv", "LANG", "C.UTF-8"});
  for (const auto& [k, v] : spec.env) cmd.insert(cmd.end(), {"--setenv", k, v});
  if (!tag.empty()) cmd.insert(cmd.end(), {"--setenv", "GEOMECH_SANDBOX_TAG", tag});
  cmd.insert(cmd.end(), {"--chdir", spec.chdir.empty() ? "/tmp" : spec.chdir});
  cmd.insert(cmd.end(), {"--", dash, "-c", limits_script(spec.limits), "geomech-limits"});
  cmd.insert(cmd.end(), argv.begin(), argv.end());
  return cmd;
}

SandboxStart sandbox_start(pid_t first_process) {
  SandboxStart out;
  const std::string& folder = sandbox_accounts_folder();
  if (folder.empty() || first_process <= 0) return out;
  const std::string file = folder + "/status-" + std::to_string(first_process);
  std::ifstream f(file);
  out.reported = f.is_open();
  // One JSON object a line: {"child-pid": N, ...} once it has made the sandbox's first process, then
  // {"exit-code": N} only if that process went on to execute the program (bubblewrap 0.5 and later).
  for (std::string line; std::getline(f, line);) {
    const auto at = line.find("\"exit-code\":");
    if (at == std::string::npos) continue;
    out.started = true;
    out.exit_code = std::atoi(line.c_str() + at + 12);
  }
  std::error_code ec;
  fs::remove(file, ec);
  return out;
}

std::string sandbox_limits_in_words(const SandboxLimits& l) {
  std::ostringstream s;
  s << l.processes << " tasks (processes and threads) in all, counted by the kernel in the sandbox's own user namespace"
    << (cgroup_keeps("pids") ? " and by its cgroup" : "") << "; memory: ";
  if (l.memory_mb <= 0)
    s << "no limit";
  else if (cgroup_keeps("memory"))
    s << l.memory_mb << " MiB in all (its cgroup)";
  else
    s << l.memory_mb << " MiB of writable memory per process (no cgroup here: " << cgroup_limits_in_words() << ")";
  s << "; CPU: one share (setsid() refused" << (cgroup_keeps("cpu") ? "; its own cgroup" : "") << "), " << l.cpu_seconds
    << " s per process; files written up to " << l.file_mb << " MiB; " << l.open_files << " open files; /tmp "
    << l.scratch_mb << " MiB";
  return s.str();
}

std::string sandbox_cannot_reach(const std::string& p) {
  const unsigned uid = sandbox_uid();
  std::filesystem::path at;
  for (const auto& part : std::filesystem::path(p)) {
    at /= part;
    struct stat st {};
    if (::stat(at.c_str(), &st) != 0) return at.string() + " (does not exist)";
    if (!S_ISDIR(st.st_mode)) continue;
    const bool pass = st.st_uid == uid ? (st.st_mode & S_IXUSR) : (st.st_mode & S_IXOTH);
    if (!pass) return at.string();
  }
  return {};
}

std::string sandbox_unavailable() {
  static std::once_flag once;
  static std::string why;
  std::call_once(once, [] {
    if (bwrap_program().empty()) {
      why =
          "untrusted mode needs bwrap (Debian package bubblewrap), which is not installed: `apt-get install "
          "bubblewrap`, or check with --trusted (in-process: only for code you trust)";
      return;
    }
    if (which("dash").empty()) {
      why = "untrusted mode needs dash (Debian package dash, the system's /bin/sh) to start its sandbox";
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
