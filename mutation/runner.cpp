#include "mutation/runner.hpp"
#include "mutation/kill_matrix.hpp"
#include "mutation/served_mutant.hpp"

#include "harness/isolation/isolate.hpp"
#include "harness/reports/report.hpp"
#include "impl/reference_subject.hpp"
#include "mutation/catalogue.hpp"
#include "properties/runner.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

#ifndef GM_SOURCE_DIR
#define GM_SOURCE_DIR "."
#endif

namespace gm::mutation {

using nlohmann::json;

std::string default_equivalent_path() { return std::string(GM_SOURCE_DIR) + "/spec/equivalent_mutants.json"; }

std::map<std::string, Equivalence> load_equivalent(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  json j = json::parse(in);
  std::map<std::string, Equivalence> out;
  for (const auto& e : j.at("equivalent")) {
    const std::string name = e.at("mutant").get<std::string>();
    const std::string why = e.at("argument").get<std::string>();
    if (why.empty()) throw std::runtime_error(path + ": mutant '" + name + "' has no argument");
    out[name] = Equivalence{why, e.value("alone_only", false)};
  }
  return out;
}

namespace {

std::string first_line(const std::string& s) {
  const auto n = s.find('\n');
  return n == std::string::npos ? s : s.substr(0, n);
}

// The properties that apply to a mutant, in the order they are tried.
std::vector<const Property*> candidates(const MutantDef& m, const std::set<std::string>& excluded) {
  std::vector<const Property*> out;
  for (const auto& p : properties()) {
    if (excluded.count(p.id)) continue;
    bool use = false;
    if (m.op_class == "handwritten") {
      use = true;
    } else if (!m.integrator.empty()) {
      use = p.scope == Scope::Integrator && (p.step == m.step || p.step == StepKind::None ||
                                             (m.step == StepKind::RigidBody && p.step == StepKind::RigidBodyMatrix));
    } else {
      use = std::find(p.needs.begin(), p.needs.end(), m.slot) != p.needs.end();
    }
    if (use) out.push_back(&p);
  }
  if (m.op_class == "handwritten")  // the properties naming it as their negative control first
    std::stable_partition(out.begin(), out.end(), [&](const Property* p) {
      return std::find(p->negative_controls.begin(), p->negative_controls.end(), m.name) != p->negative_controls.end();
    });
  return out;
}

ModeResult run_mode(const SubjectSet& s, const std::vector<const Property*>& props, const MutantsOptions& o) {
  ModeResult r;
  r.ran = true;
  RunOptions ro;
  ro.seed = o.seed;
  ro.case_factor = o.case_factor;
  ro.honour_rc_params = false;
  if (o.matrix) {
    // The matrix asks whether each check kills, not for the smallest counterexample: no shrinking,
    // and no new case after a second (at least one case runs), so that a mutant that makes a check
    // slow costs a bounded time there.
    ro.shrink = false;
    ro.case_budget_seconds = 1.0;
  }
  std::set<std::string> ran;
  // The matrix of one mutant stops starting new cells after this long: an integrator's mutant
  // applies to every integrator property, whose long runs would otherwise take minutes each; the
  // cells left out are counted (matrix_skipped) and the quick profile uses the measured ones.
  const auto mode_start = std::chrono::steady_clock::now();
  constexpr double kMatrixBudgetSeconds = 20;
  for (ScalarKind k : {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact}) {
    for (const Property* p : props) {
      if (!p->runs_in(k)) continue;
      if (o.matrix &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - mode_start).count() > kMatrixBudgetSeconds) {
        ++r.matrix_skipped;
        continue;
      }
      std::vector<Verdict> vs;
      const std::string cell = p->id + "/" + scalar_name(k);
      const auto started = std::chrono::steady_clock::now();
      auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
      try {
        vs = run_property(*p, s, k, ro);
      } catch (const std::exception& e) {
        if (!r.killed) r.killed_by = p->id + " [" + scalar_name(k) + "] threw: " + first_line(e.what());
        r.killed = true;
        if (o.matrix) r.cells[cell] = {true, seconds()};
        if (!o.verbose && !o.matrix) return r;
        continue;
      }
      if (o.matrix) {
        bool ran_here = false, killed_here = false;
        for (const Verdict& v : vs) {
          if (v.outcome == Outcome::NotProvided) continue;
          if (v.outcome == Outcome::Error && v.message.find("without listing it in its needs") != std::string::npos)
            continue;
          ran_here = true;
          killed_here = killed_here || v.outcome != Outcome::Pass;
        }
        if (ran_here) r.cells[cell] = {killed_here, seconds()};
      }
      for (const Verdict& v : vs) {
        std::string where = p->id + " [" + v.scalar + (v.integrator.empty() ? "" : " " + v.integrator) + "]";
        if (o.verbose)
          r.log.push_back(std::string(outcome_name(v.outcome)) + "  " + where + "  " + first_line(v.message));
        if (v.outcome == Outcome::NotProvided) continue;
        if (v.outcome == Outcome::Error && v.message.find("without listing it in its needs") != std::string::npos) {
          r.undeclared.push_back(p->id);  // a defect of the property, not a kill
          continue;
        }
        if (ran.insert(p->id).second) r.properties.push_back(p->id);
        if (v.outcome == Outcome::Pass) continue;
        if (!r.killed) {
          r.killed = true;
          r.killed_by = where + " " + outcome_name(v.outcome) + ": " + first_line(v.message);
        }
        if (!o.verbose && !o.matrix) return r;
      }
    }
  }
  return r;
}

json mode_json(const ModeResult& m) {
  json cells = json::object();
  for (const auto& [k, v] : m.cells) cells[k] = {v.first, v.second};
  return json{{"ran", m.ran},
              {"killed", m.killed},
              {"killed_by", m.killed_by},
              {"properties", m.properties},
              {"undeclared", m.undeclared},
              {"log", m.log},
              {"error", m.error},
              {"cells", cells},
              {"matrix_skipped", m.matrix_skipped}};
}
ModeResult mode_from(const json& j) {
  ModeResult m;
  m.ran = j.value("ran", false);
  m.killed = j.value("killed", false);
  m.killed_by = j.value("killed_by", "");
  m.properties = j.value("properties", std::vector<std::string>{});
  m.undeclared = j.value("undeclared", std::vector<std::string>{});
  m.log = j.value("log", std::vector<std::string>{});
  m.error = j.value("error", "");
  m.matrix_skipped = j.value("matrix_skipped", 0);
  if (j.contains("cells"))
    for (const auto& [k, v] : j.at("cells").items()) m.cells[k] = {v.at(0).get<bool>(), v.at(1).get<double>()};
  return m;
}

}  // namespace

