// Python: a file of functions named after the slots, served by student/python/geomech_server.py in
// the user's interpreter, in float, mpmath.mpf at 50 digits and fractions.Fraction; a notebook with
// a Python kernel (IPython's) has its code cells served the same way.
#include "harness/languages/notebook.hpp"
#include "harness/languages/rows.hpp"

#include "core/data_path.hpp"

#include <cctype>
#include <cstdlib>
#include <regex>
#include <set>

namespace gm::harness {

namespace {

std::string python_interpreter() {
  // The user's interpreter: $GEOMECH_PYTHON, else the python3 that comes first on PATH (a
  // venv's or pyenv's), else Debian's.
  return interpreter_named("GEOMECH_PYTHON", "python3", "/usr/bin/python3");
}

std::vector<std::string> python_server(const std::string& file) {
  // -B: no __pycache__ written beside the student's file or in the source tree.
  return {python_interpreter(), "-u", "-B", suite_data_path("student/python/geomech_server.py"), file};
}

SandboxedInterpreter python_in_sandbox(const std::string& interpreter) {
  return python_for_sandbox(interpreter,
                            "Set GEOMECH_PYTHON to one it can read, such as the system's /usr/bin/python3, or make the "
                            "interpreter's folders readable");
}

// The functions a Python file defines at module level (`def name(`).
std::vector<std::string> python_function_names(const std::string& source) {
  static const std::regex decl(R"((?:^|\n)def\s+([A-Za-z_]\w*)\s*\()");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), decl); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  return {names.begin(), names.end()};
}

// Comments (#) and string literals ('...', "...", and the triple-quoted ones across lines) blanked.
std::string python_code_only(const std::string& text) {
  std::string out = text;
  auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '#') {
      const std::size_t end = text.find('\n', i);
      blank(i, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end;
    } else if (text.compare(i, 3, "\"\"\"") == 0 || text.compare(i, 3, "'''") == 0) {
      const std::size_t end = text.find(text.substr(i, 3), i + 3);
      blank(i + 3, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end + 3;
    } else if (c == '"' || c == '\'') {
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

// `def name(` at any indentation (methods too).
std::vector<Definition> python_definitions(const std::string& code) {
  static const std::regex def(R"((^|\n)[ \t]*def[ \t]+([A-Za-z_]\w*)[ \t]*\()");
  std::vector<Definition> out;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), def); it != std::sregex_iterator(); ++it)
    out.push_back({static_cast<std::size_t>(it->position(2)), (*it)[2].str()});
  return out;
}

// An argument or result type of the slot table (C++) in Python's words.
std::string python_type(const std::string& t) {
  auto has = [&](const char* w) { return t.find(w) != std::string::npos; };
  if (has("Vec3Pair")) return "(3-list, 3-list)";
  if (has("MatXPair")) return "(matrix, matrix)";
  if (has("Vec3")) return "3-list";
  if (has("Vec6")) return "6-list";
  if (has("VecX")) return "list";
  if (has("Mat3")) return "3x3 list of rows";
  if (has("MatX")) return "list of rows";
  if (has("LieAlgebraId")) return "'so3'|'so4'|'sl2'";
  if (has("int")) return "int";
  return "scalar";
}

std::string python_signature(const std::string& slot, const std::string& signature) {
  std::string out;
  for (const auto& [type, name] : slot_parameters(signature))
    out += (out.empty() ? "" : ", ") + name + ": " + python_type(type);
  return "def " + slot + "(" + out + ") -> " + python_type(slot_result_type(signature));
}

std::string python_integrator_interface() {
  return "  class Midpoint:                           # one class (or dict) per integrator, at module level\n"
         "      name = \"midpoint\"\n"
         "      claims = {\"order\": 2, \"casimir\": True}  # keys: order symmetric casimir energy orthogonality "
         "spectrum\n"
         "                                            #   poisson noether equivariant bounded_energy symplectic\n"
         "      def rigid_body_step(I, x, h):         # I: 3-list, x[\"Pi\"]: 3-list, x[\"O\"]: 3x3 list of rows\n"
         "          return {\"Pi\": Pi, \"O\": O}         # or the pair (Pi, O)\n"
         "      # manakov_step(A, x, h): x[\"M\"], x[\"O\"] n x n; clebsch_step(I, QP, h), manakov_clebsch_step(A, QP, "
         "h):\n"
         "      # QP the pair (Q, P); h a float or an mpmath.mpf (steps are not run in rationals)\n";
}

