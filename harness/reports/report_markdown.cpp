// report.md: the Markdown report of a check, for people (report.hpp, markdown_report); it renders the engine's decisions.
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/work_precision.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/html_page.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;
using namespace report_parts;
using nlohmann::json;

namespace {

// The title, the source and interpreter, the result, what was not checked, how it was checked, the
// warnings.
void write_header(std::ostream& md, const CheckResult& r) {
  md << "# geomech report: " << md_inline(r.subject) << "\n\n";
  if (!r.description.empty()) md << md_inline(r.description) << "\n\n";
  if (!r.info.source.empty()) {
    // The file's own name: a report handed back to a student names their file, not the
    // folders of the machine that checked it.
    fs::path src = fs::path(r.info.source).lexically_normal();
    if (!src.has_filename()) src = src.parent_path();
    md << "Source: " << md_inline(src.filename().string()) << "\n\n";
  }
  if (!r.info.notebook.empty()) md << "Notebook: " << md_inline(r.info.notebook) << "\n\n";
  if (!r.info.interpreter.empty()) md << "Interpreter: " << md_inline(r.info.interpreter) << "\n\n";
  md << "**Result: " << r.verdict_word() << "** - " << summary_counts(r) << ". Exit status " << r.exit_code()
     << ".\n\n";
  if (r.ran() == 0)
    md << "Nothing was checked: no property could run on what this implementation provides"
       << (r.narrowed ? " with this selection" : "") << ". A check that ran nothing is not a pass.\n\n";
  if (!r.unchecked.empty()) {
    md << "## Not checked (this fails the check)\n\n";
    for (const auto& u : r.unchecked) md << "- " << md_cell(u) << "\n";
    md << "\n";
  }
  md << "Checked " << r.selection << " with seed " << r.seed << " in " << seconds_text(r.seconds)
     << ". Residuals are in units of eps * scale (eps of the scalar; the scale is the size of the inputs).";
  if (!r.info.reproduce_prefix.empty()) md << " Re-run: `" << r.info.reproduce_prefix << "`.";
  md << "\n\n";
  if (!r.info.warnings.empty()) {
    md << "## Warnings\n\n";
    for (const auto& w : r.info.warnings) md << "- " << md_cell(w) << "\n";
    md << "\n";
  }
}

// What to fix: the first fixes the check decided (harness/checking/first_fix.hpp), the steps that
// raise, then the rest, one line per property and outcome. `problems` is sorted here for the details.
void write_what_to_fix(std::ostream& md, const CheckResult& r, std::vector<const Verdict*>& problems) {
  if (!problems.empty()) {
    // One line per property (and integrator) and outcome, naming the scalars it happened in;
    // ordered by root cause: a slot whose own direct property fails comes first, with
    // the properties that fail only because they call it grouped under it.
    md << "## What to fix\n\n";
    const RootCauses& rc = r.first_fixes;
    for (const auto& slot : rc.order) {
      const Verdict* direct = &rc.broken.at(slot);
      if (auto c = rc.calls_broken.find(slot); c != rc.calls_broken.end())
        md << "- **" << slot_named(r, slot, "`") << " fails too**, and it calls `" << c->second
           << "`, which is wrong (above): fix that first. Its own check `" << direct->property << "` fails in ["
           << direct->scalar << "](#" << anchor_of(*direct) << "): " << md_cell(first_line(direct->message)) << "\n";
      else
        md << "- **" << slot_named(r, slot, "`") << " is wrong**: its own check `" << direct->property << "` fails in ["
           << direct->scalar << "](#" << anchor_of(*direct) << "): " << md_cell(first_line(direct->message)) << "\n";
      auto it = rc.downstream.find(slot);
      if (it != rc.downstream.end() && !it->second.empty()) {
        md << "  - these fail too, and call `" << slot << "` (fix it first): ";
        for (std::size_t i = 0; i < it->second.size(); ++i) md << (i ? ", " : "") << "`" << it->second[i] << "`";
        md << "\n";
      }
    }
    // A step that raises: one line per message, naming the integrators that raise it and the claimed
    // checks it stopped. The integrator's domain check says where it raises
    // (properties/integrators/integrator_domain.cpp): its line leads for the raise it measured (its
    // message holds the raise's), and is not repeated below; another raise (a TypeError of the 50-digit
    // run at a slow state, say) is said with its own place, not the domain's.
    std::vector<std::pair<std::string, std::vector<const Verdict*>>> raises;
    for (const Verdict* v : problems) {
      if (v->step_raised.empty()) continue;
      const std::string key = first_line(v->step_raised);
      auto it = std::find_if(raises.begin(), raises.end(), [&](const auto& g) { return g.first == key; });
      if (it == raises.end())
        raises.push_back({key, {v}});
      else
        it->second.push_back(v);
    }
    std::set<const Verdict*> said;
    auto domain_of = [&](const std::string& integrator, const std::string& raise) -> const Verdict* {
      for (const Verdict* v : problems)
        if (v->integrator == integrator && v->property.find("integrator_domain") != std::string::npos &&
            v->message.find(raise) != std::string::npos)
          return v;
      return nullptr;
    };
    for (const auto& [raise, vs] : raises) {
      std::vector<std::string> integrators;
      for (const Verdict* v : vs)
        if (std::find(integrators.begin(), integrators.end(), v->integrator) == integrators.end())
          integrators.push_back(v->integrator);
      const Verdict* domain = domain_of(vs.front()->integrator, raise);
      md << "- **integrator" << (integrators.size() > 1 ? "s " : " ");
      for (std::size_t i = 0; i < integrators.size(); ++i) md << (i ? ", " : "") << "`" << integrators[i] << "`";
      md << ": your step raises**: ";
      if (domain) {
        std::string line = first_line(domain->message);
        if (line.rfind(domain->integrator + ": ", 0) == 0) line = line.substr(domain->integrator.size() + 2);
        md << md_cell(line);
        for (const Verdict* v : problems)
          if (v->property == domain->property && v->message.find(raise) != std::string::npos) said.insert(v);
      } else {
        md << "at " << md_cell(vs.front()->step_raised_where) << ": " << md_cell(raise);
      }
      md << ". The claimed checks it stopped: ";
      for (std::size_t i = 0; i < vs.size(); ++i)
        md << (i ? ", " : "") << "[`" << row_name(*vs[i]) << "` " << vs[i]->scalar << "](#" << anchor_of(*vs[i]) << ")";
      md << "\n";
    }
    // Then the rest, an integrator's claimed checks before the ones nobody claimed.
    std::stable_sort(problems.begin(), problems.end(), [&](const Verdict* a, const Verdict* b) {
      return judges_a_claim_made(r, *a) > judges_a_claim_made(r, *b);
    });
    std::vector<std::pair<std::string, std::vector<const Verdict*>>> groups;
    for (const Verdict* v : problems) {
      if (rc.explained.count(v->property) || !v->step_raised.empty() || said.count(v)) continue;
      const std::string key = row_name(*v) + "|" + outcome_name(v->outcome);
      auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == key; });
      if (it == groups.end())
        groups.push_back({key, {v}});
      else
        it->second.push_back(v);
    }
    for (const auto& [key, vs] : groups) {
      const Verdict& v = *vs.front();
      md << "- **" << outcome_name(v.outcome) << "** `" << row_name(v) << "` in ";
      for (std::size_t i = 0; i < vs.size(); ++i)
        md << (i ? ", " : "") << "[" << vs[i]->scalar << "](#" << anchor_of(*vs[i]) << ")";
      md << ": " << md_cell(v.title) << ". " << md_cell(first_line(v.message)) << "\n";
    }
    md << "\n";
  }
}

