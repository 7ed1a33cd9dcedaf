#include "mutation/kill_matrix.hpp"

#include "harness/quick_profile.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace gm::mutation {

using nlohmann::json;

namespace {

// The mutants that count (not equivalent in the full reference) and, per check, which of them it
// kills and what it cost.
struct Cells {
  std::vector<std::string> mutants;
  std::map<std::string, std::set<std::size_t>> kills;  // check -> mutant indices
  std::map<std::string, std::pair<int, double>> cost;  // check -> (runs, seconds summed)
};

Cells cells_of(const MutantsRun& run) {
  Cells c;
  for (const auto& r : run.results) {
    if (r.equivalent_in(false) || !r.full.ran) continue;
    const std::size_t i = c.mutants.size();
    c.mutants.push_back(r.name);
    for (const auto& [check, cell] : r.full.cells) {
      auto& [runs, secs] = c.cost[check];
      ++runs;
      secs += cell.second;
      if (cell.first) c.kills[check].insert(i);
    }
  }
  return c;
}

double mean_cost(const Cells& c, const std::string& check) {
  const auto it = c.cost.find(check);
  return it == c.cost.end() || it->second.first == 0 ? 0 : it->second.second / it->second.first;
}

std::string secs(double s) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(s < 0.1 ? 4 : 2) << s;
  return os.str();
}

}  // namespace

std::vector<MatrixRow> kill_matrix(const MutantsRun& run) {
  const Cells c = cells_of(run);
  std::map<std::size_t, int> killers;  // mutant -> how many checks kill it
  for (const auto& [check, ks] : c.kills)
    for (std::size_t m : ks) ++killers[m];
  std::vector<MatrixRow> rows;
  for (const auto& [check, cost] : c.cost) {
    MatrixRow r;
    r.check = check;
    r.ran = cost.first;
    r.seconds = mean_cost(c, check);
    if (auto it = c.kills.find(check); it != c.kills.end()) {
      r.killed = static_cast<int>(it->second.size());
      for (std::size_t m : it->second) r.unique += killers[m] == 1;
    }
    rows.push_back(r);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const MatrixRow& a, const MatrixRow& b) { return a.killed > b.killed; });
  return rows;
}

QuickProfile choose_quick_profile(const MutantsRun& run) {
  const Cells c = cells_of(run);
  QuickProfile q;
  q.mutants = static_cast<int>(c.mutants.size());
  std::set<std::size_t> left;
  for (const auto& [check, ks] : c.kills) left.insert(ks.begin(), ks.end());
  q.killable = static_cast<int>(left.size());
  for (const auto& r : run.results)
    if (!r.equivalent_in(false) && r.full.ran && r.full.killed &&
        std::none_of(r.full.cells.begin(), r.full.cells.end(), [](const auto& c) { return c.second.first; }))
      ++q.killed_by_run;
  q.checks_all = c.cost.size();
  for (const auto& [check, cost] : c.cost) q.seconds_all += mean_cost(c, check);
  while (!left.empty()) {
    std::string best;
    double best_rate = -1;
    std::size_t best_new = 0;
    for (const auto& [check, ks] : c.kills) {
      std::size_t fresh = 0;
      for (std::size_t m : ks) fresh += left.count(m);
      if (fresh == 0) continue;
      const double rate = static_cast<double>(fresh) / (mean_cost(c, check) + 1e-3);
      if (rate > best_rate || (rate == best_rate && fresh > best_new)) best = check, best_rate = rate, best_new = fresh;
    }
    for (std::size_t m : c.kills.at(best)) left.erase(m);
    q.checks.push_back(best);
    q.killed += static_cast<int>(best_new);
    q.cumulative.push_back(q.killed);
    q.seconds += mean_cost(c, best);
  }
  return q;
}

std::string quick_profile_summary(const QuickProfile& q) {
  std::ostringstream os;
  os << "quick profile: " << q.checks.size() << " of " << q.checks_all << " checks kill " << q.killed << " of the "
     << q.killable << " mutants the whole matrix kills (" << q.mutants << " not equivalent); their mean cost per mutant "
     << secs(q.seconds) << " s against " << secs(q.seconds_all) << " s for every check";
  if (q.killed_by_run > 0)
    os << "; " << q.killed_by_run << " more killed only by a crash or a timeout of their whole run, which no single "
       << "check's cell records";
  os << "\n";
  return os.str();
}

json quick_profile_json(const QuickProfile& q, const MutantsRun& run) {
  json j;
  j["format"] = harness::kQuickProfileFormat;
  j["made_by"] = "geomech mutants --matrix --case-factor " + secs(run.options.case_factor) + " --seed " +
                 std::to_string(run.options.seed) + " --write-quick-profile FILE";
  j["mutants"] = q.mutants;
  j["killable"] = q.killable;
  j["killed"] = q.killed;
  j["killed_by_run"] = q.killed_by_run;
  j["checks_all"] = q.checks_all;
  j["seconds_profile"] = q.seconds;
  j["seconds_all"] = q.seconds_all;
  j["checks"] = q.checks;
  j["cumulative_kills"] = q.cumulative;
  return j;
}

std::string matrix_markdown(const MutantsRun& run) {
  std::ostringstream os;
  const QuickProfile q = choose_quick_profile(run);
  const auto rows = kill_matrix(run);
  int skipped = 0, mutants_skipping = 0;
  for (const auto& r : run.results)
    if (r.full.matrix_skipped > 0) skipped += r.full.matrix_skipped, ++mutants_skipping;
  os << "## Kill matrix (full reference)\n\n"
     << "Every property in every scalar on every mutant it applies to, without stopping at the first kill (`--matrix`). "
        "killed: mutants it kills (equivalent ones left out); unique: killed by it and by no other check; cost: mean "
        "seconds per mutant it ran on. A check that kills nothing unique may still be the only cheap one to kill "
        "something.\n\n"
     << "Each mutant's matrix stops starting new cells after 20 s (an integrator's mutant applies to every "
        "integrator property and their long runs): "
     << skipped << " cells of " << mutants_skipping << " mutants were not measured.\n\n"
     << "| check | ran on | killed | unique | cost (s) |\n|---|---|---|---|---|\n";
  for (const auto& r : rows)
    os << "| " << r.check << " | " << r.ran << " | " << r.killed << " | " << r.unique << " | " << secs(r.seconds) << " |\n";
  os << "\n## Quick profile\n\n" << quick_profile_summary(q) << "\n"
     << "Chosen greedily (most new kills per second of cost first); `geomech check --quick` runs these checks "
        "(spec/quick_profile.json):\n\n| # | check | mutants killed so far |\n|---|---|---|\n";
  for (std::size_t i = 0; i < q.checks.size(); ++i)
    os << "| " << i + 1 << " | " << q.checks[i] << " | " << q.cumulative[i] << " |\n";
  return os.str();
}

}  // namespace gm::mutation
