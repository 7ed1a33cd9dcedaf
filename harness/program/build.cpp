#include "harness/program/build.hpp"

#include "core/subject.hpp"
#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/submission_intake.hpp"
#include "harness/reports/report.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// When a sandboxed compile or link did not reach the compiler, the grader's set-up, with the fix.
// bubblewrap says whether it executed the compiler's wrapper (its status, sandbox_start), and that
// wrapper fails with a status no compiler exits with (a limit it could not set, the compiler not
// found there). Never the output: once the compiler ran, every byte of it is the compiler's, and a
// file can make its first diagnostic read "bwrap: ..." (#line 1 "bwrap: ...", as the file name).
// A compile stopped at its timeout, or cancelled, is not told apart (its report is read and removed).
std::string sandbox_start_fault(const ProcessResult& pr, const fs::path& dir) {
  if (!pr.started) return {};  // not even spawned: the caller says so
  const SandboxStart st = sandbox_start(pr.pid);
  if (pr.timed_out || pr.cancelled) return {};
  const std::string first = pr.output.substr(0, pr.output.find('\n'));
  std::string fault;
  if (!st.started)
    fault = "the grader's machine, not the file: the sandbox could not start the compiler" +
            (first.empty() ? std::string() : " (" + first + ")");
  else if (is_sandbox_wrapper_status(st.exit_code))
    fault = "the grader's machine, not the file: the sandbox started but could not run the compiler (status " +
            std::to_string(st.exit_code) +
            (st.exit_code == kSandboxLimitFailed ? ": a limit it could not set" : ": the compiler is not found there") +
            (first.empty() ? std::string() : "; " + first) + ")";
  else
    return {};
  if (const std::string blocked = sandbox_cannot_reach(dir.string()); !blocked.empty())
    fault += ". Its user (" + std::string(sandbox_uid() == 65534 ? "nobody" : "this user") + ") cannot pass " +
             blocked + ". Fix: `chmod o+x " + blocked + "`, or --cache-dir DIR in a folder every user may pass";
  else
    fault += ". Fix: `geomech self-test` says what the sandbox lacks";
  return fault;
}

// The library a link failed for with "DSO missing from command line" ("/usr/lib/.../libdl.so.2:
// error adding symbols: DSO missing from command line" -> "libdl.so.2"), or "" when it did not.
std::string dso_missing(const std::string& output) {
  const std::string marker = ": error adding symbols: DSO missing from command line";
  const auto at = output.find(marker);
  if (at == std::string::npos) return {};
  const auto begin = output.find_last_of(" /\n", at);
  const std::string lib =
      output.substr(begin == std::string::npos ? 0 : begin + 1, at - (begin == std::string::npos ? 0 : begin + 1));
  return lib.rfind("lib", 0) == 0 && lib.find(".so") != std::string::npos ? lib : std::string();
}

// What a sandboxed compile may read and write: the suite's headers (of a source tree, only its
// core/ and student/ folders: the compiler can be told to read any file through #include), the
// prebuilt files, and the build folder (handed to the sandbox's user).
SandboxSpec compiler_sandbox(const Toolchain& tc, const fs::path& dir) {
  SandboxSpec spec;
  std::error_code ec;
  auto add = [&](const fs::path& p) {
    if (p.empty() || !fs::exists(p, ec)) return;
    const std::string s = fs::weakly_canonical(p, ec).string();
    // The system is visible already, but for /usr/local (an installed suite's headers and libraries).
    if (s.rfind("/usr/", 0) == 0 && s.rfind("/usr/local/", 0) != 0) return;
    spec.read_only.push_back(s);
  };
  for (const auto& inc : tc.includes) {
    if (fs::exists(fs::path(inc) / "core" / "subject.hpp", ec) && fs::exists(fs::path(inc) / "golden", ec)) {
      add(fs::path(inc) / "core");  // the suite's source tree: its headers alone
      add(fs::path(inc) / "student");
    } else {
      add(inc);
    }
  }
  for (const auto& f : {tc.driver_object, tc.server_object, tc.harness_library, tc.property_library}) add(f);
  for (const auto& f : tc.other_libraries) add(f);
  if (!tc.precompiled_header.empty()) add(fs::path(tc.precompiled_header).parent_path());
  spec.writable = dir.string();
  spec.chdir = dir.string();
  spec.report_start = true;            // whether the compiler ran is bubblewrap's word (sandbox_start_fault)
  spec.limits.memory_mb = 8192;        // a 50-digit instantiation compiles in about 1.5 GB
  spec.limits.file_mb = 2048;          // a sanitized suite's objects and programs reach hundreds of MB
  spec.limits.scratch_mb = 2048;       // the compiler's temporary files (a tmpfs: memory used as needed)
  if (sandbox_uid() != ::geteuid()) {  // root hands the folder to nobody
    ::chown(dir.c_str(), sandbox_uid(), sandbox_uid());
    for (const auto& e : fs::recursive_directory_iterator(dir, ec))
      ::lchown(e.path().c_str(), sandbox_uid(), sandbox_uid());
  }
  return spec;
}

const char* kScalars[] = {"double", "mp50", "exact"};