MutantsRun run_mutants(const MutantsOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  MutantsRun run;
  run.options = o;
  run.equivalent = load_equivalent(o.equivalent_file.empty() ? default_equivalent_path() : o.equivalent_file);
  const SubjectSet& ref = reference_subject();
  std::vector<MutantDef> all = all_mutants(ref);
  {
    std::set<std::string> names;
    for (const auto& m : all) names.insert(m.name);
    for (const auto& [n, why] : run.equivalent)
      if (!names.count(n)) run.unknown_equivalents.push_back(n);
  }
  std::vector<MutantDef> chosen;
  for (auto& m : all)
    if ((o.slot.empty() || m.slot == o.slot) && (o.mutant.empty() || m.name == o.mutant))
      chosen.push_back(std::move(m));

  harness::IsolationOptions iso;
  iso.jobs = std::max(1, o.jobs);
  iso.timeout_seconds = o.timeout_seconds;

  // Baseline: a property that fails on the reference itself with these options cannot measure
  // anything; it is left out and reported.
  std::set<std::string> needed;
  for (const auto& m : chosen)
    for (const Property* p : candidates(m, {})) needed.insert(p->id);
  std::vector<std::string> base_ids(needed.begin(), needed.end());
  std::vector<std::function<std::string()>> base_tasks;
  for (const auto& id : base_ids)
    base_tasks.push_back([id, &ref, o]() -> std::string {
      MutantsOptions q = o;
      q.verbose = false;
      ModeResult r = run_mode(ref, {find_property(id)}, q);
      return r.killed ? r.killed_by : "";
    });
  const auto base_results = harness::run_isolated(base_tasks, iso);
  std::set<std::string> excluded;
  for (std::size_t i = 0; i < base_ids.size(); ++i) {
    const auto& tr = base_results[i];
    if (tr.status != harness::TaskResult::Status::Ok || !tr.payload.empty()) {
      excluded.insert(base_ids[i]);
      run.baseline_failures.push_back(base_ids[i] + ": " +
                                      (tr.status == harness::TaskResult::Status::Ok ? tr.payload : tr.detail));
    }
  }

  std::vector<std::function<std::string()>> tasks;
  for (const auto& m : chosen)
    tasks.push_back([&m, &ref, &excluded, o]() -> std::string {
      const auto props = candidates(m, excluded);
      json j;
      ModeResult full, alone;
      try {
        full = run_mode(m.full(ref), props, o);
      } catch (const std::exception& e) {
        full.ran = true;
        full.error = e.what();
      }
      if (o.alone && m.alone) {
        try {
          MutantsOptions alone_options = o;
          alone_options.matrix = false;  // the matrix is of the full reference
          alone = run_mode(m.alone(ref), props, alone_options);
        } catch (const std::exception& e) {
          alone.ran = true;
          alone.error = e.what();
        }
      }
      j["full"] = mode_json(full);
      j["alone"] = mode_json(alone);
      if (o.through_protocol) {
        ModeResult served;
        try {
          MutantsOptions served_options = o;
          served_options.matrix = false;
          served = run_mode(served_mutant(o.program, m.name), props, served_options);
        } catch (const std::exception& e) {
          served.ran = true;
          served.error = e.what();
        }
        j["protocol"] = mode_json(served);
      }
      return j.dump();
    });
  std::size_t done = 0;
  iso.on_finished = [&](std::size_t, const harness::TaskResult&) {
    ++done;
    if (!o.verbose && (done % 25 == 0 || done == tasks.size()))
      std::cerr << "geomech mutants: " << done << "/" << tasks.size() << " mutants\n";
  };
  const auto results = harness::run_isolated(tasks, iso);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const MutantDef& m = chosen[i];
    MutantResult r;
    r.name = m.name;
    r.slot = m.slot.empty() ? "(handwritten)" : m.slot;
    r.op = m.op;
    r.op_class = m.op_class;
    r.description = m.description;
    r.integrator = m.integrator;
    r.seconds = results[i].seconds;
    if (auto it = run.equivalent.find(m.name); it != run.equivalent.end()) {
      r.equivalent = true;
      r.equivalent_alone_only = it->second.alone_only;
      r.equivalence_argument = it->second.argument;
    }
    std::set<std::string> specs;
    for (const Property* p : candidates(m, excluded))
      if (m.op_class != "handwritten" ||
          std::find(p->negative_controls.begin(), p->negative_controls.end(), m.name) != p->negative_controls.end())
        specs.insert(p->spec);
    r.spec_entries.assign(specs.begin(), specs.end());
    const auto& tr = results[i];
    if (tr.status == harness::TaskResult::Status::Ok) {
      const json j = json::parse(tr.payload);
      r.full = mode_from(j.at("full"));
      r.alone = mode_from(j.at("alone"));
      if (j.contains("protocol")) r.protocol = mode_from(j.at("protocol"));
    } else {
      // A crash or a hang of the whole mutant run is a detection (the suite would report it).
      r.full.ran = true;
      r.full.killed = true;
      r.full.killed_by = "the run " +
                         std::string(tr.status == harness::TaskResult::Status::TimedOut ? "timed out" : "crashed") +
                         ": " + tr.detail;
      r.alone = r.full;
      if (!m.alone) r.alone = ModeResult{};
      if (o.through_protocol) r.protocol = r.full;
    }
    run.results.push_back(std::move(r));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

namespace {

// The tally of one mode of each mutant (full, alone or through the protocol), among those of `slot`
// and `spec` (empty: all); `alone` says which equivalence applies.
template <class Mode>
Tally tally_of(const MutantsRun& run, Mode mode, bool alone, const std::string& slot = "",
               const std::string& spec = "") {
  Tally t;
  for (const auto& r : run.results) {
    if (!slot.empty() && r.slot != slot) continue;
    if (!spec.empty() && std::find(r.spec_entries.begin(), r.spec_entries.end(), spec) == r.spec_entries.end())
      continue;
    const ModeResult& m = mode(r);
    if (!m.ran) continue;
    ++t.mutants;
    if (r.equivalent_in(alone))
      ++t.equivalent;
    else if (m.killed)
      ++t.killed;
    else
      ++t.survived;
  }
  return t;
}

}  // namespace

Tally tally(const MutantsRun& run, bool alone, const std::string& slot, const std::string& spec) {
  return tally_of(
      run, [alone](const MutantResult& r) -> const ModeResult& { return alone ? r.alone : r.full; }, alone, slot, spec);
}

Tally tally_protocol(const MutantsRun& run) {
  return tally_of(
      run, [](const MutantResult& r) -> const ModeResult& { return r.protocol; }, false);
}

std::vector<std::string> protocol_differences(const MutantsRun& run) {
  std::vector<std::string> out;
  for (const auto& r : run.results)
    if (r.protocol.ran && r.full.ran && r.protocol.killed != r.full.killed)
      out.push_back(r.name +
                    (r.full.killed ? ": killed in-process, not through the protocol"
                                   : ": killed through the protocol, not in-process") +
                    (r.protocol.killed ? " (" + r.protocol.killed_by + ")" : ""));
  return out;
}

namespace {

std::string protocol_score_line(const MutantsRun& run) {
  const Tally p = tally_protocol(run);
  if (p.mutants == 0) return "";
  std::ostringstream os;
  os << p.killed << "/" << (p.mutants - p.equivalent) << " = " << std::fixed << std::setprecision(1) << 100 * p.score()
     << "% (each mutant served out of process by the C++ "
     << "protocol server, as untrusted mode serves a submission); verdicts that differ from the in-process run: "
     << protocol_differences(run).size();
  return os.str();
}

std::string pct(double x) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(1) << 100 * x << "%";
  return os.str();
}

std::vector<std::string> slot_order(const MutantsRun& run) {
  std::vector<std::string> out;
  for (const auto& r : run.results)
    if (std::find(out.begin(), out.end(), r.slot) == out.end()) out.push_back(r.slot);
  return out;
}
std::vector<std::string> spec_order(const MutantsRun& run) {
  std::set<std::string> s;
  for (const auto& r : run.results) s.insert(r.spec_entries.begin(), r.spec_entries.end());
  return {s.begin(), s.end()};
}

std::string replay(const MutantsRun& run, const MutantResult& r) {
  return run.options.front_door + " mutants --mutant " + r.name + " --verbose";
}

}  // namespace

