#include "harness/submissions/languages.hpp"

#include "core/data_path.hpp"
#include "harness/remote/remote_subject.hpp"

#include <cstdlib>
#include <filesystem>

namespace gm::harness {

namespace fs = std::filesystem;
using protocol::on_path;

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

std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why) {
  const fs::path p(file);
  std::error_code ec;
  if (p.extension() == ".py") {
    if (language) *language = "python";
    // -B: no __pycache__ written beside the student's file or in the source tree.
    return {python_interpreter(), "-u", "-B", suite_data_path("student/python/geomech_server.py"), file};
  }
  if (p.extension() == ".m" || (fs::is_directory(p, ec) && !fs::is_empty(p, ec))) {
    if (language) *language = "octave";
    if (const std::string embedded = octave_server_program(); !embedded.empty()) return {embedded, file};
    return {octave_interpreter(),
            "--no-gui",
            "--quiet",
            "--no-init-file",
            "--no-history",
            suite_data_path("student/octave/geomech_server.m"),
            file};
  }
  if (why) *why = "not a .py or .m file (nor a folder of .m files)";
  return {};
}

}  // namespace gm::harness
