// C++, the suite's own language: a file compiled with the suite (trusted) or into a protocol server
// that links nothing of the judge (untrusted). Its values are written as the suite's tests write
// them, its slots are the slots themselves.
#include "harness/languages/rows.hpp"

#include <regex>
#include <set>

namespace gm::harness {

namespace {

// `name(` preceded by a return type: static members and free functions alike.
std::vector<std::string> cpp_function_names(const std::string& source) {
  static const std::regex decl(R"((?:static|inline|constexpr|auto|void|T|double|int|float|>)\s+([A-Za-z_]\w*)\s*\()");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), decl); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  return {names.begin(), names.end()};
}

// Comments (// and /* */) and string literals blanked, newlines kept.
std::string cpp_code_only(const std::string& text) { return c_like_code_only(text, "\"'", 0); }

// A function with a body: `name(...) ... {`.
std::vector<Definition> cpp_definitions(const std::string& code) {
  static const std::regex def(R"((^|[\s>*&])([A-Za-z_]\w*)[ \t]*\([^;{}]*\)[^;{}]*\{)");
  std::vector<Definition> out;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), def); it != std::sregex_iterator(); ++it)
    out.push_back({static_cast<std::size_t>(it->position(2)), (*it)[2].str()});
  return out;
}

std::string cpp_signature(const std::string& slot, const std::string& signature) { return slot + "  " + signature; }

std::string cpp_integrator_interface() {
  return "  struct Midpoint {\n"
         "    static constexpr const char* name = \"midpoint\";\n"
         "    static constexpr gm::student::Claims claims{.order = 2, .casimir = true};\n"
         "    template <class T>\n"
         "    static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h);\n"
         "    // also: manakov_step(const MatX<T>& A, const ManakovState<T>& x, const T& h) (x.M, x.O),\n"
         "    //       clebsch_step(I, const Vec3Pair<T>& QP, h), manakov_clebsch_step(A, const MatXPair<T>& QP, h)\n"
         "  };\n"
         "  GEOMECH_STUDENT(MyRigidBody, Midpoint);   // the slots' type, then the integrators\n"
         "  // claims: order symmetric casimir energy orthogonality spectrum poisson noether equivariant\n"
         "  //         bounded_energy symplectic\n";
}

}  // namespace

Language cpp_row() {
  Language cpp;
  cpp.id = "c++";
  cpp.name = "C++";
  cpp.extensions = {".cpp", ".cc"};
  cpp.route = Route::Compiled;
  cpp.marker = "GEOMECH_STUDENT(";
  cpp.files_beside = true;
  cpp.function_names = cpp_function_names;
  cpp.code_only = cpp_code_only;
  cpp.definitions = cpp_definitions;
  cpp.signature = cpp_signature;
  cpp.integrator_interface = cpp_integrator_interface;
  return cpp;  // values: ValueStyle's defaults, the suite's own
}

}  // namespace gm::harness