// The compiles of one file, each registering a piece of it (the macros read by
// geomech/detail/scalar_selection.hpp). mp50 and exact are compiled whole; double is compiled whole
// too, except for a first look (`geomech check`), which compiles its slots alone in two pieces at
// once (the Manakov slots of SO(n) and the others, gm::student::detail::slot_piece_of): the full
// build then adds its integrators, a third piece, rather than compile the whole again. In pieces the
// double instantiation costs more CPU (each piece instantiates what it shares with the others: 7.0
// s against 4.4 for examples/students/correct.hpp), so only a first look, which waits for it, takes them.
struct Unit {
  const char* name;             // its files: NAME.o, .d, .cmd, .json, .log
  int scalar;                   // in kScalars
  int slot_piece, slot_pieces;  // see gm::student::detail::WholeFile
  bool integrators;
};
constexpr Unit kUnits[] = {{"double", 0, 0, 1, true},
                           {"double-slots-1", 0, 0, 2, false},
                           {"double-slots-2", 0, 1, 2, false},
                           {"double-integrators", 0, 0, 0, true},
                           {"mp50", 1, 0, 1, true},
                           {"exact", 2, 0, 1, true}};
constexpr int kDoubleWhole = 0, kDoubleOtherSlots = 1, kDoubleManakovSlots = 2, kDoubleIntegrators = 3;
constexpr int kUnitCount = static_cast<int>(std::size(kUnits));

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream os;
  os << f.rdbuf();
  return os.str();
}

std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex(std::uint64_t x) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
  return std::string(buf, 10);
}

fs::file_time_type mtime(const fs::path& p) {
  std::error_code ec;
  auto t = fs::last_write_time(p, ec);
  return ec ? fs::file_time_type::max() : t;
}

// The files a make-style dependency file names (the object's prerequisites).
std::vector<std::string> depfile_inputs(const fs::path& dep) {
  std::string text = read_text(dep);
  std::vector<std::string> out;
  const auto colon = text.find(": ");
  if (colon == std::string::npos) return out;
  std::string cur;
  for (std::size_t i = colon + 2; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
      ++i;
      continue;
    }
    if (c == '\\' && i + 1 < text.size() && text[i + 1] == ' ') {
      cur += ' ';
      ++i;
      continue;
    }
    if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      if (c == '\n' && i + 1 < text.size() && text[i + 1] != ' ') break;
      continue;
    }
    cur += c;
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// `extra`: inputs the dependency file cannot name. The headers read from a precompiled header are
// not listed in it, so its .gch stands for them (the suite's build remakes it when one changes).
bool object_current(const fs::path& obj, const fs::path& dep, const fs::path& cmd_file, const std::string& cmd,
                    const std::vector<std::string>& extra) {
  if (!fs::exists(obj) || !fs::exists(dep) || !fs::exists(cmd_file)) return false;
  if (read_text(cmd_file) != cmd) return false;
  const auto t = mtime(obj);
  for (const auto& in : depfile_inputs(dep))
    if (mtime(in) > t) return false;
  for (const auto& in : extra)
    if (!fs::exists(in) || mtime(in) > t) return false;
  return true;
}

std::string join(const std::set<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::string trim_lines(const std::string& text, std::size_t max_lines) {
  std::istringstream in(text);
  std::string out, line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    if (n++ == max_lines) {
      out += "... (" + std::to_string(std::count(text.begin(), text.end(), '\n') - max_lines) + " more lines)\n";
      break;
    }
    out += line + "\n";
  }
  return out;
}

// Compiler messages spell the suite's scalars out in full (hundreds of characters of Boost); a
// student reads Rational and Real50 better.
std::string shorten_types(std::string line) {
  const std::string open = "boost::multiprecision::number<";
  for (std::size_t at = line.find(open); at != std::string::npos; at = line.find(open, at)) {
    int depth = 0;
    std::size_t end = at + open.size() - 1;
    for (; end < line.size(); ++end) {
      if (line[end] == '<') ++depth;
      if (line[end] == '>' && --depth == 0) break;
    }
    if (end >= line.size()) break;
    const std::string inside = line.substr(at, end + 1 - at);
    const std::string name = inside.find("rational_adaptor") != std::string::npos   ? "Rational"
                             : inside.find("cpp_bin_float<50") != std::string::npos ? "Real50"
                                                                                    : "number<...>";
    line.replace(at, end + 1 - at, name);
    at += name.size();
  }
  return line;
}

std::string clip(std::string line) {
  line = shorten_types(std::move(line));
  if (line.size() > 400) line = line.substr(0, 400) + " ...";
  return line;
}