std::string console_table(const MutantsRun& run) {
  std::ostringstream os;
  auto row = [&](const std::string& label, const Tally& f, const Tally& a) {
    os << std::left << std::setw(34) << label << std::right << std::setw(8) << f.mutants << std::setw(8) << f.killed
       << std::setw(6) << f.equivalent << std::setw(9) << f.survived << std::setw(9) << pct(f.score());
    if (a.mutants)
      os << std::setw(8) << a.killed << std::setw(9) << a.survived << std::setw(9) << pct(a.score());
    else
      os << std::setw(8) << "-" << std::setw(9) << "-" << std::setw(9) << "-";
    os << "\n";
  };
  auto header = [&](const std::string& what) {
    os << std::left << std::setw(34) << what << std::right << std::setw(8) << "mutants" << std::setw(8) << "killed"
       << std::setw(6) << "equiv" << std::setw(9) << "survived" << std::setw(9) << "score" << std::setw(8) << "alone:k"
       << std::setw(9) << "survived" << std::setw(9) << "score"
       << "\n";
  };
  header("slot");
  for (const auto& s : slot_order(run)) row(s, tally(run, false, s), tally(run, true, s));
  os << "\n";
  header("spec entry");
  for (const auto& s : spec_order(run)) row(s, tally(run, false, "", s), tally(run, true, "", s));
  os << "\n";
  const Tally f = tally(run, false), a = tally(run, true);
  os << "mutants: " << run.results.size() << " (" << f.equivalent << " equivalent)\n";
  os << "score, in the full reference: " << f.killed << "/" << (f.mutants - f.equivalent) << " = " << pct(f.score())
     << "\n";
  os << "score, slot alone:            " << a.killed << "/" << (a.mutants - a.equivalent) << " = " << pct(a.score())
     << " (" << a.mutants << " mutants; hand-written ones have no alone mode)\n";
  if (const std::string p = protocol_score_line(run); !p.empty()) {
    os << "score, through the protocol:  " << p << "\n";
    for (const auto& d : protocol_differences(run)) os << "  differs: " << d << "\n";
  }
  if (!run.baseline_failures.empty()) {
    os << "properties failing on the reference itself (left out):\n";
    for (const auto& b : run.baseline_failures) os << "  " << b << "\n";
  }
  for (const auto& n : run.unknown_equivalents) os << "warning: equivalent list names no mutant: " << n << "\n";
  std::vector<const MutantResult*> surv;
  for (const auto& r : run.results)
    if (r.survives()) surv.push_back(&r);
  if (!surv.empty()) {
    os << "\nsurvivors (not equivalent):\n";
    for (const auto* r : surv) {
      os << "  " << r->name << (r->full.killed ? "  [survives alone only]" : "") << "\n    " << r->description
         << "\n    properties run: ";
      const auto& props = r->full.killed ? r->alone.properties : r->full.properties;
      if (props.empty()) os << "(none)";
      for (std::size_t i = 0; i < props.size(); ++i) os << (i ? ", " : "") << props[i];
      os << "\n    replay: " << replay(run, *r) << "\n";
    }
  }
  for (const auto& r : run.results) {
    for (const auto* m : {&r.full, &r.alone}) {
      if (!m->error.empty()) os << "error: " << r.name << ": " << m->error << "\n";
    }
    if (!r.alone.undeclared.empty()) {
      os << "note: " << r.name << " (alone): properties calling a slot they do not declare:";
      for (const auto& u : r.alone.undeclared) os << " " << u;
      os << "\n";
    }
  }
  os << "time: " << std::fixed << std::setprecision(1) << run.seconds << " s\n";
  return os.str();
}