// IPython's own syntax in a cell: a cell magic (%%time on the first line) sets the whole cell aside; a
// line magic (%timeit f(x)) or a shell escape (!pip install mpmath), or one assigned (files = !ls), at
// the start of a statement (not inside brackets, a string or after a backslash) becomes `pass` at
// its indentation, so that every other line keeps its number and a block keeps a statement.
CellCode python_cell_code(const std::string& source) {
  CellCode out;
  if (const std::string magic = cell_magic(source); !magic.empty()) {
    out.whole_cell = "a cell magic (" + magic + "), run by IPython, not Python";
    return out;
  }
  const std::string code = python_code_only(source);
  static const std::regex assigned(R"(^[ \t]*[A-Za-z_][\w.]*[ \t]*=[ \t]*[%!])");
  int depth = 0, line_no = 0;
  bool continued = false;
  std::size_t at = 0;
  while (at <= source.size()) {
    const std::size_t end = std::min(source.find('\n', at), source.size());
    const std::string line = source.substr(at, end - at), bare = code.substr(at, end - at);
    ++line_no;
    const std::size_t first = bare.find_first_not_of(" \t");
    std::string replaced = line;
    if (depth == 0 && !continued && first != std::string::npos) {
      char op = bare[first];  // '!' a shell escape, '%' a line magic, at the statement's start or assigned
      std::smatch m;
      if (op != '!' && op != '%' && std::regex_search(bare, m, assigned))
        op = bare[static_cast<std::size_t>(m.length(0)) - 1];
      if (op == '!' || op == '%') {
        std::string what = line.substr(first);
        while (!what.empty() && (what.back() == '\r' || what.back() == ' ')) what.pop_back();
        out.skipped.emplace_back(line_no,
                                 std::string(op == '!' ? "a shell escape" : "a line magic") + " (" + what + ")");
        replaced = line.substr(0, first) + "pass";
      }
    }
    for (const char c : bare) depth += (c == '(' || c == '[' || c == '{') - (c == ')' || c == ']' || c == '}');
    if (depth < 0) depth = 0;
    const std::size_t last = bare.find_last_not_of(" \t\r");
    continued = last != std::string::npos && bare[last] == '\\';
    out.code += replaced;
    if (end == source.size()) break;
    out.code += '\n';
    at = end + 1;
  }
  return out;
}

ValueStyle python_values() {
  ValueStyle v;
  v.nested_rows = true;
  v.mp50_before = "mpf('";
  v.mp50_after = "')";
  v.rational_before = "Fraction(";
  v.rational_between = ", ";
  v.rational_after = ")";
  v.vector_type = "{n}-list of {s}";
  v.any_vector_type = "list of {s}";
  v.matrix_type = "{n} list of rows of {s}";
  v.any_matrix_type = "list of rows of {s}";
  v.double_name = "float";
  v.mp50_name = "mpf";
  v.rational_name = "Fraction";
  return v;
}

}  // namespace

Language python_row() {
  Language python;
  python.id = "python";
  python.name = "Python";
  python.extensions = {".py"};
  python.route = Route::Served;
  python.function_noun = "Python function";
  python.version_label = "Python";
  python.values = python_values();
  python.timeout_factor = 3;
  python.double_only_error = "TypeError";
  python.double_only_hint =
      "(a TypeError in 50 digits: a step that computes in double only says so with precision = \"double\" "
      "in its class, and is then run in double only; docs/STUDENTS.md, \"A step's stated precision\")";
  python.function_names = python_function_names;
  python.code_only = python_code_only;
  python.definitions = python_definitions;
  python.slots_heading = "## Python: functions named after the slots (scalars: float, mpmath.mpf, fractions.Fraction)";
  python.slots_fence = "python";
  python.comment = "# ";
  python.signature = python_signature;
  python.integrator_interface = python_integrator_interface;
  python.interpreter_variable = "GEOMECH_PYTHON";
  python.system_interpreter = "/usr/bin/python3";
  python.interpreter = python_interpreter;
  python.start_probe = {"-c", "import sys"};
  python.for_sandbox = python_in_sandbox;
  python.self_test_by_default = true;
  python.server = python_server;
  python.kernels = {"python", "python3"};
  python.cell_code = python_cell_code;
  return python;
}

}  // namespace gm::harness