// The errors of a failed compile, each with the place in the student's file it comes from and
// the slot it concerns: a few lines a student can act on (the full output is kept in a file).
std::string error_summary(const std::string& out, const std::string& source, std::size_t max_errors = 8) {
  static const std::regex marker(R"(detail::slot_([A-Za-z0-9_]+))");
  const std::string file = fs::path(source).filename().string();
  std::istringstream in(out);
  std::string place, slot, summary;
  std::size_t n = 0, total = 0;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, marker)) slot = m[1];
    // The first place in the student's own file since the last error: the innermost of their lines.
    const bool include_chain = line.find("In file included from") != std::string::npos ||
                               (line.find_first_not_of(' ') != std::string::npos &&
                                line.compare(line.find_first_not_of(' '), 5, "from ") == 0);
    if (place.empty() && !include_chain && line.find(file + ":") != std::string::npos &&
        line.find(": error:") == std::string::npos && line.find(": note:") == std::string::npos) {
      const auto at = line.find(file + ":");
      place = line.substr(at, line.find(' ', at) == std::string::npos ? std::string::npos : line.find(' ', at) - at);
      while (!place.empty() && (place.back() == ':' || place.back() == ',')) place.pop_back();
    }
    const auto e = line.find("error:");
    if (e == std::string::npos) continue;
    ++total;
    if (n < max_errors) {
      std::string where = line.find(file + ":") != std::string::npos
                              ? line.substr(line.find(file + ":"), line.find(": error:") - line.find(file + ":"))
                              : place;
      summary += "  " + (where.empty() ? std::string() : where + ": ") + (slot.empty() ? "" : "(in " + slot + ") ") +
                 clip(line.substr(e)) + "\n";
      ++n;
    }
    place.clear();
    slot.clear();
  }
  if (total > n) summary += "  ... and " + std::to_string(total - n) + " more errors\n";
  return summary;
}

}  // namespace

std::string default_toolchain_path() {
  if (const char* p = std::getenv("GEOMECH_TOOLCHAIN"); p && *p) return p;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path candidate = exe.parent_path().parent_path() / "student" / "toolchain.json";
    if (fs::exists(candidate)) return candidate.string();
    const fs::path installed = exe.parent_path().parent_path() / "share" / "geomech-spec" / "toolchain.json";
    if (fs::exists(installed)) return installed.string();
  }
  return "student/toolchain.json";
}

Toolchain load_toolchain(const std::string& path) {
  std::ifstream f(path);
  if (!f)
    throw std::runtime_error("cannot read the student toolchain " + path +
                             " (it is written when the suite is configured; run `./geomech build` first)");
  Toolchain t;
  t.path = path;
  try {
    const json j = json::parse(f);
    if (j.at("format") != "geomech-student-toolchain 1") throw std::runtime_error("unknown format");
    t.cxx = j.at("cxx").get<std::string>();
    t.flags = j.at("flags").get<std::vector<std::string>>();
    t.link_flags = j.at("link_flags").get<std::vector<std::string>>();
    t.includes = j.at("includes").get<std::vector<std::string>>();
    t.opt = j.at("opt").get<std::map<std::string, std::string>>();
    t.driver_object = j.at("driver_object").get<std::string>();
    t.server_object = j.value("server_object", "");
    t.harness_library = j.at("harness_library").get<std::string>();
    t.property_library = j.at("property_library").get<std::string>();
    t.other_libraries = j.at("other_libraries").get<std::vector<std::string>>();
    t.cache_dir = j.at("cache_dir").get<std::string>();
    t.precompiled_header = j.value("precompiled_header", "");
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a valid student toolchain description (" + e.what() + ")");
  }
  // An installed toolchain (share/geomech-spec/toolchain.json) names its files relative to itself,
  // so that the installed tree can be moved (cmake --install --prefix, a Debian package).
  const fs::path here = fs::absolute(path).parent_path();
  auto resolve = [&](std::string& p) {
    if (!p.empty() && fs::path(p).is_relative()) p = (here / p).lexically_normal().string();
  };
  resolve(t.driver_object);
  resolve(t.server_object);
  resolve(t.harness_library);
  resolve(t.property_library);
  for (auto& i : t.includes) resolve(i);
  resolve(t.precompiled_header);
  if (!t.precompiled_header.empty() && !fs::exists(t.precompiled_header + ".gch")) t.precompiled_header.clear();
  for (const auto& i : t.includes) {
    const fs::path selection = fs::path(i) / "geomech" / "detail" / "scalar_selection.hpp";
    if (fs::exists(selection)) {
      t.scalar_selection = selection.string();
      break;
    }
  }
  if (t.scalar_selection.empty())
    throw std::runtime_error(path +
                             ": none of its includes holds geomech/detail/scalar_selection.hpp (an install "
                             "older than the tool?): reinstall or rebuild the suite");
  if (t.cache_dir.empty()) {  // per user: $XDG_CACHE_HOME/geomech-spec, ~/.cache/geomech-spec
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    t.cache_dir = xdg && *xdg     ? std::string(xdg) + "/geomech-spec"
                  : home && *home ? std::string(home) + "/.cache/geomech-spec"
                                  : (fs::temp_directory_path() / "geomech-spec-cache").string();
  }
  for (const auto& p : {t.driver_object, t.harness_library, t.property_library})
    if (!fs::exists(p))
      throw std::runtime_error("the prebuilt file " + p + " is missing: build the suite first (`./geomech build`)");
  return t;
}

std::string first_error(const std::string& out) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);)
    if (line.find("error:") != std::string::npos) return clip(line);
  return {};
}

std::map<std::string, std::string> slots_failing_in(const std::string& out) {
  static const std::regex marker(R"(detail::slot_([A-Za-z0-9_]+))");
  std::map<std::string, std::string> failing;
  std::set<std::string> pending;  // slots named since the last error line
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    for (auto it = std::sregex_iterator(line.begin(), line.end(), marker); it != std::sregex_iterator(); ++it) {
      const std::string slot = (*it)[1];
      if (is_slot_name(slot)) pending.insert(slot);
    }
    if (line.find("error:") != std::string::npos) {
      const std::string msg = clip(line);
      for (const auto& s : pending)
        if (!failing.count(s)) failing[s] = msg;
      pending.clear();
    }
  }
  return failing;
}

