#include "mutation/kill_matrix.hpp"

#include "harness/checking/quick_profile.hpp"
#include "harness/checking/thorough_only.hpp"

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

// The command that makes a file from the matrix, with the run's case factor and seed (provenance).
std::string made_by(const MutantsRun& run, const char* write_option) {
  return "geomech mutants --matrix --case-factor " + secs(run.options.case_factor) + " --seed " +
         std::to_string(run.options.seed) + " " + write_option + " FILE";
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
  std::stable_sort(rows.begin(), rows.end(),
                   [](const MatrixRow& a, const MatrixRow& b) { return a.killed > b.killed; });
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
     << q.killable << " mutants the whole matrix kills (" << q.mutants
     << " not equivalent); their mean cost per mutant " << secs(q.seconds) << " s against " << secs(q.seconds_all)
     << " s for every check";
  if (q.killed_by_run > 0)
    os << "; " << q.killed_by_run << " more killed only by a crash or a timeout of their whole run, which no single "
       << "check's cell records";
  os << "\n";
  return os.str();
}

json quick_profile_json(const QuickProfile& q, const MutantsRun& run) {
  json j;
  j["format"] = harness::kQuickProfileFormat;
  j["made_by"] = made_by(run, "--write-quick-profile");
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

ThoroughOnly choose_thorough_only(const MutantsRun& run, double min_seconds) {
  const Cells c = cells_of(run);
  ThoroughOnly t;
  t.min_seconds = min_seconds;
  auto is_50_digit = [](const std::string& check) {
    static const std::string tail = "/mp50";
    return check.size() > tail.size() && check.compare(check.size() - tail.size(), tail.size(), tail) == 0;
  };
  std::vector<std::string> candidates;
  for (const auto& [check, cost] : c.cost) {
    if (!is_50_digit(check)) continue;
    t.seconds_50_digit += mean_cost(c, check);
    if (mean_cost(c, check) >= min_seconds) candidates.push_back(check);
  }
  t.candidates = static_cast<int>(candidates.size());
  // Most costly first, so that of two checks killing the same mutants the cheaper one is kept.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](const std::string& a, const std::string& b) { return mean_cost(c, a) > mean_cost(c, b); });
  std::map<std::size_t, int> killers;  // mutant -> checks kept that kill it
  for (const auto& [check, ks] : c.kills)
    for (std::size_t m : ks) ++killers[m];
  t.killable = static_cast<int>(killers.size());
  for (const auto& check : candidates) {
    const auto it = c.kills.find(check);
    const bool all_killed_elsewhere = it == c.kills.end() || std::all_of(it->second.begin(), it->second.end(),
                                                                         [&](std::size_t m) { return killers[m] > 1; });
    if (!all_killed_elsewhere) continue;
    if (it != c.kills.end())
      for (std::size_t m : it->second) --killers[m];
    t.checks.push_back({check, mean_cost(c, check), it == c.kills.end() ? 0 : static_cast<int>(it->second.size())});
    t.seconds_left_out += mean_cost(c, check);
  }
  for (const auto& [m, n] : killers) t.killed_by_kept += n > 0;
  return t;
}

std::string thorough_only_summary(const ThoroughOnly& t) {
  std::ostringstream os;
  os << "left to --thorough for an implementation behind the protocol: " << t.checks.size() << " of the "
     << t.candidates << " 50-digit checks costing " << secs(t.min_seconds) << " s or more per mutant ("
     << secs(t.seconds_left_out) << " s of the " << secs(t.seconds_50_digit)
     << " s all 50-digit checks cost); the checks kept kill " << t.killed_by_kept << " of the " << t.killable
     << " mutants the matrix kills\n";
  return os.str();
}

json thorough_only_json(const ThoroughOnly& t, const MutantsRun& run) {
  json j;
  j["format"] = harness::kThoroughOnlyFormat;
  j["made_by"] = made_by(run, "--write-thorough-only");
  j["rule"] =
      "the 50-digit checks costing at least min_seconds per mutant in the matrix, most costly first, each left "
      "out when every mutant it kills is still killed by a check that is kept";
  j["min_seconds"] = t.min_seconds;
  // The factor the matrix ran at: an implementation behind the protocol runs that share of each
  // property's cases by default (harness/checking/thorough_only.hpp).
  j["case_factor"] = run.options.case_factor;
  j["candidates"] = t.candidates;
  j["killable"] = t.killable;
  j["killed_by_kept"] = t.killed_by_kept;
  j["seconds_left_out"] = t.seconds_left_out;
  j["seconds_50_digit"] = t.seconds_50_digit;
  j["checks"] = json::array();
  for (const auto& c : t.checks)
    j["checks"].push_back({{"check", c.check}, {"seconds", c.seconds}, {"killed", c.killed}});
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
     << "Every property in every scalar on every mutant it applies to, without stopping at the first kill "
        "(`--matrix`). "
        "killed: mutants it kills (equivalent ones left out); unique: killed by it and by no other check; cost: mean "
        "seconds per mutant it ran on. A check that kills nothing unique may still be the only cheap one to kill "
        "something.\n\n"
     << "Each mutant's matrix stops starting new cells after 20 s (an integrator's mutant applies to every "
        "integrator property and their long runs): "
     << skipped << " cells of " << mutants_skipping << " mutants were not measured.\n\n"
     << "| check | ran on | killed | unique | cost (s) |\n|---|---|---|---|---|\n";
  for (const auto& r : rows)
    os << "| " << r.check << " | " << r.ran << " | " << r.killed << " | " << r.unique << " | " << secs(r.seconds)
       << " |\n";
  os << "\n## Quick profile\n\n"
     << quick_profile_summary(q) << "\n"
     << "Chosen greedily (most new kills per second of cost first); `geomech check --quick` runs these checks "
        "(spec/quick_profile.json):\n\n| # | check | mutants killed so far |\n|---|---|---|\n";
  for (std::size_t i = 0; i < q.checks.size(); ++i)
    os << "| " << i + 1 << " | " << q.checks[i] << " | " << q.cumulative[i] << " |\n";
  const ThoroughOnly t = choose_thorough_only(run);
  os << "\n## 50-digit runs left to --thorough\n\n"
     << thorough_only_summary(t) << "\n"
     << "An implementation behind the protocol (Python, untrusted C++) skips these unless checked with --thorough "
        "(spec/thorough_only.json); every mutant each one kills is killed by a check that is kept:\n\n"
     << "| check | killed | cost (s) |\n|---|---|---|\n";
  for (const auto& c : t.checks) os << "| " << c.check << " | " << c.killed << " | " << secs(c.seconds) << " |\n";
  return os.str();
}

}  // namespace gm::mutation
