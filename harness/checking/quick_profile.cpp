#include "harness/checking/quick_profile.hpp"

#include "core/data_path.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gm::harness {

std::string default_quick_profile_path() { return suite_data_path("spec/quick_profile.json"); }

QuickSelection load_quick_profile(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(path + ": no quick profile (made by `geomech mutants --matrix --write-quick-profile`)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    if (j.at("format") != kQuickProfileFormat) throw std::runtime_error("unknown format");
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a quick profile (" + e.what() + ")");
  }
  QuickSelection s;
  for (const auto& c : j.at("checks")) s.checks.insert(c.get<std::string>());
  std::ostringstream os;
  os << s.checks.size() << " of " << j.value("checks_all", 0)
     << " checks chosen from the kill matrix: together they kill " << j.value("killed", 0) << " of the "
     << j.value("killable", 0) << " mutants the whole suite kills (" << j.value("mutants", 0)
     << " mutants of the reference; `" << j.value("made_by", std::string("?")) << "`)";
  s.provenance = os.str();
  return s;
}

}  // namespace gm::harness