bool integrators_failing_in(const std::string& out) { return out.find("gm_integrator_of") != std::string::npos; }

std::string hint_for(const std::string& error, const std::string& scalar) {
  static const std::regex math(R"((std::)?(sqrt|sin|cos|tan|exp|log|pow|abs|fabs|atan2|hypot)\b)");
  if (scalar == "exact" && std::regex_search(error, std::regex(R"(\b(sqrt|sin|cos|exp|log|pow|atan2|hypot)\b)")))
    return "square roots and transcendental functions have no exact rational value; these slots are checked in "
           "double and mp50 only";
  if (error.find("no matching function") != std::string::npos && std::regex_search(error, math))
    return "call the function unqualified (`using std::sqrt; sqrt(x)`) so that the overload for the " + scalar +
           " scalar is found";
  if (error.find("cannot convert") != std::string::npos || error.find("conversion from") != std::string::npos)
    return "a double (variable or literal) is used where the scalar T is expected: write T(0.5) or T(1) / T(2), "
           "and declare locals as T, not double";
  if (error.find("ambiguous") != std::string::npos)
    return "mixing T with double literals is ambiguous for multiprecision scalars: write T(2) instead of 2.0";
  return {};
}

namespace {

// The file and the headers beside it, copied into dir/src for the sandboxed compiler: in a class,
// the submission's snapshot holds only the student's own files and the headers the lecturer shares
// (harness/class/class_mode.hpp); for one file, the headers of its folder. Read as a stranger's: a
// link, FIFO or device among them is refused by name, never followed or opened; not the other
// sources of the folder. Returns what went wrong, "" when copied.
std::string copy_for_the_sandbox(const fs::path& source, const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir / "src", ec);
  std::vector<std::pair<std::string, std::string>> copies;
  try {
    const StrangerFolder beside(source.parent_path().string());
    copies.emplace_back(source.filename().string(), beside.read(source.filename().string(), IntakeLimits{}.file_bytes));
    std::uint64_t bytes = copies.back().second.size();
    for (const auto& e : beside.list()) {
      const std::string ext = fs::path(e.name).extension().string();
      if (ext != ".hpp" && ext != ".h") continue;
      if (e.kind != EntryKind::File) throw RefusedEntry(e.name, describe(e.kind));
      copies.emplace_back(e.name, beside.read(e.name, IntakeLimits{}.file_bytes));
      if ((bytes += copies.back().second.size()) > IntakeLimits{}.total_bytes)
        throw RefusedEntry(e.name, "beyond the size of a submission: " +
                                       std::to_string(IntakeLimits{}.total_bytes >> 20) + " MiB in all");
    }
  } catch (const RefusedEntry& e) {
    return "the file is not compiled: " + std::string(e.what()) + " (beside " + source.filename().string() + ")";
  }
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(dir / "src", ec))
    if (std::none_of(copies.begin(), copies.end(),
                     [&](const auto& c) { return c.first == e.path().filename().string(); }))
      stale.push_back(e.path());
  for (const auto& p : stale) fs::remove(p, ec);  // a header no longer beside it is no longer there
  for (const auto& [name, text] : copies) {
    const fs::path to = dir / "src" / name;
    std::error_code copy_ec;
    if (read_text(to) != text) {
      fs::remove(to, copy_ec);
      std::ofstream out(to, std::ios::binary | std::ios::trunc);
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      if (!out) return "cannot copy " + name + " into " + (dir / "src").string();
    }
  }
  return "";
}

// One unit's compile (kUnits[u]) of the student's file, and what it learnt.
struct UnitState {
  bool wanted = true;  // compiled in this run (not: --scalar double, or the first look's integrators)
  std::set<std::string> skip;
  std::map<std::string, std::string> skip_reason;
  bool skip_integrators = false;
  bool done = false;
  bool ok = false;
  std::string unavailable;
  std::string output;  // compiler output of the final attempt
};

// What every compile of one file shares: the toolchain, its libraries, the file as compiled and
// the build folder.
struct CompileSetting {
  const Toolchain& tc;
  const LibraryFlags& libs;
  fs::path compiled_source;
  fs::path dir;

  fs::path file(int u, const char* extension) const { return dir / (std::string(kUnits[u].name) + extension); }