std::string markdown_report(const MutantsRun& run) {
  std::ostringstream os;
  const Tally f = tally(run, false), a = tally(run, true);
  os << "# Mutation score\n\n";
  os << "Single-mistake variants of the reference implementation, run through the properties that apply to them "
        "(case factor "
     << run.options.case_factor << ", seed " << run.options.seed << "). A mutant is killed when one verdict is "
     << "FAIL, CRASH, TIMEOUT or ERROR. Equivalent mutants (spec/equivalent_mutants.json) are not in the "
        "denominator.\n\n";
  os << "- mutants: " << run.results.size() << " (" << f.equivalent << " equivalent)\n";
  os << "- score in the full reference: " << f.killed << "/" << (f.mutants - f.equivalent) << " = " << pct(f.score())
     << "\n";
  os << "- score with the mutated slot alone: " << a.killed << "/" << (a.mutants - a.equivalent) << " = "
     << pct(a.score()) << "\n";
  if (const std::string p = protocol_score_line(run); !p.empty()) {
    os << "- score through the protocol: " << p << "\n";
    for (const auto& d : protocol_differences(run)) os << "  - differs: `" << d << "`\n";
  }
  os << "- time: " << std::fixed << std::setprecision(1) << run.seconds << " s\n\n";
  auto table = [&](const std::string& what, const std::vector<std::string>& keys, bool by_slot) {
    os << "| " << what
       << " | mutants | killed | equivalent | survived | score | alone: killed | alone: survived | alone: score |\n";
    os << "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& k : keys) {
      const Tally t = by_slot ? tally(run, false, k) : tally(run, false, "", k);
      const Tally u = by_slot ? tally(run, true, k) : tally(run, true, "", k);
      os << "| " << k << " | " << t.mutants << " | " << t.killed << " | " << t.equivalent << " | " << t.survived
         << " | " << pct(t.score()) << " | " << (u.mutants ? std::to_string(u.killed) : "-") << " | "
         << (u.mutants ? std::to_string(u.survived) : "-") << " | " << (u.mutants ? pct(u.score()) : "-") << " |\n";
    }
    os << "\n";
  };
  os << "## Per slot\n\n";
  table("slot", slot_order(run), true);
  os << "## Per spec entry\n\nA mutant counts for every spec entry with a property that applies to it.\n\n";
  table("spec entry", spec_order(run), false);
  os << "## Survivors\n\n";
  for (const auto& r : run.results) {
    if (!r.survives()) continue;
    os << "- `" << r.name << "`" << (r.full.killed ? " (alone only)" : "") << ": " << r.description << ". Replay: `"
       << replay(run, r) << "`\n";
  }
  os << "\n## Equivalent mutants\n\n";
  for (const auto& r : run.results)
    if (r.equivalent)
      os << "- `" << r.name << "`"
         << (r.equivalent_alone_only ? " (with the slot alone; killed in the full reference)" : "") << ": "
         << r.equivalence_argument << "\n";
  if (!run.baseline_failures.empty()) {
    os << "\n## Properties failing on the reference (left out)\n\n";
    for (const auto& b : run.baseline_failures) os << "- " << b << "\n";
  }
  if (run.options.matrix) os << "\n" << matrix_markdown(run);
  return os.str();
}