// Every property: a row each, a cell per scalar.
void write_every_property(std::ostream& md, const CheckResult& r, const Catalogue* c) {
  md << "## Every property\n\n"
     << "| property | statement | spec entry (place in the notes) | double | mp50 | exact |\n"
     << "|---|---|---|---|---|---|\n";
  std::vector<std::string> md_not_run;
  for (const auto& [name, by] : table_rows(r)) {
    if (nothing_ran(by)) {
      md_not_run.push_back(name);
      continue;
    }
    const Verdict& any = *by.begin()->second;
    const std::string place = place_of(any, c);
    md << "| `" << name << "` | " << md_cell(any.title) << " | `" << any.spec << "`"
       << (place.empty() ? "" : " (" + md_cell(place) + ")") << " |";
    for (const char* s : {"double", "mp50", "exact"}) {
      auto it = by.find(s);
      if (it == by.end()) {
        md << " - |";
        continue;
      }
      const Verdict& v = *it->second;
      std::string cell = verdict_cell(v, std::string(s) == "exact");
      if (is_problem(v.outcome)) cell = "[**" + cell + "**](#" + anchor_of(v) + ")";
      md << " " << cell << " |";
    }
    md << "\n";
  }
  if (!md_not_run.empty()) {
    md << "\nNot provided in any scalar (" << md_not_run.size() << " properties, reasons under *Not provided*): ";
    for (std::size_t i = 0; i < md_not_run.size(); ++i) md << (i ? ", " : "") << "`" << md_not_run[i] << "`";
    md << ".\n";
  }
  md << "\nA dash means the property does not run in that scalar (integrators and anything that needs square "
        "roots or flows are not run in exact rationals).\n\n";
}