  std::vector<std::string> command(int u, const std::set<std::string>& skip, bool skip_integrators) const {
    const Unit& unit = kUnits[u];
    const std::string scalar = kScalars[unit.scalar];
    std::vector<std::string> cmd{tc.cxx};
    cmd.insert(cmd.end(), tc.flags.begin(), tc.flags.end());
    cmd.push_back(tc.opt.count(scalar) ? tc.opt.at(scalar) : "-O1");
    cmd.push_back("-fdiagnostics-color=never");
    cmd.push_back("-DGEOMECH_STUDENT_ONLY=" + std::to_string(unit.scalar));
    cmd.push_back("-DGEOMECH_STUDENT_CHECK=1");
    if (unit.slot_pieces != 1) {
      cmd.push_back("-DGEOMECH_SLOTS_PIECE=" + std::to_string(unit.slot_piece));
      cmd.push_back("-DGEOMECH_SLOTS_PIECES=" + std::to_string(unit.slot_pieces));
    }
    if (!skip.empty()) cmd.push_back("-DGEOMECH_SKIP_SLOTS=\"" + join(skip) + "\"");
    if (skip_integrators || !unit.integrators) cmd.push_back("-DGEOMECH_SKIP_INTEGRATORS=1");
    // The precompiled student.hpp first (GCC reads a .gch only for the first include), then what
    // this compile registers; the header tests none of the macros above, so every compile uses it.
    if (!tc.precompiled_header.empty()) {
      cmd.push_back("-include");
      cmd.push_back(tc.precompiled_header);
    }
    cmd.push_back("-include");
    cmd.push_back(tc.scalar_selection);
    cmd.push_back("-I" + compiled_source.parent_path().string());
    for (const auto& inc : tc.includes) cmd.push_back("-I" + inc);
    cmd.insert(cmd.end(), libs.compile.begin(), libs.compile.end());
    cmd.push_back("-MMD");
    cmd.push_back("-MF");
    cmd.push_back(file(u, ".d").string());
    cmd.push_back("-c");
    cmd.push_back(compiled_source.string());
    cmd.push_back("-o");
    cmd.push_back(file(u, ".o").string());
    return cmd;
  }
};

// The units whose object is up to date with its notes (nothing to compile for them).
void read_cached_objects(const CompileSetting& cs, const std::vector<std::string>& pch_inputs, UnitState st[]) {
  for (int k = 0; k < kUnitCount; ++k) {
    const fs::path notes = cs.file(k, ".json");
    if (!fs::exists(notes)) continue;
    try {
      const json n = json::parse(read_text(notes));
      std::set<std::string> skip = n.at("skip").get<std::set<std::string>>();
      const bool skip_int = n.at("skip_integrators").get<bool>();
      const std::string cmd = shell_join(cs.command(k, skip, skip_int));
      if (n.at("ok").get<bool>() &&
          object_current(cs.file(k, ".o"), cs.file(k, ".d"), cs.file(k, ".cmd"), cmd, pch_inputs)) {
        st[k].skip = skip;
        st[k].skip_reason = n.at("skip_reason").get<std::map<std::string, std::string>>();
        st[k].skip_integrators = skip_int;
        st[k].done = st[k].ok = true;
        st[k].output = n.value("warnings", "");
      }
    } catch (const std::exception&) {
      // unreadable notes: compile again
    }
  }
}

// What a failed mp50 or exact compile teaches: leave out the slots its messages name (or the
// integrators) in the next round, or, when it names none left, give the scalar up.
void learn_from_a_failed_compile(UnitState& st, const std::string& scalar, const std::string& output) {
  const auto failing = slots_failing_in(output);
  bool progress = false;
  for (const auto& [slot, msg] : failing)
    if (!st.skip.count(slot)) {
      st.skip.insert(slot);
      const std::string hint = hint_for(msg, scalar);
      st.skip_reason[slot] =
          "does not compile for " + scalar + ": " + msg + (hint.empty() ? "" : " (hint: " + hint + ")");
      progress = true;
    }
  if (!progress && !st.skip_integrators && integrators_failing_in(output)) {
    st.skip_integrators = true;
    progress = true;
  }
  if (!progress) {
    st.done = true;
    const std::string err = first_error(output);
    const std::string hint = hint_for(err, scalar);
    st.unavailable = "the implementation does not compile for " + scalar + ": " + err +
                     (hint.empty() ? "" : " (hint: " + hint + ")");
  }
}

// The build notes (scalar_unavailable, slot_notes, warnings), and each compiled unit's own notes
// written beside its object for the next run's cache.
json notes_of(const UnitState st[], const CompileSetting& cs) {
  json notes;
  notes["scalar_unavailable"] = json::object();
  notes["slot_notes"] = json::object();
  notes["warnings"] = json::array();
  std::string double_output;  // the double pieces' warnings, each piece's once
  for (int u = 0; u < kUnitCount; ++u) {
    const int k = kUnits[u].scalar;
    const std::string scalar = kScalars[k];
    if (!st[u].ok) {  // a double piece that failed ended the build; one not wanted says nothing
      if (k != 0)
        notes["scalar_unavailable"][scalar] = st[u].unavailable.empty() ? "did not compile" : st[u].unavailable;
      continue;
    }
    for (const auto& [slot, why] : st[u].skip_reason) notes["slot_notes"][scalar][slot] = why;
    if (st[u].skip_integrators)
      notes["warnings"].push_back("the integrators do not compile for " + scalar + ", so they are checked in " +
                                  (k == 1 ? "double only" : "double and mp50 only"));
    if (k == 0 && double_output.find(st[u].output) == std::string::npos) double_output += st[u].output;
    json n;
    n["ok"] = true;
    n["skip"] = st[u].skip;
    n["skip_reason"] = st[u].skip_reason;
    n["skip_integrators"] = st[u].skip_integrators;
    n["warnings"] = st[u].output;
    std::ofstream(cs.file(u, ".json"), std::ios::trunc) << n.dump(1);
  }
  if (double_output.find("warning:") != std::string::npos)
    notes["warnings"].push_back("the compiler has warnings about this file:\n" + trim_lines(double_output, 12));
  return notes;
}

// The double piece that did not compile (the file does not compile), or -1.
int failed_double_piece(const UnitState st[]) {
  for (int u = 0; u < kUnitCount; ++u)
    if (kUnits[u].scalar == 0 && st[u].wanted && st[u].done && !st[u].ok) return u;
  return -1;
}

