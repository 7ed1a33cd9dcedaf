// JavaScript on Node: an ES module (.mjs, or a .js file, ES module or CommonJS) exporting functions
// named after the slots, served by student/javascript/geomech_server.mjs in double (JavaScript's
// numbers are IEEE doubles, so nothing is checked in 50 digits or exactly). Integrators are exported
// objects or classes. A physics engine built to WebAssembly is driven from such a file.
#include "harness/languages/rows.hpp"

#include "core/data_path.hpp"

#include <cstdlib>
#include <regex>
#include <set>

namespace gm::harness {

namespace {

std::string node_interpreter() {
  // $GEOMECH_NODE, else the node first on PATH (nvm's, a distribution's), else Debian's.
  return interpreter_named("GEOMECH_NODE", "node", "/usr/bin/node");
}

std::vector<std::string> node_server(const std::string& file) {
  return {node_interpreter(), suite_data_path("student/javascript/geomech_server.mjs"), file};
}

SandboxedInterpreter node_in_sandbox(const std::string& interpreter) {
  return installation_for_sandbox(interpreter, "the Node installation",
                                  "Set GEOMECH_NODE to one it can read, such as the system's /usr/bin/node, or "
                                  "make the interpreter's folders readable");
}

// The functions a module exports where a slot may be: `export function name(`, `export const name =`,
// `exports.name =`, `module.exports = { name, ... }` (its shorthand and `name:` keys).
std::vector<std::string> javascript_function_names(const std::string& source) {
  static const std::regex exported(
      R"((?:^|\n)[ \t]*(?:export[ \t]+(?:async[ \t]+)?function\*?[ \t]+|export[ \t]+(?:const|let|var)[ \t]+|(?:module\.)?exports\.)([A-Za-z_$][\w$]*))");
  static const std::regex object(R"(module\.exports\s*=\s*\{([^}]*)\})");
  static const std::regex key(R"(^\s*([A-Za-z_$][\w$]*)\s*(?::|$))");  // `name` or `name: value`
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), exported); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  for (auto it = std::sregex_iterator(source.begin(), source.end(), object); it != std::sregex_iterator(); ++it) {
    const std::string body = (*it)[1].str();
    std::size_t from = 0;
    for (;;) {
      const std::size_t comma = body.find(',', from);
      const std::string entry = body.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
      std::smatch m;
      if (std::regex_search(entry, m, key)) names.insert(m[1].str());
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
  }
  return {names.begin(), names.end()};
}

// Comments (// and /* */) and string literals ('...', "...", `...` across lines) blanked.
std::string javascript_code_only(const std::string& text) { return c_like_code_only(text, "\"'`", '`'); }

// Where functions begin: `function name(`, `name = (...) =>` or `name = function`, and methods
// (`name(...) {` at a line's start, in a class or an object).
std::vector<Definition> javascript_definitions(const std::string& code) {
  static const std::regex def(
      R"((?:function\*?[ \t]+([A-Za-z_$][\w$]*)[ \t]*\()|(?:([A-Za-z_$][\w$]*)[ \t]*[=:][ \t]*(?:async[ \t]*)?(?:function\b|\([^()]*\)[ \t]*=>|[A-Za-z_$][\w$]*[ \t]*=>))|(?:(?:^|\n)[ \t]*(?:static[ \t]+)?([A-Za-z_$][\w$]*)[ \t]*\([^()]*\)[ \t]*\{))");
  static const std::set<std::string> keywords{"if", "for", "while", "switch", "catch", "function", "return"};
  std::vector<Definition> out;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), def); it != std::sregex_iterator(); ++it)
    for (int g = 1; g <= 3; ++g)
      if ((*it)[g].matched && !keywords.count((*it)[g].str()))
        out.push_back({static_cast<std::size_t>(it->position(g)), (*it)[g].str()});
  return out;
}

// The npm packages a file names, one `// geomech: npm NAME` line each (NAME as npm spells a package:
// lower case, digits, - . _ ~, not first a - . or _; an @scope/ before it); a line that names anything else is left out
// (the import then fails inside the sandbox with Node's own message).
std::vector<std::string> javascript_named_packages(const std::string& source) {
  static const std::regex line(R"((?:^|\n)[ \t]*//[ \t]*geomech:[ \t]*npm[ \t]+(\S+)[ \t]*(?=\r?\n|$))");
  static const std::regex name(R"(^(@[a-z0-9~][a-z0-9._~-]*/)?[a-z0-9~][a-z0-9._~-]*$)");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), line); it != std::sregex_iterator(); ++it)
    if (const std::string n = (*it)[1].str(); n.size() <= 214 && std::regex_match(n, name)) names.insert(n);
  return {names.begin(), names.end()};
}