std::string json_report(const MutantsRun& run) {
  json j;
  const Tally f = tally(run, false), a = tally(run, true);
  j["case_factor"] = run.options.case_factor;
  j["seed"] = run.options.seed;
  j["seconds"] = run.seconds;
  auto score = [](const Tally& t) {
    return json{{"killed", t.killed},
                {"equivalent", t.equivalent},
                {"survived", t.survived},
                {"mutants", t.mutants},
                {"score", t.score()}};
  };
  j["score_full"] = score(f);
  j["score_alone"] = score(a);
  j["baseline_failures"] = run.baseline_failures;
  if (const Tally p = tally_protocol(run); p.mutants > 0) {
    j["score_protocol"] = score(p);
    j["score_protocol"]["differences"] = protocol_differences(run);
  }
  if (run.options.matrix) j["quick_profile"] = quick_profile_json(choose_quick_profile(run), run);
  j["mutants"] = json::array();
  for (const auto& r : run.results)
    j["mutants"].push_back({{"name", r.name},
                            {"slot", r.slot},
                            {"operator", r.op},
                            {"class", r.op_class},
                            {"integrator", r.integrator},
                            {"description", r.description},
                            {"equivalent", r.equivalent},
                            {"equivalent_alone_only", r.equivalent_alone_only},
                            {"equivalence_argument", r.equivalence_argument},
                            {"spec_entries", r.spec_entries},
                            {"full", mode_json(r.full)},
                            {"alone", mode_json(r.alone)},
                            {"protocol", mode_json(r.protocol)},
                            {"seconds", r.seconds}});
  return j.dump(1);
}