// "for double (its Manakov slots)", "for mp50".
std::string unit_label(int u) {
  const Unit& unit = kUnits[u];
  std::string label = std::string("for ") + kScalars[unit.scalar];
  if (unit.slot_pieces == 0) label += " (its integrators)";
  if (unit.slot_pieces == 2) label += unit.slot_piece == 1 ? " (its Manakov slots)" : " (its other slots)";
  return label;
}

// The option that makes the compiler driver link with LLVM's lld, else with binutils' gold, when
// one is on the PATH: faster than the default ld on a check program (0.12 and 0.29 s against 0.52,
// bench/one_mistake_cpp.sh). Only the first look links with it: the full link keeps the default linker,
// whose messages the hints of link_failure read. "" when neither is found.
std::string fast_linker_option() {
  static const std::string option = [] {
    const char* path = std::getenv("PATH");
    for (const char* linker : {"lld", "gold"}) {
      std::istringstream dirs(path ? path : "");
      for (std::string dir; std::getline(dirs, dir, ':');) {
        std::error_code ec;
        if (!dir.empty() && fs::exists(fs::path(dir) / ("ld." + std::string(linker)), ec))
          return "-fuse-ld=" + std::string(linker);
      }
    }
    return std::string();
  }();
  return option;
}

// What a failed link says, with a hint where the output names a known cause.
std::string link_failure(const std::string& output) {
  std::string hint;
  if (output.find("multiple definition of `main'") != std::string::npos)
    hint = "\nhint: the file defines main(); guard it with #ifndef GEOMECH_STUDENT_CHECK ... #endif";
  if (const std::string lib = dso_missing(output); !lib.empty())
    hint = "\nhint: the program needs the library " + lib +
           ", which no flag names (a library that a library you "
           "use depends on, left out of its pkg-config file): add --ldflags -l" +
           lib.substr(3, lib.find(".so") - 3) + " (or `// geomech: ldflags -l" + lib.substr(3, lib.find(".so") - 3) +
           "` in the file)";
  else if (output.find("undefined reference") != std::string::npos)
    hint = "\nhint: a function is declared but never defined (or defined in another file: list every file)";
  return "the program could not be linked:\n" + trim_lines(output, 30) + hint;
}

// A program's arguments as they are run (wrapped in the sandbox when sandboxed).
using RunArgv = std::function<std::vector<std::string>(const std::vector<std::string>&)>;

// Rounds of compiles: the scalars not done, at once; a scalar whose compile names slots (or the
// integrators) that do not compile for it is compiled again without them. False when the build
// cannot go on (r.message says why: the compiler did not start, or the sandbox did not).
bool compile_rounds(const CompileSetting& cs, const BuildOptions& o, const fs::path& source, const RunArgv& run_argv,
                    UnitState st[], bool& compiled_anything, BuildResult& r) {
  for (int round = 0; round < 5; ++round) {
    if (failed_double_piece(st) >= 0) break;  // the file itself does not compile: nothing else to learn
    std::vector<int> todo;
    for (int k = 0; k < kUnitCount; ++k)
      if (!st[k].done) todo.push_back(k);
    if (todo.empty()) break;
    std::vector<ProcessSpec> specs;
    std::vector<std::string> commands;
    for (int k : todo) {
      ProcessSpec p;
      p.argv = cs.command(k, st[k].skip, st[k].skip_integrators);
      commands.push_back(shell_join(p.argv));  // the cache's key: without the sandbox's wrapping
      p.argv = run_argv(p.argv);
      p.decisive = kUnits[k].scalar == 0;  // the file does not compile: the other compiles are stopped
      specs.push_back(p);
      const std::string label = "compiling " + unit_label(k) +
                                (st[k].skip.empty() ? "" : " without " + join(st[k].skip)) +
                                (st[k].skip_integrators ? " (integrators left out)" : "");
      r.log.push_back(label + (o.verbose ? ": " + shell_join(p.argv) : ""));
    }
    compiled_anything = true;
    const auto results = run_processes(specs, o.jobs, o.compile_timeout_seconds);
    for (std::size_t i = 0; i < todo.size(); ++i) {
      const int k = todo[i];
      const std::string scalar = kScalars[kUnits[k].scalar];
      const ProcessResult& pr = results[i];
      if (pr.cancelled) {                            // stopped when double failed: nothing learnt, nothing kept
        if (o.sandbox) (void)sandbox_start(pr.pid);  // its status, read and removed
        continue;
      }
      st[k].output = pr.output;
      if (pr.timed_out)  // said as an error of the file, so that the summary below shows it
        st[k].output += "\n" + source.filename().string() + ": error: the compiler was stopped after " +
                        std::to_string(static_cast<long>(o.compile_timeout_seconds)) +
                        " s (an #include of a device such as /dev/zero, or a template recursion without end?)\n";
      std::ofstream(cs.file(k, ".log"), std::ios::trunc) << shell_join(specs[i].argv) << "\n\n" << pr.output;
      if (o.sandbox)
        if (std::string fault = sandbox_start_fault(pr, cs.dir); !fault.empty()) {
          r.machine_fault = r.message = std::move(fault);
          return false;
        }
      if (pr.started && pr.exit_code == 0) {
        st[k].done = st[k].ok = true;
        std::ofstream(cs.file(k, ".cmd"), std::ios::trunc) << commands[i];
        continue;
      }
      if (!pr.started) {
        r.message = pr.output;
        return false;
      }
      if (kUnits[k].scalar == 0) {
        st[k].done = true;
        continue;
      }
      learn_from_a_failed_compile(st[k], scalar, pr.output);
    }
  }

  return true;
}