// An argument or result type of the slot table (C++) in JavaScript's words.
std::string javascript_type(const std::string& t) {
  auto has = [&](const char* w) { return t.find(w) != std::string::npos; };
  if (has("Vec3Pair")) return "[vec3, vec3]";
  if (has("MatXPair")) return "[matrix, matrix]";
  if (has("Vec3")) return "vec3";
  if (has("Vec6")) return "vec6";
  if (has("VecX")) return "array";
  if (has("Mat3")) return "3x3 rows";
  if (has("MatX")) return "rows";
  if (has("LieAlgebraId")) return "'so3'|'so4'|'sl2'";
  if (has("int")) return "integer";
  return "number";
}

std::string javascript_signature(const std::string& slot, const std::string& signature) {
  std::string args, types;
  for (const auto& [type, name] : slot_parameters(signature)) {
    args += (args.empty() ? "" : ", ") + name;
    types += (types.empty() ? "" : ", ") + name + ": " + javascript_type(type);
  }
  return "export function " + slot + "(" + args + ")  // (" + types + ") -> " +
         javascript_type(slot_result_type(signature));
}

std::string javascript_integrator_interface() {
  return "  export const midpoint = {                 // an exported object (or class) per integrator\n"
         "    name: \"midpoint\",\n"
         "    claims: { order: 2, casimir: true },    // keys: order symmetric casimir energy orthogonality spectrum\n"
         "                                            //   poisson noether equivariant bounded_energy symplectic\n"
         "    rigid_body_step(I, x, h) {              // I: vec3, x.Pi: vec3, x.O: 3x3 rows (arrays or typed arrays)\n"
         "      return { Pi, O };                     // or [Pi, O]; a NaN crosses as what it is\n"
         "    },\n"
         "  };\n"
         "  // manakov_step(A, x, h): x.M, x.O n x n; clebsch_step(I, [Q, P], h), manakov_clebsch_step(A, [Q, P], h);\n"
         "  // state: \"quaternion_wxyz omega\" (an engine's own state form), precision: \"float\" (a float engine)\n";
}

ValueStyle javascript_values() {
  ValueStyle v;
  v.nested_rows = true;
  v.vector_type = "array of {n} {s}s";
  v.any_vector_type = "array of {s}s";
  v.matrix_type = "{n} array of rows of {s}s";
  v.any_matrix_type = "array of rows of {s}s";
  v.double_name = v.mp50_name = v.rational_name = "number";
  return v;
}

}  // namespace

Language javascript_row() {
  Language js;
  js.id = "javascript";
  js.name = "JavaScript";
  js.extensions = {".mjs", ".js"};
  js.route = Route::Served;
  js.function_noun = "JavaScript function";
  js.version_label = "Node";
  js.scalars_note = " (JavaScript code is checked in double only)";
  js.values = javascript_values();
  // Double only (no 50-digit flows), but every check starts its own Node (no sessions) and loads the
  // module again: an engine's WebAssembly build takes a second or more to load and compile.
  js.timeout_factor = 2;
  js.function_names = javascript_function_names;
  js.code_only = javascript_code_only;
  js.definitions = javascript_definitions;
  js.slots_heading = "## JavaScript (Node): exported functions named after the slots (double only)";
  js.slots_fence = "js";
  js.comment = "// ";
  js.signature = javascript_signature;
  js.integrator_interface = javascript_integrator_interface;
  js.interpreter_variable = "GEOMECH_NODE";
  js.system_interpreter = "/usr/bin/node";
  js.interpreter = node_interpreter;
  // Started inside the sandbox by the grader's machine check: Node, and a WebAssembly memory under
  // the sandbox's memory limit (which an address-space limit once refused: V8 reserves gigabytes).
  js.start_probe = {"-e", "new WebAssembly.Memory({ initial: 1 })"};
  js.for_sandbox = node_in_sandbox;
  js.server = node_server;
  js.named_packages = javascript_named_packages;
  js.package_folder = "node_modules";
  return js;
}

}  // namespace gm::harness
