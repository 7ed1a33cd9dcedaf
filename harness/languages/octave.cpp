// Octave (MATLAB's language): a file of functions, or a folder with one function per file, served in
// double by geomech-octave-server (Octave linked in) or student/octave/geomech_server.m in
// octave-cli; a notebook with an Octave kernel (octave_kernel, a metakernel) has its code cells
// served the same way.
#include "harness/languages/notebook.hpp"
#include "harness/languages/rows.hpp"

#include "core/data_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>

namespace gm::harness {

namespace fs = std::filesystem;

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

std::string octave_interpreter() {
  // $GEOMECH_OCTAVE, else the octave-cli first on PATH (the script server names it so when missing).
  return interpreter_named("GEOMECH_OCTAVE", "octave-cli", "octave-cli");
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

SandboxedInterpreter octave_in_sandbox(const std::string& interpreter) {
  return installation_for_sandbox(interpreter, "the Octave installation",
                                  "Set GEOMECH_OCTAVE to one it can read, such as the system's /usr/bin/octave-cli, "
                                  "or make the interpreter's folders readable");
}

// `function [r] = name(` or `function name(` (a file of functions; a folder has one per `name.m`).
std::vector<std::string> octave_function_names(const std::string& source) {
  static const std::regex decl(R"((?:^|\n)\s*function\s+(?:\[?[\w\s,]*\]?\s*=\s*)?([A-Za-z_]\w*)\s*[\(\n;])");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), decl); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  return {names.begin(), names.end()};
}

// Comments (% and #, to the end of the line) and "..." strings blanked: in Octave a ' is also the
// transpose, so '...' strings are left as they are.
std::string octave_code_only(const std::string& text) {
  std::string out = text;
  auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '%' || c == '#') {
      const std::size_t end = text.find('\n', i);
      blank(i, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end;
    } else if (c == '"') {
      std::size_t k = i + 1;
      while (k < text.size() && text[k] != c && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
      blank(i + 1, k);
      i = k + 1;
    } else {
      ++i;
    }
  }
  return out;
}

std::vector<Definition> octave_definitions(const std::string& code) {
  static const std::regex def(R"((^|\n)[ \t]*function[ \t]+(?:[^\n=]*=[ \t]*)?([A-Za-z_]\w*)[ \t]*[\(\n;])");
  std::vector<Definition> out;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), def); it != std::sregex_iterator(); ++it)
    out.push_back({static_cast<std::size_t>(it->position(2)), (*it)[2].str()});
  return out;
}

// An argument or result type of the slot table (C++) in MATLAB's words.
std::string octave_type(const std::string& t) {
  auto has = [&](const char* w) { return t.find(w) != std::string::npos; };
  if (has("Vec3Pair")) return "{3x1, 3x1}";
  if (has("MatXPair")) return "{matrix, matrix}";
  if (has("Vec3")) return "3x1";
  if (has("Vec6")) return "6x1";
  if (has("VecX")) return "column";
  if (has("Mat3")) return "3x3";
  if (has("MatX")) return "matrix";
  if (has("LieAlgebraId")) return "'so3'|'so4'|'sl2'";
  if (has("int")) return "int";
  return "scalar";
}

std::string octave_signature(const std::string& slot, const std::string& signature) {
  std::string out;
  for (const auto& [type, name] : slot_parameters(signature))
    out += (out.empty() ? "" : ", ") + name + " %" + octave_type(type);
  return "function r = " + slot + "(" + out + ")  % r: " + octave_type(slot_result_type(signature));
}

std::string octave_integrator_interface() {
  return "  function list = geomech_integrators()     % a struct array, one element per integrator\n"
         "    list = struct('name', 'midpoint', 'claims', struct('order', 2, 'casimir', true), ...\n"
         "                  'rigid_body_step', @midpoint_step);\n"
         "  end\n"
         "  function x = midpoint_step(I, x0, h)      % I: 3x1; x0.Pi: 3x1 column; x0.O: 3x3; return x.Pi, x.O\n"
         "  % manakov_step(A, x, h): x.M, x.O n x n; clebsch_step(I, QP, h), manakov_clebsch_step(A, QP, h): QP = {Q, "
         "P}\n"
         "  % claims fields: order symmetric casimir energy orthogonality spectrum poisson noether equivariant\n"
         "  %                bounded_energy symplectic\n";
}

// The Octave kernel's own syntax in a cell (metakernel's): a cell magic (%%file on the first line)
// sets the whole cell aside; a shell escape (!ls) at the start of a statement becomes an empty line,
// so that every other line keeps its number. Its line magics (%plot inline) are comments in Octave.
CellCode octave_cell_code(const std::string& source) {
  CellCode out;
  if (const std::string magic = cell_magic(source); !magic.empty()) {
    out.whole_cell = "a cell magic (" + magic + "), run by the Octave kernel, not Octave";
    return out;
  }
  const std::string code = octave_code_only(source);
  int depth = 0, line_no = 0;
  bool continued = false;
  std::size_t at = 0;
  while (at <= source.size()) {
    const std::size_t end = std::min(source.find('\n', at), source.size());
    const std::string line = source.substr(at, end - at), bare = code.substr(at, end - at);
    ++line_no;
    const std::size_t first = bare.find_first_not_of(" \t");
    std::string replaced = line;
    if (depth == 0 && !continued && first != std::string::npos && bare[first] == '!') {
      std::string what = line.substr(first);
      while (!what.empty() && (what.back() == '\r' || what.back() == ' ')) what.pop_back();
      out.skipped.emplace_back(line_no, "a shell escape (" + what + ")");
      replaced.clear();
    }
    for (const char c : bare) depth += (c == '(' || c == '[' || c == '{') - (c == ')' || c == ']' || c == '}');
    if (depth < 0) depth = 0;
    const std::size_t last = bare.find_last_not_of(" \t\r");
    continued = last != std::string::npos && last >= 2 && bare.compare(last - 2, 3, "...") == 0;
    out.code += replaced;
    if (end == source.size()) break;
    out.code += '\n';
    at = end + 1;
  }
  return out;
}

ValueStyle octave_values() {
  ValueStyle v;
  v.column_separator = "; ";  // a column is rows
  v.vector_type = "{n}x1 column vector";
  v.any_vector_type = "column vector";
  v.matrix_type = "{n} matrix";
  v.any_matrix_type = "matrix";
  v.double_name = v.mp50_name = v.rational_name = "double";
  return v;
}

}  // namespace

Language octave_row() {
  Language octave;
  octave.id = "octave";
  octave.name = "Octave";
  octave.extensions = {".m"};
  octave.route = Route::Served;
  octave.folder_of_files = true;
  octave.function_noun = "Octave function";
  octave.version_label = "Octave";
  octave.scalars_note = " (Octave code is checked in double only)";
  octave.values = octave_values();
  octave.timeout_factor = 6;
  octave.function_names = octave_function_names;
  octave.code_only = octave_code_only;
  octave.definitions = octave_definitions;
  octave.slots_heading = "## Octave / MATLAB: functions named after the slots (double only)";
  octave.slots_fence = "matlab";
  octave.comment = "% ";
  octave.signature = octave_signature;
  octave.integrator_interface = octave_integrator_interface;
  octave.interpreter_variable = "GEOMECH_OCTAVE";
  octave.system_interpreter = "/usr/bin/octave-cli";
  octave.interpreter = octave_interpreter;
  octave.for_sandbox = octave_in_sandbox;
  octave.server = octave_server;  // its start is tried by its first check
  octave.kernels = {"octave"};
  octave.cell_code = octave_cell_code;
  return octave;
}

}  // namespace gm::harness