// The link of the compiled scalars with the check program's main (or the protocol server's), the
// harness and the properties, unless the program is up to date.
struct Linked {
  bool ok = false;
  bool current = false;  // nothing to link: the program was up to date
  fs::path program;
  std::string message, machine_fault, log;
};

Linked link_program(const CompileSetting& cs, const BuildOptions& o, const UnitState st[],
                    const std::vector<std::string>& trusted_roots, bool compiled_anything, const RunArgv& run_argv) {
  std::vector<std::string> link{cs.tc.cxx};
  if (o.fast_link && !fast_linker_option().empty()) link.push_back(fast_linker_option());
  link.insert(link.end(), cs.tc.link_flags.begin(), cs.tc.link_flags.end());
  for (int k = 0; k < kUnitCount; ++k)
    if (st[k].ok) link.push_back(cs.file(k, ".o").string());
  // The check program links the properties (whole archive: their registrations); the protocol
  // server of untrusted mode links only the registry and the protocol from the same libraries.
  const std::string& main_object = o.server ? cs.tc.server_object : cs.tc.driver_object;
  link.push_back(main_object);
  link.push_back(cs.tc.harness_library);
  if (!o.server) link.push_back("-Wl,--whole-archive");
  link.push_back(cs.tc.property_library);
  if (!o.server) link.push_back("-Wl,--no-whole-archive");
  for (const auto& l : cs.tc.other_libraries) link.push_back(l);
  link.insert(link.end(), cs.libs.link.begin(), cs.libs.link.end());
  // A shared library under a folder the grader trusts is found at run time where it was linked (the
  // suite's own run path: the loader searches only the system's folders).
  for (const auto& root : trusted_roots)
    for (const auto& f : cs.libs.link)
      if (f.rfind("-L" + root, 0) == 0 && (f.size() == 2 + root.size() || f[2 + root.size()] == '/'))
        link.push_back("-Wl,-rpath," + f.substr(2));
  const std::string program_name = !o.program_name.empty() ? o.program_name : o.server ? "server" : "check";
  Linked out;
  out.program = cs.dir / program_name;
  const fs::path& program = out.program;
  const fs::path link_file = cs.dir / ("link-" + program_name + ".cmd");
  link.push_back("-o");
  link.push_back(program.string());
  const std::string link_cmd = shell_join(link);
  bool& link_current = out.current;
  link_current = fs::exists(program) && read_text(link_file) == link_cmd && !compiled_anything;
  if (link_current) {
    const auto t = mtime(program);
    for (const auto& in : {main_object, cs.tc.harness_library, cs.tc.property_library})
      if (mtime(in) > t) link_current = false;
    for (int k = 0; k < kUnitCount; ++k)
      if (st[k].ok && mtime(cs.file(k, ".o")) > t) link_current = false;
  }
  if (!link_current) {
    out.log = std::string("linking") + (o.verbose ? ": " + link_cmd : "");
    std::error_code ec;
    fs::remove(link_file, ec);
    const ProcessResult pr = run_process(ProcessSpec{run_argv(link), {}, false}, o.compile_timeout_seconds);
    if (o.sandbox)
      if (std::string fault = sandbox_start_fault(pr, cs.dir); !fault.empty()) {
        out.machine_fault = out.message = std::move(fault);
        return out;
      }
    if (!pr.started || pr.exit_code != 0) {
      out.message = link_failure(pr.output);
      return out;
    }
    std::ofstream(link_file, std::ios::trunc) << link_cmd;
  }
  out.ok = true;
  return out;
}

// Sandboxed (untrusted mode): copies the source into `dir` for the compiler and sets out what the
// sandbox shows it; false, with r.message, when it cannot.
bool prepare_sandbox(const fs::path& source, const fs::path& dir, const Toolchain& tc, const BuildOptions& o,
                     fs::path& compiled_source, SandboxSpec& sandbox, BuildResult& r) {
  if (o.server && tc.server_object.empty()) {
    r.message = "the toolchain " + tc.path + " has no server_object: rebuild the suite (`./geomech build`)";
    return false;
  }
  if (const std::string why = copy_for_the_sandbox(source, dir); !why.empty()) {
    r.message = why;
    return false;
  }
  compiled_source = dir / "src" / source.filename();
  sandbox = compiler_sandbox(tc, dir);
  return true;
}

// The library flags the source asks for, and the roots the grader trusts; false, with r.message,
// when they cannot be resolved.
bool resolve_libraries(const fs::path& source, const fs::path& compiled_source, const BuildOptions& o,
                       SandboxSpec& sandbox, LibraryFlags& libs, std::vector<std::string>& trusted_roots,
                       BuildResult& r) {
  try {
    trusted_roots = trusted_library_roots();
    LibraryRequest wanted = o.libraries;
    wanted.add(declared_in_source(read_text(compiled_source), source.filename().string()));
    libs = resolve_library_flags(wanted, o.sandbox);
    // The folders the grader trusts (GEOMECH_LIBRARY_ROOTS) are shown to the sandboxed compiler.
    if (o.sandbox)
      for (const auto& root : trusted_roots) sandbox.read_only.push_back(root);
  } catch (const std::exception& e) {
    r.message = e.what();
    return false;
  }
  return true;
}

