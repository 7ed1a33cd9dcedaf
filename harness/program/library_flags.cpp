#include "harness/program/library_flags.hpp"

#include "harness/isolation/process.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gm::harness {

namespace fs = std::filesystem;

void LibraryRequest::add(const LibraryRequest& o) {
  pkgs.insert(pkgs.end(), o.pkgs.begin(), o.pkgs.end());
  cxxflags.insert(cxxflags.end(), o.cxxflags.begin(), o.cxxflags.end());
  ldflags.insert(ldflags.end(), o.ldflags.begin(), o.ldflags.end());
}

std::vector<std::string> split_flags(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  bool any = false;
  char quote = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote)
        quote = 0;
      else if (c == '\\' && quote == '"' && i + 1 < text.size())
        cur += text[++i];
      else
        cur += c;
    } else if (c == '\'' || c == '"') {
      quote = c, any = true;
    } else if (c == '\\' && i + 1 < text.size()) {
      cur += text[++i], any = true;
    } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      if (any || !cur.empty()) out.push_back(cur);
      cur.clear(), any = false;
    } else {
      cur += c, any = true;
    }
  }
  if (quote) throw std::invalid_argument("an unclosed quote in the flags '" + text + "'");
  if (any || !cur.empty()) out.push_back(cur);
  return out;
}

LibraryRequest declared_in_source(const std::string& text, const std::string& file_name) {
  LibraryRequest r;
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 2, "//") != 0) continue;
    std::string rest = line.substr(start + 2);
    const auto word = rest.find_first_not_of(" \t");
    if (word == std::string::npos || rest.compare(word, 8, "geomech:") != 0) continue;
    rest = rest.substr(word + 8);
    std::vector<std::string> words = split_flags(rest);
    if (words.empty())
      throw std::invalid_argument(
          file_name + ":" + std::to_string(n) +
          ": a `// geomech:` line says nothing; write "
          "`// geomech: pkg NAME`, `// geomech: cxxflags FLAGS` or `// geomech: ldflags FLAGS`");
    const std::string what = words.front();
    words.erase(words.begin());
    if (what == "pkg")
      r.pkgs.insert(r.pkgs.end(), words.begin(), words.end());
    else if (what == "cxxflags")
      r.cxxflags.insert(r.cxxflags.end(), words.begin(), words.end());
    else if (what == "ldflags")
      r.ldflags.insert(r.ldflags.end(), words.begin(), words.end());
    else
      throw std::invalid_argument(file_name + ":" + std::to_string(n) + ": `// geomech: " + what +
                                  "` is not a request the suite knows; write `// geomech: pkg NAME`, "
                                  "`// geomech: cxxflags FLAGS` or `// geomech: ldflags FLAGS`");
  }
  return r;
}

std::vector<std::string> trusted_library_roots() {
  std::vector<std::string> roots;
  const char* env = std::getenv("GEOMECH_LIBRARY_ROOTS");
  if (!env) return roots;
  std::string text = env;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t colon = std::min(text.find(':', start), text.size());
    const std::string r = text.substr(start, colon - start);
    start = colon + 1;
    if (r.empty()) continue;
    std::error_code ec;
    if (r.front() != '/' || !fs::is_directory(r, ec))
      throw std::invalid_argument("GEOMECH_LIBRARY_ROOTS: '" + r +
                                  "' is not an absolute path of a folder (the grader's "
                                  "setting: the folders of libraries installed for a class, separated by ':')");
    const std::string real = fs::weakly_canonical(fs::path(r), ec).string();
    if (real == "/") throw std::invalid_argument("GEOMECH_LIBRARY_ROOTS: '/' would show the sandbox the whole machine");
    roots.push_back(real);
  }
  return roots;
}

// The folder to trust for DIR: its parent when DIR is an include or lib folder (PREFIX/include ->
// PREFIX), so that one root covers a library's headers and its archives.
std::string library_root_of(const std::string& dir) {
  std::error_code ec;
  fs::path real = fs::weakly_canonical(fs::path(dir), ec);
  if (ec) real = dir;
  for (fs::path p = real; p.has_parent_path() && p != p.parent_path(); p = p.parent_path()) {
    const std::string leaf = p.filename().string();
    if (leaf == "include" || leaf == "lib" || leaf == "lib64") return p.parent_path().string();
  }
  return real.string();
}

