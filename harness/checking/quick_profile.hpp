// `geomech check --quick`: the checks of the quick profile, the small set chosen from
// the kill matrix of `geomech mutants --matrix` (mutation/kill_matrix.hpp) that still kills every
// mutant the whole suite kills. The profile is a file, spec/quick_profile.json, made by that
// command and committed with its provenance.
#pragma once

#include <set>
#include <string>

namespace gm::harness {

inline constexpr const char* kQuickProfileFormat = "geomech-quick-profile 1";

struct QuickSelection {
  std::set<std::string> checks;  // "property/scalar"
  std::string provenance;        // one sentence: how many checks, what they kill, the command
};

// Throws std::runtime_error naming the file when it cannot be read or is not a profile.
QuickSelection load_quick_profile(const std::string& path);
std::string default_quick_profile_path();

}  // namespace gm::harness
