#include "harness/program/student_parts.hpp"

#include "harness/isolation/process.hpp"
#include "harness/program/cli.hpp"
#include "harness/remote/slot_names.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace gm::student {

namespace {

// Reads the build notes (JSON written by geomech check) into notes; false, having said why, when it cannot.
bool read_build_notes(const std::string& notes_file, nlohmann::json& notes) {
  std::ifstream f(notes_file);
  if (!f) {
    std::cerr << "geomech: cannot read the build notes " << notes_file << "\n";
    return false;
  }
  try {
    notes = nlohmann::json::parse(f);
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << notes_file << ": " << e.what() << "\n";
    return false;
  }
  return true;
}

// --states-its-precision: 0 when the program fills no slot and every integrator states a precision, 1 otherwise.
int states_its_precision() {
  // The registrations of this program (a first look's double slots): its slots and its claims.
  const Registered& r = registered();
  bool any_slot = false;
  if (r.d)
    for (const auto& slot : subject_slots()) any_slot = any_slot || r.d->provides(slot.name);
  const std::vector<IntegratorClaims> none;
  const std::vector<IntegratorClaims>& claims = r.d_info ? r.d_info->claims : none;
  bool all_state = !claims.empty();
  for (const auto& c : claims)
    all_state = all_state && (c.precision == "float" || c.precision == "single" || c.precision == "double");
  return !any_slot && all_state ? 0 : 1;
}

// --describe: prints the slots and integrators found, per scalar, and the notes and warnings.
void describe_subject(const SubjectSet& s, const harness::SubjectInfo& info) {
  std::cout << "implementation: " << s.name << " (" << s.description << ")\n";
  auto show = [&](const auto* sub, const char* scalar) {
    std::cout << scalar << ":";
    if (!sub) {
      auto it = info.scalar_unavailable.find(scalar);
      std::cout << " nothing (" << (it == info.scalar_unavailable.end() ? "not registered" : it->second) << ")\n";
      return;
    }
    for (const auto& slot : subject_slots())
      if (sub->provides(slot.name)) std::cout << " " << slot.name;
    if constexpr (!is_exact_v<typename std::remove_pointer_t<decltype(sub)>::Scalar>)
      for (const auto& i : sub->integrators)
        std::cout << " integrator:" << i.name << (i.rigid_body_step ? "[rigid_body_step]" : "")
                  << (i.manakov_step ? "[manakov_step]" : "") << (i.clebsch_step ? "[clebsch_step]" : "")
                  << (i.manakov_clebsch_step ? "[manakov_clebsch_step]" : "");
    std::cout << "\n";
  };
  show(s.d.get(), "double");
  show(s.mp.get(), "mp50");
  show(s.q.get(), "exact");
  for (const auto& [scalar, slots] : info.slot_notes)
    for (const auto& [slot, why] : slots) std::cout << "note: " << scalar << " " << slot << ": " << why << "\n";
  for (const auto& w : info.warnings) std::cout << "warning: " << w << "\n";
  for (const auto& u : info.unchecked) std::cout << "unchecked: " << u << "\n";
}

}  // namespace

int student_main(int argc, char** argv) {
  if (!harness::die_with_parent_when_asked()) return 2;  // a class run's check, whose run has ended
  CLI::App app{"check a student implementation against the geomech properties"};
  harness::CheckCliOptions o;
  harness::add_check_options(app, o);
  std::string name, source, prefix, notes_file;
  bool describe = false;
  app.add_option("--name", name, "name of the implementation in the report (default: its registration)");
  app.add_option("--source", source, "the source file, shown in the report");
  app.add_option("--reproduce-prefix", prefix, "command printed to replay a failure");
  app.add_option("--build-notes", notes_file, "what the build found (JSON written by geomech check)");
  app.add_flag("--describe", describe, "print the slots and integrators found, per scalar, and exit");
  bool one_precision = false;
  app.add_flag("--states-its-precision", one_precision,
               "exit 0 when the file fills no slot and every integrator states a precision (float, single or "
               "double), so that its other scalars would check nothing; 1 otherwise");
  CLI11_PARSE(app, argc, argv);

  nlohmann::json notes;
  if (!notes_file.empty() && !read_build_notes(notes_file, notes)) return 2;
  if (one_precision) return states_its_precision();
  {
    const Registered& r = registered();
    if (!r.d && !r.mp && !r.q) {
      std::cerr << "geomech: " << (source.empty() ? std::string("the program") : source)
                << " registers no implementation: write GEOMECH_STUDENT(YourStruct, YourIntegrators...) at namespace "
                   "scope, after the struct (see docs/STUDENTS.md)\n";
      return 2;
    }
  }
  harness::SubjectInfo info;
  info.source = source;
  if (prefix.empty()) {
    prefix = std::filesystem::path(argv[0]).string();
  }
  info.reproduce_prefix = prefix;
  const SubjectSet s = assemble(name, info, notes);
  if (!source.empty()) {  // functions named like a slot but not one: say which slot they mean
    std::ifstream in(source);
    std::ostringstream text;
    text << in.rdbuf();
    for (const auto& advice : harness::slot_name_advice(info.language->function_names(text.str())))
      info.warnings.push_back(advice);
  }

  if (describe) {
    describe_subject(s, info);
    return 0;
  }
  try {
    return harness::run_check_cli(s, info, o);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace gm::student