MutantsRun load_mutants_report(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read a mutants report");
  MutantsRun run;
  try {
    const json j = json::parse(in);
    run.options.case_factor = j.at("case_factor").get<double>();
    run.options.seed = j.at("seed").get<std::uint64_t>();
    run.options.matrix = j.contains("quick_profile");
    run.seconds = j.value("seconds", 0.0);
    run.baseline_failures = j.value("baseline_failures", std::vector<std::string>{});
    for (const auto& m : j.at("mutants")) {
      MutantResult r;
      r.name = m.at("name").get<std::string>();
      r.slot = m.value("slot", "");
      r.op = m.value("operator", "");
      r.op_class = m.value("class", "");
      r.integrator = m.value("integrator", "");
      r.description = m.value("description", "");
      r.equivalent = m.value("equivalent", false);
      r.equivalent_alone_only = m.value("equivalent_alone_only", false);
      r.equivalence_argument = m.value("equivalence_argument", "");
      r.spec_entries = m.value("spec_entries", std::vector<std::string>{});
      r.full = mode_from(m.at("full"));
      r.alone = mode_from(m.at("alone"));
      if (m.contains("protocol")) r.protocol = mode_from(m.at("protocol"));
      r.seconds = m.value("seconds", 0.0);
      run.results.push_back(std::move(r));
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a mutants report (" + e.what() + ")");
  }
  if (!run.options.matrix) throw std::runtime_error(path + ": the report has no kill matrix (made without --matrix)");
  return run;
}

int mutants_command(const MutantsOptions& o) {
  MutantsRun run;
  try {
    run = o.from_report.empty() ? run_mutants(o) : load_mutants_report(o.from_report);
  } catch (const std::exception& e) {
    std::cerr << "geomech mutants: " << e.what() << "\n";
    return 2;
  }
  if (run.results.empty()) {
    std::cerr << "geomech mutants: no mutant matches" << (o.slot.empty() ? "" : " --slot " + o.slot)
              << (o.mutant.empty() ? "" : " --mutant " + o.mutant) << "\n";
    return 2;
  }
  if (o.verbose)
    for (const auto& r : run.results) {
      std::cout << r.name << ": " << r.description << "\n";
      for (const auto* m : {&r.full, &r.alone}) {
        if (!m->ran) continue;
        std::cout << "  " << (m == &r.full ? "in the full reference" : "alone") << ": "
                  << (m->killed ? "KILLED by " + m->killed_by : std::string("SURVIVED")) << "\n";
        for (const auto& l : m->log) std::cout << "    " << l << "\n";
      }
    }
  std::cout << console_table(run);
  try {
    if (!o.report_dir.empty()) {
      std::filesystem::create_directories(o.report_dir);
      harness::write_file_atomically(o.report_dir + "/mutants.md", markdown_report(run));
      harness::write_file_atomically(o.report_dir + "/mutants.json", json_report(run));
      std::cout << "report: " << o.report_dir << "/mutants.md\n";
    }
    if (o.matrix || !o.from_report.empty()) {
      const QuickProfile q = choose_quick_profile(run);
      std::cout << quick_profile_summary(q);
      if (!o.quick_profile_out.empty()) {
        harness::write_file_atomically(o.quick_profile_out, quick_profile_json(q, run).dump(1) + "\n");
        std::cout << "quick profile: " << o.quick_profile_out << "\n";
      }
      const ThoroughOnly t = choose_thorough_only(run);
      std::cout << thorough_only_summary(t);
      if (!o.thorough_only_out.empty()) {
        harness::write_file_atomically(o.thorough_only_out, thorough_only_json(t, run).dump(1) + "\n");
        std::cout << "50-digit runs left to --thorough: " << o.thorough_only_out << "\n";
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "geomech mutants: " << e.what() << "\n";
    return 2;
  }
  const Tally f = tally(run, false);
  if (!protocol_differences(run).empty()) return 1;  // the protocol changes what the properties see
  return f.score() < o.min_score ? 1 : 0;
}

}  // namespace gm::mutation
