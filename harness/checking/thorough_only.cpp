#include "harness/checking/thorough_only.hpp"

#include "core/data_path.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gm::harness {

std::string default_thorough_only_path() { return suite_data_path("spec/thorough_only.json"); }

ThoroughOnlySelection load_thorough_only(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(
        path +
        ": no list of 50-digit runs left to --thorough (made by `geomech mutants --matrix --write-thorough-only`)");
  nlohmann::json j;
  ThoroughOnlySelection s;
  try {
    j = nlohmann::json::parse(in);
    if (j.at("format") != kThoroughOnlyFormat) throw std::runtime_error("unknown format");
    for (const auto& c : j.at("checks")) s.checks.insert(c.at("check").get<std::string>());
    if (j.contains("case_factor")) {
      s.case_factor = j.at("case_factor").get<double>();
      if (!(s.case_factor > 0 && s.case_factor <= 1)) throw std::runtime_error("case_factor must be in (0, 1]");
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a list of 50-digit runs left to --thorough (" + e.what() + ")");
  }
  std::ostringstream os;
  os << "in the kill matrix, every mutant these " << s.checks.size() << " runs kill is killed by a check that is kept ("
     << j.value("killed_by_kept", 0) << " of the " << j.value("killable", 0) << " mutants the matrix kills; `"
     << j.value("made_by", std::string("?")) << "`)";
  s.provenance = os.str();
  if (s.case_factor < 1) {
    std::ostringstream cf;
    cf << "at " << s.case_factor
       << " of each property's cases, the kill matrix's checks kill every mutant the suite kills ("
       << j.value("killable", 0) << "; `" << j.value("made_by", std::string("?")) << "`)";
    s.case_factor_note = cf.str();
  }
  return s;
}

}  // namespace gm::harness