// Each integrator with its claims, its portraits and figures; the work-precision diagram; other
// figures.
void write_integrators_and_figures(std::ostream& md, const CheckResult& r) {
  const auto figures = report_figures(r);
  if (!r.integrators.empty()) {
    md << "## Integrators and their claims\n\n";
    for (const auto& integ : r.integrators) {
      md << "### " << integ.name << "\n\n";
      md << "Steps: ";
      for (std::size_t i = 0; i < integ.steps.size(); ++i) md << (i ? ", " : "") << "`" << integ.steps[i] << "`";
      md << "; scalars: ";
      for (std::size_t i = 0; i < integ.scalars.size(); ++i) md << (i ? ", " : "") << integ.scalars[i];
      md << (integ.has_claims ? "" : "; no claims declared") << domain_words(integ.claims.domain) << ".\n\n";
      if (!integ.form.is_notes())
        md << "State: " << describe_state_form(integ.form) << " (declared `" << state_form_words(integ.form)
           << "`); the suite reads it as the notes' (Pi, O) by " << state_form_conversion(integ.form)
           << ", and steps your own state along each run.\n\n";
      if (const std::string p = precision_words(integ); !p.empty()) md << "Precision: " << md_inline(p) << ".\n\n";
      bool any_row = false;
      for (const auto& row : claim_rows(r, integ)) any_row = any_row || row.status != "-";
      if (!any_row)
        md << "Nothing claimed, and no property reported on any claim.\n\n";
      else
        md << "| claim | claimed | finding | measured | evidence |\n|---|---|---|---|---|\n";
      for (const auto& row : claim_rows(r, integ)) {
        if (row.status == "-") continue;  // neither claimed nor checked
        std::string status = md_cell(row.status);
        if (row.fails) status = "**" + status + "**";
        std::string finding = row.measured.empty() ? "" : md_cell(row.measured);
        if (!row.why.empty() && row.status.rfind("verified", 0) != 0)
          finding += (finding.empty() ? "" : "; ") + md_cell(row.why);
        md << "| " << row.claim << " | " << row.claimed << " | " << status << " | " << finding << " | "
           << md_cell(row.evidence) << " |\n";
      }
      md << "\n";
      if (std::find(integ.steps.begin(), integ.steps.end(), "rigid_body_step") == integ.steps.end() &&
          std::find(integ.steps.begin(), integ.steps.end(), "manakov_step") != integ.steps.end())
        md << "No pictures are drawn for `manakov_step` yet (only for `rigid_body_step`).\n\n";
      for (const auto& p : r.portraits) {
        if (p.integrator != integ.name) continue;
        if (!p.message.empty()) md << "Portrait in " << p.scalar << ": " << md_cell(p.message) << "\n\n";
      }
      for (const auto& f : figures)
        if (f.integrator == integ.name) md << "![" << f.file << "](" << f.file << ")\n\n";
    }
  }
  for (const auto& p : r.portraits) {
    if (p.property != "work-precision") continue;
    md << "## Work-precision diagram and long-time energy\n\n";
    md << "Every integrator of this implementation beside the suite's methods for the same kind of step (RK4, "
          "midpoint, a splitting or the isospectral method, and Boost.Odeint's adaptive Dormand-Prince), in double: "
          "the error at t = 4 against steps, vector-field evaluations and wall time, and the energy error over a long "
          "run on log-log axes. Wall times of a Python or Octave implementation include the protocol's round trips. "
          "Data: [figures/work-precision.csv](figures/work-precision.csv).\n\n";
    md << (p.outcome == Outcome::Pass ? "" : std::string("**Not drawn (") + outcome_name(p.outcome) + ")**: ")
       << md_cell(p.message) << "\n\n";
    for (const auto& f : figures)
      if (f.file.rfind("figures/work-precision", 0) == 0) md << "![" << f.file << "](" << f.file << ")\n\n";
  }
  std::vector<std::string> other_figures;
  for (const auto& f : figures)
    if (f.integrator.empty() && f.file.rfind("figures/work-precision", 0) != 0) other_figures.push_back(f.file);
  if (!other_figures.empty()) {
    md << "## Figures\n\n";
    for (const auto& f : other_figures) md << "![" << f << "](" << f << ")\n\n";
  }
}