// Which units this build compiles; those it does not are marked done, with the reason.
void choose_units(const BuildOptions& o, UnitState st[]) {
  // Scalars not asked for (--scalar double) are not compiled at all. Double is the whole compile,
  // or the pieces: for a first look (its slots only), and after one, when its two pieces are up to
  // date and the whole is not (see kUnits).
  const bool pieces =
      !o.integrators || (st[kDoubleOtherSlots].ok && st[kDoubleManakovSlots].ok && !st[kDoubleWhole].ok);
  for (int k = 0; k < kUnitCount; ++k) {
    const Unit& unit = kUnits[k];
    st[k].wanted = k == kDoubleWhole                                    ? !pieces
                   : k == kDoubleOtherSlots || k == kDoubleManakovSlots ? pieces
                   : k == kDoubleIntegrators                            ? pieces && o.integrators
                   : unit.scalar == 1                                   ? o.mp50
                                                                        : o.exact;
    if (!st[k].wanted) {
      st[k].done = true;
      st[k].ok = false;
      st[k].unavailable =
          std::string("not compiled for ") + kScalars[unit.scalar] +
          (o.scalars_left_out_because.empty() ? " in this run (--scalar)" : ": " + o.scalars_left_out_because);
    }
  }
}

}  // namespace

BuildResult build_student(const std::string& source_in, const Toolchain& tc, const BuildOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  BuildResult r;
  std::error_code ec;
  const fs::path source = fs::canonical(source_in, ec);
  if (ec || !fs::is_regular_file(source)) {
    r.message = "cannot read " + source_in + (ec ? ": " + ec.message() : ": not a regular file");
    return r;
  }
  r.source = source.string();
  r.name = o.name.empty() ? source.stem().string() : o.name;
  // Absolute: the sandbox binds the folder and runs the compiler in it from its own root, where a
  // path relative to our working folder would name nothing.
  const fs::path dir = fs::absolute(o.cache_dir.empty() ? tc.cache_dir : o.cache_dir) /
                       (r.name + "-" + hex(fnv1a(r.source)) + (o.sandbox ? "-sandboxed" : ""));
  fs::create_directories(dir, ec);
  if (ec) {
    r.message = "cannot create the build directory " + dir.string() + ": " + ec.message();
    return r;
  }
  // Sandboxed (untrusted mode): the compiler sees a copy of the one source file, the
  // suite's headers and the prebuilt files, and writes only into `dir` (harness/isolation/sandbox.hpp).
  fs::path compiled_source = source;
  SandboxSpec sandbox;
  if (o.sandbox && !prepare_sandbox(source, dir, tc, o, compiled_source, sandbox, r)) return r;
  const RunArgv run_argv = [&](const std::vector<std::string>& argv) {
    return o.sandbox ? sandboxed(argv, sandbox) : argv;
  };

  // The libraries it uses (harness/program/library_flags.hpp): the command line's and the file's
  // own `// geomech:` lines; a stranger's (sandboxed) are vetted before the compiler sees them.
  LibraryFlags libs;
  std::vector<std::string> trusted_roots;  // GEOMECH_LIBRARY_ROOTS
  if (!resolve_libraries(source, compiled_source, o, sandbox, libs, trusted_roots, r)) return r;
  if (o.verbose)
    for (const auto& d : libs.dropped) r.log.push_back("left out " + d);

  std::vector<std::string> pch_inputs;
  if (!tc.precompiled_header.empty()) pch_inputs.push_back(tc.precompiled_header + ".gch");
  const CompileSetting cs{tc, libs, compiled_source, dir};
  UnitState st[kUnitCount];
  if (!o.force) read_cached_objects(cs, pch_inputs, st);
  choose_units(o, st);

  bool compiled_anything = false;
  if (!compile_rounds(cs, o, source, run_argv, st, compiled_anything, r)) {
    r.seconds = seconds();
    return r;
  }

  if (const int failed = failed_double_piece(st); failed >= 0) {
    const std::string hint = missing_header_hint(st[failed].output);
    r.message = "the file does not compile:\n" + error_summary(st[failed].output, r.source) +
                (hint.empty() ? "" : "hint: " + hint + "\n") +
                "the compiler's full output: " + cs.file(failed, ".log").string();
    r.does_not_compile = true;
    r.seconds = seconds();
    return r;
  }
  const json notes = notes_of(st, cs);

  const Linked linked = link_program(cs, o, st, trusted_roots, compiled_anything, run_argv);
  if (!linked.log.empty()) r.log.push_back(linked.log);
  if (!linked.ok) {
    r.message = linked.message;
    r.machine_fault = linked.machine_fault;
    return r;
  }
  const fs::path& program = linked.program;
  r.cached = !compiled_anything && linked.current;

  r.notes = notes;
  r.notes_file = (dir / "build-notes.json").string();
  write_file_atomically(r.notes_file, notes.dump(1) + "\n");
  r.program = program.string();
  r.ok = true;
  r.seconds = seconds();
  return r;
}

}  // namespace gm::harness
