// The 50-digit runs an implementation behind the protocol (Python, untrusted C++) leaves to
// `geomech check --thorough` (item 4). They are chosen from the kill matrix of
// `geomech mutants --matrix` (mutation/kill_matrix.hpp, choose_thorough_only): the costly 50-digit
// runs of properties whose every kill another check kept also makes. Every statement is still
// checked (in double, and in rationals where it is exact); what is left out is repeating a costly
// one in 50 digits, whose added power is precision, which the slots' own 50-digit checks show.
// The list is a file, spec/thorough_only.json, made by that command with its provenance. The file
// also says the case factor the matrix ran at, which such an implementation's default check uses.
#pragma once

#include <set>
#include <string>

namespace gm::harness {

inline constexpr const char* kThoroughOnlyFormat = "geomech-thorough-only 1";

struct ThoroughOnlySelection {
  std::set<std::string> checks;  // "property/mp50"
  std::string provenance;        // one sentence: how many, why they may wait, the command
  // The case factor of the kill matrix the list was chosen from (`case_factor`; 1 when the file
  // has none). At that factor the matrix's checks kill every mutant the suite kills, so an
  // implementation behind the protocol, whose every call is a round trip, runs that share of each
  // property's cases by default, and --thorough runs them all.
  double case_factor = 1.0;
  std::string case_factor_note;  // one sentence: the factor, why it is enough, the command
};

// Throws std::runtime_error naming the file when it cannot be read or is not such a list.
ThoroughOnlySelection load_thorough_only(const std::string& path);
std::string default_thorough_only_path();

}  // namespace gm::harness