void write_not_provided(std::ostream& md, const CheckResult& r) {
  // What did not run, short for a short submission. The checks of what is not written at
  // all are one count per missing slot (a three-slot file's report was 223 lines, mostly these);
  // the checks that what is written cannot run in a scalar (double only) keep their reason, as
  // they say something about the code.
  md << "## Not provided\n\n";
  if (r.count(Outcome::NotProvided) == 0) {
    md << "Nothing: every property ran.\n\n";
  } else {
    std::map<std::string, int> missing_slots;            // a slot or integrator step not written -> its checks
    std::map<std::string, std::set<std::string>> other;  // double only: reason -> rows
    int not_written = 0;
    for (const auto& v : r.verdicts) {
      if (v.outcome != Outcome::NotProvided) continue;
      if (not_provided_kind(r, v) == "double only") {
        other[v.message].insert(v.property + " [" + v.scalar + "]");
        continue;
      }
      ++not_written;
      std::string what;
      if (const Property* p = property_of(v))
        for (const auto& need : p->needs)
          if (is_slot_name(need) && std::none_of(r.provided.begin(), r.provided.end(), [&](const auto& kv) {
                return std::find(kv.second.begin(), kv.second.end(), need) != kv.second.end();
              })) {
            what = "`" + need + "`";
            break;
          }
      if (what.empty()) what = md_cell(v.message);
      ++missing_slots[what];
    }
    md << r.count(Outcome::NotProvided)
       << " checks could not run; none is skipped silently (each, by name and "
          "scalar, is in verdicts.json).\n\n";
    if (not_written > 0 && is_engine_wrapper(r)) {
      md << "- " << not_written
         << " need slots of the notes: an engine wrapper: slots not provided (its integrators "
            "are checked).\n";
    } else if (not_written > 0) {
      md << "- " << not_written << " need what this implementation does not have, by what they need: ";
      bool first = true;
      for (const auto& [what, n] : missing_slots) md << (first ? "" : ", ") << what << " (" << n << ")", first = false;
      md << ".\n";
    }
    for (const auto& [reason, rows] : other) {
      md << "- " << md_cell(reason) << " (" << rows.size() << "): ";
      std::size_t k = 0;
      for (const auto& row : rows) {
        if (k == 6) {
          md << " and " << rows.size() - 6 << " more";
          break;
        }
        md << (k++ ? ", " : "") << "`" << row << "`";
      }
      md << "\n";
    }
    md << "\n";
  }
}

// What this run left to --thorough: 50-digit runs, cases, the diagram.
void write_left_out(std::ostream& md, const CheckResult& r) {
  if (!r.left_to_thorough.empty()) {
    md << "## Left to --thorough\n\n"
       << r.left_to_thorough.size()
       << " costly 50-digit runs were not done: an implementation behind the protocol leaves "
          "them to `--thorough`, since "
       << md_cell(r.thorough_only_note)
       << ". Each of these properties ran in double "
          "(and in rationals where it is exact), and every slot's own check ran in 50 digits: ";
    bool first = true;
    for (const auto& c : r.left_to_thorough) {
      md << (first ? "" : ", ") << "`" << c << "`";
      first = false;
    }
    md << ".\n\n";
  }
  if (r.case_factor > 0) {
    md << "## Cases\n\n"
       << "Every check ran " << r.case_factor
       << " of its property's cases: an implementation behind the protocol "
          "makes every call a round trip, and "
       << md_cell(r.case_factor_note) << ". `--thorough` runs every case.\n\n";
  }
  if (!r.work_precision_left_out.empty()) md << "Not drawn: " << md_cell(r.work_precision_left_out) << ".\n\n";
}

// The slots provided per scalar, and what exercised each.
void write_slots(std::ostream& md, const CheckResult& r) {
  md << "Slots provided:\n\n";
  for (const char* s : {"double", "mp50", "exact"}) {
    auto it = r.provided.find(s);
    md << "- " << s << ": ";
    if (it == r.provided.end() || it->second.empty()) {
      md << "none";
      if (auto u = r.info.scalar_unavailable.find(s); u != r.info.scalar_unavailable.end())
        md << " (" << md_cell(u->second) << ")";
    } else {
      for (std::size_t i = 0; i < it->second.size(); ++i) md << (i ? ", " : "") << "`" << it->second[i] << "`";
    }
    md << "\n";
  }
  md << "\n";
  // For each provided slot, the properties that exercised it; a provided slot that
  // nothing exercised is a warning, never silence.
  if (!r.exercised.empty() || !r.unexercised.empty()) {
    md << "## What exercised each slot\n\n| slot or integrator | properties that ran on it |\n|---|---|\n";
    for (const auto& [slot, ps] : r.exercised) {
      md << "| `" << slot << "` | ";
      for (std::size_t i = 0; i < ps.size(); ++i) md << (i ? ", " : "") << "`" << ps[i] << "`";
      md << " |\n";
    }
    md << "\n";
    for (const auto& w : r.unexercised) md << "- **warning:** " << md_cell(w) << "\n";
    if (!r.unexercised.empty()) md << "\n";
  }
}

