// The kill matrix of `geomech mutants --matrix`: which check (property and scalar)
// kills which mutant of the full reference, and what it costs; and the quick profile chosen from
// it, the small set of checks that still kills every mutant the full suite kills, which
// `geomech check --quick` runs (spec/quick_profile.json).
#pragma once

#include "mutation/runner.hpp"

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace gm::mutation {

struct MatrixRow {
  std::string check;   // "property/scalar"
  int ran = 0;         // mutants it ran on (the slot it needs was mutated, or an integrator's step)
  int killed = 0;      // of those, killed (not counting equivalent mutants)
  int unique = 0;      // killed by this check and no other
  double seconds = 0;  // mean seconds per mutant it ran on
};

// Rows for every check that ran on some mutant, the ones that kill most first.
std::vector<MatrixRow> kill_matrix(const MutantsRun& run);

struct QuickProfile {
  std::vector<std::string> checks;  // "property/scalar", in the order chosen
  std::vector<int> cumulative;      // mutants killed by the first i + 1 checks
  int mutants = 0;                  // not equivalent in the full reference
  int killable = 0;                 // killed by some check of the matrix
  int killed = 0;                   // killed by the profile (= killable, by construction)
  int killed_by_run = 0;            // killed only by a crash or a timeout of their whole run (no cell)
  double seconds = 0;               // the profile's mean cost per mutant, summed over its checks
  std::size_t checks_all = 0;       // every check of the matrix
  double seconds_all = 0;           // their mean cost, summed
};

// Greedy set cover: repeatedly the check that kills the most mutants not yet killed per second
// of its mean cost, until every killable mutant is killed.
QuickProfile choose_quick_profile(const MutantsRun& run);
std::string quick_profile_summary(const QuickProfile& q);
nlohmann::json quick_profile_json(const QuickProfile& q, const MutantsRun& run);
std::string matrix_markdown(const MutantsRun& run);

// The 50-digit runs an implementation behind the protocol leaves to `geomech check --thorough`
// (spec/thorough_only.json, harness/checking/thorough_only.hpp). An interpreted implementation computes in
// 50 digits a hundred times slower than compiled code, and a few 50-digit runs (long flows, the
// variational principles) are nearly all of its check's time. Chosen here so that no mutant the
// matrix kills is lost: the 50-digit checks costing at least `min_seconds` per mutant, most costly
// first, each left out when every mutant it kills is still killed by a check that is kept.
struct ThoroughOnly {
  struct Check {
    std::string check;   // "property/mp50"
    double seconds = 0;  // mean cost per mutant in the matrix
    int killed = 0;      // mutants it kills, every one killed by a kept check too
  };
  std::vector<Check> checks;
  double min_seconds = 0;
  int candidates = 0;           // 50-digit checks costing at least min_seconds
  int killable = 0;             // killed by some check of the matrix
  int killed_by_kept = 0;       // killed by the checks kept (= killable, by construction)
  double seconds_left_out = 0;  // the checks left out: their mean costs, summed
  double seconds_50_digit = 0;  // every 50-digit check's mean cost, summed
};
ThoroughOnly choose_thorough_only(const MutantsRun& run, double min_seconds = 0.05);
std::string thorough_only_summary(const ThoroughOnly& t);
nlohmann::json thorough_only_json(const ThoroughOnly& t, const MutantsRun& run);

}  // namespace gm::mutation
