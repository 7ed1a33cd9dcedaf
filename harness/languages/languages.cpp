#include "harness/languages/language.hpp"

#include "core/data_path.hpp"

#include <cstdlib>
#include <unistd.h>
#include <string_view>
#include <filesystem>

namespace gm::harness {

namespace fs = std::filesystem;

std::string python_interpreter() {
  // The user's interpreter: $GEOMECH_PYTHON, else the python3 that comes first on PATH (a
  // venv's or pyenv's), else Debian's.
  if (const char* py = std::getenv("GEOMECH_PYTHON"); py && *py) {
    const std::string found = on_path(py);
    return found.empty() ? py : found;
  }
  if (const std::string found = on_path("python3"); !found.empty()) return found;
  return "/usr/bin/python3";
}

std::string octave_interpreter() {
  if (const char* oc = std::getenv("GEOMECH_OCTAVE"); oc && *oc) {
    const std::string found = on_path(oc);
    return found.empty() ? oc : found;
  }
  const std::string found = on_path("octave-cli");
  return found.empty() ? "octave-cli" : found;
}

std::string octave_server_program() {
  const char* which = std::getenv("GEOMECH_OCTAVE_SERVER");
  const char* oc = std::getenv("GEOMECH_OCTAVE");
  if ((which && std::string(which) == "script") || (oc && *oc)) return "";
  std::error_code ec;
  // The linked server links the system's Octave (/usr): a user whose octave-cli on PATH is another
  // Octave (their own build, /opt/octave) gets that one, through the script server.
  if (const std::string cli = on_path("octave-cli"); !cli.empty()) {
    const std::string real = fs::weakly_canonical(cli, ec).string();
    if (!ec && real.rfind("/usr/", 0) != 0) return "";
  }
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path server = exe.parent_path() / "geomech-octave-server";
  return fs::exists(server, ec) ? server.string() : "";
}

namespace {

std::vector<std::string> python_server(const std::string& file) {
  // -B: no __pycache__ written beside the student's file or in the source tree.
  return {python_interpreter(), "-u", "-B", suite_data_path("student/python/geomech_server.py"), file};
}

std::vector<std::string> octave_server(const std::string& file) {
  if (const std::string embedded = octave_server_program(); !embedded.empty()) return {embedded, file};
  return {octave_interpreter(),
          "--no-gui",
          "--quiet",
          "--no-init-file",
          "--no-history",
          suite_data_path("student/octave/geomech_server.m"),
          file};
}

}  // namespace

const std::vector<Language>& languages() {
  static const std::vector<Language> table = [] {
    Language cpp;
    cpp.id = "c++";
    cpp.name = "C++";
    cpp.extensions = {".cpp", ".cc"};
    cpp.route = Route::Compiled;
    cpp.marker = "GEOMECH_STUDENT(";
    cpp.files_beside = true;

    Language python;
    python.id = "python";
    python.name = "Python";
    python.extensions = {".py"};
    python.route = Route::Served;
    python.interpreter_variable = "GEOMECH_PYTHON";
    python.system_interpreter = "/usr/bin/python3";
    python.interpreter = python_interpreter;
    python.start_probe = {"-c", "import sys"};
    python.server = python_server;

    Language octave;
    octave.id = "octave";
    octave.name = "Octave";
    octave.extensions = {".m"};
    octave.route = Route::Served;
    octave.folder_of_files = true;
    octave.interpreter_variable = "GEOMECH_OCTAVE";
    octave.system_interpreter = "/usr/bin/octave-cli";
    octave.interpreter = octave_interpreter;
    octave.server = octave_server;  // its start is tried by its first check
    return std::vector<Language>{cpp, python, octave};
  }();
  return table;
}

const Language* language_of_extension(std::string_view extension) {
  for (const auto& l : languages())
    for (const auto& e : l.extensions)
      if (e == extension) return &l;
  return nullptr;
}

const Language* language_of(const std::string& path) {
  const fs::path p(path);
  if (const Language* l = language_of_extension(p.extension().string())) return l;
  std::error_code ec;
  if (fs::is_directory(p, ec) && !fs::is_empty(p, ec))
    for (const auto& l : languages())
      if (l.folder_of_files) return &l;
  return nullptr;
}

const Language* language_named(std::string_view id) {
  for (const auto& l : languages())
    if (l.id == id) return &l;
  return nullptr;
}

std::string extensions_in_words() {
  std::vector<std::string> all;
  for (const auto& l : languages()) all.insert(all.end(), l.extensions.begin(), l.extensions.end());
  std::string out;
  for (std::size_t i = 0; i < all.size(); ++i) out += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i];
  return out;
}

std::string folder_in_words() {
  std::string out;
  for (const auto& l : languages())
    if (l.folder_of_files) out += ", nor a folder of " + l.extensions.front() + " files";
  return out;
}

std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why) {
  const Language* l = language_of(file);
  if (l && l->route == Route::Served) {
    if (language) *language = l->id;
    return l->server(file);
  }
  if (why) {
    std::string served;
    for (const auto& s : languages())
      if (s.route == Route::Served)
        for (const auto& e : s.extensions) served += (served.empty() ? "" : " or ") + e;
    *why = "not a " + served + " file" + folder_in_words();
  }
  return {};
}

std::string on_path(const std::string& program) {
  if (program.find('/') != std::string::npos) return program;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t from = 0;
  for (;;) {
    const std::size_t colon = dirs.find(':', from);
    const std::string dir = dirs.substr(from, colon == std::string::npos ? std::string::npos : colon - from);
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return fs::absolute(candidate).string();
    if (colon == std::string::npos) break;
    from = colon + 1;
  }
  return "";
}

}  // namespace gm::harness