namespace {

// A folder under one of `roots`, after resolving links and "..": the system's, not the host's.
bool under(const std::string& dir, const std::vector<std::string>& roots) {
  std::error_code ec;
  const std::string real = fs::weakly_canonical(fs::path(dir), ec).string();
  if (ec || dir.empty() || dir.front() != '/') return false;
  for (const std::string& r : roots)
    if (real == r || real.rfind(r + "/", 0) == 0) return true;
  return false;
}

// The system's folders, and the ones the grader trusts (GEOMECH_LIBRARY_ROOTS).
std::vector<std::string> with_trusted(std::vector<std::string> roots) {
  for (const auto& r : trusted_library_roots()) roots.push_back(r);
  return roots;
}

// Why a flag is refused for a stranger's file, or "" when it passes. `next` is the word after it (the
// folder of a separate -I DIR), consumed by the caller when `takes_next`.
std::string refusal(const std::string& f, bool link, const std::string* next, bool* takes_next) {
  *takes_next = false;
  auto folder_flag = [&](const std::string& flag, const std::vector<std::string>& roots,
                         const char* what) -> std::string {
    std::string dir = f.substr(flag.size());
    if (dir.empty()) {
      if (!next) return "'" + f + "' without its folder";
      dir = *next;
      *takes_next = true;
    }
    if (under(dir, roots)) return {};
    return "'" + f + (f.size() == flag.size() ? " " + dir : "") + "': the folder is not one of the system's " + what +
           " folders (" + (link ? "/usr/lib, /lib" : "/usr/include") +
           ") nor under GEOMECH_LIBRARY_ROOTS, so it would "
           "show the sandboxed compiler a folder of this machine; a grader who installed the library there for the "
           "class trusts it with GEOMECH_LIBRARY_ROOTS=" +
           library_root_of(dir);
  };
  if (f.empty()) return "an empty flag";
  if (f[0] == '@') return "'" + f + "': an @file makes the compiler read its options from a file of this machine";
  if (f.rfind("-B", 0) == 0) return "'" + f + "': -B makes the compiler run its programs from another folder";
  if (f == "-wrapper" || f.rfind("-wrapper", 0) == 0)
    return "'" + f + "': -wrapper runs a program of the host around each tool";
  if (f.rfind("-fplugin", 0) == 0) return "'" + f + "': -fplugin loads code of the host into the compiler";
  if (f.rfind("-specs", 0) == 0 || f.rfind("--specs", 0) == 0)
    return "'" + f + "': -specs rewrites the compiler driver's commands";
  if (f.rfind("-Wl,", 0) == 0 || f.rfind("-Wa,", 0) == 0 || f.rfind("-Wp,", 0) == 0 || f == "-Xlinker" ||
      f == "-Xassembler" || f == "-Xpreprocessor")
    return "'" + f +
           "': it passes options to another program (the linker, the assembler), beyond what the suite can vet";
  if (f.rfind("-D", 0) == 0 || f.rfind("-U", 0) == 0) return f.size() > 2 ? "" : "'" + f + "' without its macro";
  if (f == "-pthread") return "";
  if (f.rfind("-W", 0) == 0) return "";  // a warning switch (-Wall, -Wno-unused); -Wl, and the like are refused above
  static const std::vector<std::string> include_roots = with_trusted({"/usr/include"});
  static const std::vector<std::string> library_roots = with_trusted({"/usr/lib", "/lib", "/usr/lib64", "/lib64"});
  if (!link && f.rfind("-isystem", 0) == 0) return folder_flag("-isystem", include_roots, "include");
  if (!link && f.rfind("-I", 0) == 0) return folder_flag("-I", include_roots, "include");
  if (link && f.rfind("-L", 0) == 0) return folder_flag("-L", library_roots, "library");
  if (link && f.rfind("-l", 0) == 0) {
    const std::string name = f.substr(2);
    if (name.empty() || name.find('/') != std::string::npos || name.find(':') != std::string::npos)
      return "'" + f + "': a library is named by its name alone (-lode), never by a path";
    return {};
  }
  return "'" + f +
         "' is not among the flags a file checked in untrusted mode may give: -D, -U, -I or -isystem "
         "under /usr/include (or GEOMECH_LIBRARY_ROOTS), -W..., -pthread" +
         std::string(link ? "; for linking -l and -L under /usr/lib or /lib (or GEOMECH_LIBRARY_ROOTS)" : "");
}

void vet(const std::vector<std::string>& flags, bool link, const std::string& from, std::vector<std::string>& refused) {
  for (std::size_t i = 0; i < flags.size(); ++i) {
    bool takes_next = false;
    const std::string why = refusal(flags[i], link, i + 1 < flags.size() ? &flags[i + 1] : nullptr, &takes_next);
    if (!why.empty()) refused.push_back(why + " (" + from + ")");
    if (takes_next) ++i;
  }
}

bool package_name_ok(const std::string& p) {
  if (p.empty() || p[0] == '-') return false;
  for (char c : p)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == '+')) return false;
  return true;
}