// The checks that discarded cases or ran fewer than planned.
void write_partial_checks(std::ostream& md, const CheckResult& r) {
  // A discarded case is not a check. Every verdict that discarded some says how many.
  std::vector<const Verdict*> discarding;
  for (const auto& v : r.verdicts)
    if (v.discarded > 0) discarding.push_back(&v);
  if (!discarding.empty()) {
    md << "## Discarded cases\n\n"
       << "A discarded case checked nothing: its draw could not test the statement (for instance a perturbed "
          "curve that happens to be stationary). The cases counted as passed leave them out.\n\n"
       << "| check | scalar | cases passed | discarded | first reason |\n|---|---|---|---|---|\n";
    for (const Verdict* v : discarding)
      md << "| `" << row_name(*v) << "` | " << v->scalar << " | " << v->cases << " | " << v->discarded << " | "
         << md_cell(v->discard_reason) << " |\n";
    md << "\n";
  }

  // Checks whose time budget ran out before all planned cases (a slow implementation).
  std::vector<const Verdict*> short_runs;
  for (const auto& v : r.verdicts)
    if (v.outcome == Outcome::Pass && v.cases_planned > v.cases) short_runs.push_back(&v);
  if (!short_runs.empty()) {
    md << "## Checks that ran fewer cases than planned\n\n"
       << "Each check starts no new case once its time budget is spent (`--case-budget`, by default 40 % of "
          "`--timeout`), so that a correct but slow implementation is checked on fewer cases instead of being "
          "stopped as a TIMEOUT. These passed on the cases they ran; a faster implementation, or a larger "
          "`--timeout`, runs them all.\n\n"
       << "| check | scalar | cases run | planned | seconds |\n|---|---|---|---|---|\n";
    for (const Verdict* v : short_runs)
      md << "| `" << row_name(*v) << "` | " << v->scalar << " | " << v->cases << " | " << v->cases_planned << " | "
         << seconds_text(v->seconds) << " |\n";
    md << "\n";
  }
}

// One section per problem: statement, spec entry, message, counterexample, the replay command.
void write_details(std::ostream& md, const CheckResult& r, const Catalogue* c,
                   const std::vector<const Verdict*>& problems) {
  if (!problems.empty()) {
    md << "## Details\n\n";
    for (const Verdict* v : problems) {
      md << "<a id=\"" << anchor_of(*v) << "\"></a>\n### " << outcome_name(v->outcome) << ": " << row_name(*v) << " in "
         << v->scalar << "\n\n";
      md << "**Statement:** " << md_cell(v->title) << "\n\n";
      md << "**Spec entry:** `" << v->spec << "`";
      if (c)
        if (const SpecEntry* e = c->find(v->spec))
          md << ", " << md_cell(e->place) << " (notes, line " << e->line << "): " << md_cell(e->statement);
      md << "\n\n";
      md << fence(v->message);
      if (!v->counterexample.empty() && !inputs_in_message(*v)) {
        md << (v->shrink_stopped ? "\nCounterexample (full precision; shrinking was stopped by its time budget, so it "
                                   "is the smallest failing case found by then, not a minimal one):\n\n"
               : counterexample_by_name(*v) ? "\nCounterexample (shrunk, full precision), by the notes' names:\n\n"
                                            : "\nCounterexample (shrunk, full precision):\n\n");
        std::string ce;
        for (const auto& [type, value] : v->counterexample) ce += type + " = " + value + "\n";
        md << fence(ce);
      }
      md << "\n";
      if (v->outcome == Outcome::Fail && r.info.randomised)
        md << "Failed after " << v->cases << " passing cases; seed " << v->seed << ".\n\n";
      md << "Reproduce:\n\n" << fence(reproduce_command(r, *v)) << "\n";
    }
  }
}

}  // namespace

std::string markdown_report(const CheckResult& r, const Catalogue* c) {
  std::ostringstream md;
  write_header(md, r);
  std::vector<const Verdict*> problems;
  for (const auto& v : r.verdicts)
    if (is_problem(v.outcome)) problems.push_back(&v);
  write_what_to_fix(md, r, problems);
  write_every_property(md, r, c);
  write_integrators_and_figures(md, r);
  write_not_provided(md, r);
  write_left_out(md, r);
  write_slots(md, r);
  write_partial_checks(md, r);
  write_details(md, r, c, problems);
  return md.str();
}

}  // namespace gm::harness