std::vector<std::string> pkg_config(const std::string& pkg, const char* what) {
  const ProcessResult r = run_process(ProcessSpec{{"pkg-config", what, pkg}, {}, false}, 30);
  if (!r.started)
    throw std::invalid_argument("--pkg " + pkg +
                                ": pkg-config could not be run (apt-get install pkg-config): " + r.output);
  if (r.exit_code != 0) {
    std::string msg = r.output;
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
    throw std::invalid_argument("--pkg " + pkg + ": pkg-config does not know it (" + msg +
                                "); `pkg-config --list-all` lists the packages it knows");
  }
  return split_flags(r.output);
}

}  // namespace

namespace {

// A package's --cflags without what the suite sets itself: -std=..., -O..., warning switches (-W...
// but -Wl,/-Wa,/-Wp, which are passed on and vetted), with each left out said in `dropped`.
std::vector<std::string> without_suite_switches(const std::vector<std::string>& flags, const std::string& pkg,
                                                std::vector<std::string>& dropped) {
  std::vector<std::string> kept;
  for (const auto& f : flags) {
    const bool standard = f.rfind("-std=", 0) == 0 || f.rfind("--std=", 0) == 0;
    const bool optimisation = f.rfind("-O", 0) == 0;
    const bool warning =
        f.rfind("-W", 0) == 0 && f.rfind("-Wl,", 0) != 0 && f.rfind("-Wa,", 0) != 0 && f.rfind("-Wp,", 0) != 0;
    if (standard || optimisation || warning)
      dropped.push_back("'" + f + "' from pkg-config --cflags " + pkg +
                        (standard       ? ": the suite compiles in its own standard (C++20)"
                         : optimisation ? ": the suite sets the optimisation"
                                        : ": the suite sets the warnings"));
    else
      kept.push_back(f);
  }
  return kept;
}

// A folder flag (-I, -isystem, -L) with its folder canonical, "-I" "DIR" joined; other flags as they are.
std::vector<std::string> canonical_folders(const std::vector<std::string>& flags) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < flags.size(); ++i) {
    std::string f = flags[i];
    for (const char* flag : {"-isystem", "-I", "-L"}) {
      const std::string prefix = flag;
      if (f.rfind(prefix, 0) != 0) continue;
      std::string dir = f.substr(prefix.size());
      if (dir.empty() && i + 1 < flags.size()) dir = flags[++i];
      std::error_code ec;
      const fs::path real = fs::weakly_canonical(fs::path(dir), ec);  // as the compiler finds it, links followed
      f = prefix + (ec || dir.empty() ? dir : real.string());
      break;
    }
    out.push_back(f);
  }
  return out;
}

// Each flag once, in the order first given (a package asked on the command line and in the file).
// An option whose value is the next word (-include FILE, -isystem DIR, ...) and that word are kept as
// they come, and so is a word that is not an option.
void append_once(std::vector<std::string>& to, const std::vector<std::string>& flags) {
  static const std::set<std::string> takes_next = {
      "-include", "-imacros", "-isystem", "-iquote",        "-idirafter",  "-I", "-L",
      "-D",       "-U",       "-Xlinker", "-Xpreprocessor", "-Xassembler", "-x"};
  for (std::size_t i = 0; i < flags.size(); ++i) {
    const std::string& f = flags[i];
    if (takes_next.count(f) && i + 1 < flags.size()) {
      to.push_back(f);
      to.push_back(flags[++i]);
    } else if (f.empty() || f[0] != '-' || std::find(to.begin(), to.end(), f) == to.end()) {
      to.push_back(f);
    }
  }
}

}  // namespace

LibraryFlags resolve_library_flags(const LibraryRequest& req, bool stranger) {
  LibraryFlags out;
  std::vector<std::string> refused;
  std::vector<std::string> pkgs;
  for (const auto& p : req.pkgs)
    if (std::find(pkgs.begin(), pkgs.end(), p) == pkgs.end()) pkgs.push_back(p);
  // Two builds of one library (ode and ode-float64, say: single and double precision) linked
  // together mix their scalars: refused, naming both.
  for (const auto& a : pkgs)
    for (const auto& b : pkgs)
      if (b.size() > a.size() + 1 && b.rfind(a + "-", 0) == 0) {
        const std::string suffix = b.substr(a.size() + 1);
        for (const char* precision : {"float", "float32", "float64", "double", "single", "sp", "dp", "f32", "f64"})
          if (suffix == precision)
            throw std::invalid_argument("--pkg " + a + " and --pkg " + b +
                                        " are two builds of one library (in another "
                                        "precision): a program linking both mixes them; give one of them");
      }
  for (const auto& p : pkgs) {
    if (!package_name_ok(p)) {
      refused.push_back("'" + p + "' is not a pkg-config package name (letters, digits, _ - . +)");
      continue;
    }
    const auto cflags = without_suite_switches(pkg_config(p, "--cflags"), p, out.dropped);
    const auto libs = pkg_config(p, "--libs");
    if (stranger) {
      vet(cflags, false, "pkg-config --cflags " + p, refused);
      vet(libs, true, "pkg-config --libs " + p, refused);
    }
    // pkg-config spells folders as its .pc file does (PREFIX/lib/pkgconfig/../../include): the
    // sandbox is shown them canonical, as vetted.
    append_once(out.compile, stranger ? canonical_folders(cflags) : cflags);
    append_once(out.link, stranger ? canonical_folders(libs) : libs);
    out.pkgs.push_back(p);
  }
  if (stranger) {
    vet(req.cxxflags, false, "compile flags", refused);
    vet(req.ldflags, true, "link flags", refused);
  }
  append_once(out.compile, stranger ? canonical_folders(req.cxxflags) : req.cxxflags);
  append_once(out.link, stranger ? canonical_folders(req.ldflags) : req.ldflags);
  if (!refused.empty()) {
    std::string msg =
        "flags refused for a file checked in untrusted mode (its compiler runs in the sandbox, which may "
        "read the system's headers and libraries and nothing else of this machine):";
    for (const auto& r : refused) msg += "\n  " + r;
    throw std::invalid_argument(msg);
  }
  return out;
}

std::string missing_header_hint(const std::string& out) {
  const std::string tail = ": No such file or directory";
  const auto at = out.find(tail);
  if (at == std::string::npos) return {};
  const auto fatal = out.rfind("fatal error: ", at);
  if (fatal == std::string::npos) return {};
  const std::string header = out.substr(fatal + 13, at - fatal - 13);
  if (header.empty() || header.find('\n') != std::string::npos) return {};
  // The system's include folders that hold it (e.g. /usr/include/eigen3 for Eigen/Dense), and the
  // packages whose --cflags name such a folder.
  std::set<std::string> dirs;
  std::error_code ec;
  if (fs::exists(fs::path("/usr/include") / header, ec)) dirs.insert("/usr/include");
  for (auto it = fs::recursive_directory_iterator("/usr/include", fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it.depth() >= 1) it.disable_recursion_pending();  // /usr/include/X and /usr/include/X/Y
    if (it->is_directory(ec) && fs::exists(it->path() / header, ec)) dirs.insert(it->path().string());
  }
  std::set<std::string> pkgs;
  if (!dirs.empty()) {
    const ProcessResult list = run_process(ProcessSpec{{"pkg-config", "--list-all"}, {}, false}, 30);
    std::istringstream in(list.exit_code == 0 ? list.output : "");
    for (std::string line; std::getline(in, line) && pkgs.size() < 5;) {
      const std::string name = line.substr(0, line.find(' '));
      if (!package_name_ok(name)) continue;
      const ProcessResult c = run_process(ProcessSpec{{"pkg-config", "--cflags-only-I", name}, {}, false}, 30);
      for (const auto& f : split_flags(c.output))
        if (f.rfind("-I", 0) == 0 && dirs.count(fs::weakly_canonical(f.substr(2), ec).string())) pkgs.insert(name);
    }
  }
  std::string hint = "the header " + header + " is not found: ";
  if (!pkgs.empty()) {
    hint += "it is in";
    for (const auto& d : dirs) hint += " " + d;
    if (pkgs.size() == 1)
      return hint + "; give its package: --pkg " + *pkgs.begin() + " (or the line `// geomech: pkg " + *pkgs.begin() +
             "` in the file)";
    // Several packages hold it: builds of one library (single and double precision, say), each an
    // alternative to the others; given together, a program would mix them.
    hint +=
        "; give one of its packages, not several (each is another build of the library, such as single or double "
        "precision):";
    bool first = true;
    for (const auto& p : pkgs) hint += std::string(first ? " " : " or ") + "--pkg " + p, first = false;
    return hint;
  }
  if (!dirs.empty()) {
    hint += "it is in";
    for (const auto& d : dirs) hint += " " + d;
    return hint + "; give that folder: --cxxflags -I" + *dirs.begin();
  }
  return hint +
         "if it belongs to a library, install the library's development package and give its pkg-config name, "
         "--pkg NAME (or the line `// geomech: pkg NAME` in the file; `pkg-config --list-all` lists them), or "
         "its folders with --cxxflags -IDIR and its libraries with --ldflags -lNAME";
}

}  // namespace gm::harness
