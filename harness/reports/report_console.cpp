// The console summary of a finished check (report.hpp, console_report); it renders the engine's decisions.
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gm::harness {

using namespace report_parts;
using nlohmann::json;

namespace {

// The subject, the selection, the interpreter, the warnings.
void write_head(std::ostream& os, const CheckResult& r) {
  os << "geomech check: subject '" << r.subject << "'";
  if (!r.description.empty()) os << " (" << r.description << ")";
  os << "\nseed " << r.seed << "; " << r.selection << "; residuals in units of eps * scale\n";
  if (!r.info.interpreter.empty()) os << "interpreter: " << inert_text(r.info.interpreter) << "\n";
  if (!r.info.notebook.empty()) os << "notebook: " << inert_text(r.info.notebook) << "\n";
  for (const auto& w : r.info.warnings) os << "warning: " << w << "\n";
}

// A row per property, a cell per scalar; what did not run, counted.
void write_table(std::ostream& os, const CheckResult& r, const Catalogue* c) {
  os << "\n" << std::left << std::setw(44) << "property" << std::setw(30) << "spec entry (place)";
  const char* scalars[] = {"double", "mp50", "exact"};
  for (const char* s : scalars) os << std::setw(20) << s;
  os << "\n" << std::string(44 + 30 + 60, '-') << "\n";
  std::vector<std::string> not_run;
  for (const auto& [name, by] : table_rows(r)) {
    if (nothing_ran(by)) {
      not_run.push_back(name);
      continue;
    }
    const Verdict& any = *by.begin()->second;
    std::string place = any.spec;
    const std::string full = place_of(any, c);
    if (!full.empty()) place += " " + full.substr(0, full.find(','));
    if (place.size() > 29) place = place.substr(0, 28) + "~";
    std::string shown = name;
    if (shown.size() > 43) {
      // An integrator's row keeps its integrator whole (two integrators whose names begin alike
      // must not share a row's name): the property's name is cut instead.
      const auto bracket = name.rfind(" [");
      if (bracket != std::string::npos && name.back() == ']' && name.size() - bracket <= 34)
        shown = name.substr(0, 43 - (name.size() - bracket) - 1) + "~" + name.substr(bracket);
      else
        shown = name.substr(0, 42) + "~";
    }
    os << std::setw(44) << shown << std::setw(30) << place;
    for (const char* s : scalars) {
      auto it = by.find(s);
      std::string cell = "-";
      if (it != by.end()) cell = verdict_cell(*it->second, std::string(s) == "exact");
      os << std::setw(20) << cell + " ";  // a cell wider than its column still ends with a space
    }
    os << "\n";
  }
  if (!not_run.empty()) {
    // A partial file reads as what was written and how it fared, not as a list of what
    // was not: the properties that need other slots are counted here and listed in report.md.
    std::set<std::string> provided;
    for (const auto& [scalar, slots] : r.provided) provided.insert(slots.begin(), slots.end());
    const RootCauses& rc = r.first_fixes;
    std::size_t unexercised = 0;
    for (const auto& slot : provided) unexercised += r.exercised.count(slot) == 0;
    os << "(" << provided.size() << " of " << subject_slots().size() << " slots provided";
    if (!provided.empty()) {
      os << ", "
         << (unexercised == 0 ? std::string("all checked")
                              : std::to_string(provided.size() - unexercised) + " checked");
      os << ", " << rc.broken.size() << " wrong by their own check";
      if (!rc.broken.empty()) {
        os << " (";
        bool first = true;
        for (const auto& [slot, v] : rc.broken) os << (first ? "" : ", ") << slot, first = false;
        os << ")";
      }
    }
    os << "; " << not_run.size() << " more properties need slots or integrators this implementation does not provide"
       << " (report.md lists them)";
    os << ")\n";
  }
}

// The counts, the first fixes the check decided, what was not checked, discarded or cut short.
void write_summary(std::ostream& os, const CheckResult& r) {
  os << "\nsummary: " << summary_counts(r) << "  (" << seconds_text(r.seconds) << ")\n";
  {
    const RootCauses& rc = r.first_fixes;
    for (const auto& slot : rc.order) {
      const Verdict* direct = &rc.broken.at(slot);
      if (auto c = rc.calls_broken.find(slot); c != rc.calls_broken.end()) {
        os << "THEN:      " << slot_named(r, slot, "'") << " fails its own check " << direct->property << " in "
           << direct->scalar << ", and it calls '" << c->second << "', which is wrong: fix that first\n";
        continue;
      }
      os << "FIRST FIX: " << slot_named(r, slot, "'") << " is wrong: its own check " << direct->property << " fails in "
         << direct->scalar << ": " << first_line(direct->message) << "\n";
      auto it = rc.downstream.find(slot);
      if (it != rc.downstream.end())
        os << "           (" << it->second.size() << " other failing properties call '" << slot << "')\n";
    }
  }
  if (r.ran() == 0)
    os << "NOTHING CHECKED: no property could run on what this implementation provides"
       << (r.narrowed ? " with this selection" : "") << "; a check that ran nothing is not a pass (exit status 1)\n";
  for (const auto& u : r.unchecked) os << "UNCHECKED: " << u << "\n";
  if (!r.unchecked.empty()) os << "(what could not be checked fails the check: exit status 1)\n";
  {  // A discarded case checked nothing; say how many there were
    int checks = 0, cases = 0;
    for (const auto& v : r.verdicts)
      if (v.discarded > 0) ++checks, cases += v.discarded;
    if (checks > 0)
      os << "discarded: " << cases << " drawn cases in " << checks
         << " checks could not test their statement and checked nothing (report.md lists them)\n";
  }
  {  // A slow implementation is checked on fewer cases rather than timed out; say so
    int checks = 0, run = 0, planned = 0;
    for (const auto& v : r.verdicts)
      if (v.outcome == Outcome::Pass && v.cases_planned > v.cases) ++checks, run += v.cases, planned += v.cases_planned;
    if (checks > 0)
      os << "short: " << checks << " checks ran " << run << " of their " << planned
         << " planned cases before their time budget was spent (shown as PASS n/m; --case-budget, --timeout; "
            "report.md lists them)\n";
  }
  if (r.narrowed && !r.unexercised.empty())
    os << "(" << r.unexercised.size() << " provided slots and integrators were not exercised by this selection)\n";
  else
    for (const auto& w : r.unexercised) os << "warning: " << w << "\n";
}

// Each integrator's claims and what was found.
void write_claims(std::ostream& os, const CheckResult& r) {
  for (const auto& integ : r.integrators) {
    std::ostringstream rows;
    rows << std::left;
    for (const auto& row : claim_rows(r, integ))
      if (row.status != "-" && row.status.find("not selected") == std::string::npos) {
        rows << "\n  " << std::setw(18) << row.claim << std::setw(6) << row.claimed << row.status;
        if (!row.measured.empty()) rows << ": " << row.measured;
        // Why, where it is not in the measurement: what kept a claim from being decided, what
        // contradicts a claim made.
        if (!row.why.empty() &&
            (row.fails || row.status.rfind("not established", 0) == 0 || row.status.rfind("does not hold", 0) == 0 ||
             row.status.find("by the checks that ran") != std::string::npos))
          rows << "\n  " << std::setw(24) << ""
               << "(" << row.why << ")";
      }
    if (rows.str().empty()) continue;
    os << "\nintegrator '" << integ.name << "'";
    if (!integ.form.is_notes()) os << " (state: " << state_form_words(integ.form) << ")";
    if (const std::string p = precision_words(integ); !p.empty()) os << " (" << p << ")";
    os << " claims" << domain_words(integ.claims.domain) << ":" << rows.str() << "\n";
  }
}

// Every verdict that is not a pass or not provided, in full.
void write_problems(std::ostream& os, const CheckResult& r) {
  bool header = false;
  std::set<std::string> raised;  // one step raise in full per integrator and message
  std::vector<const Verdict*> ordered;
  for (const auto& v : r.verdicts)
    if (is_problem(v.outcome)) ordered.push_back(&v);
  std::stable_sort(ordered.begin(), ordered.end(), [&](const Verdict* a, const Verdict* b) {
    return judges_a_claim_made(r, *a) > judges_a_claim_made(r, *b);
  });
  for (const Verdict* vp : ordered) {
    const Verdict& v = *vp;
    if (!header) os << "\ndetails of every verdict that is not a pass or not provided:\n";
    header = true;
    if (!v.step_raised.empty() && !raised.insert(v.integrator + "\n" + v.step_raised).second) {
      os << "\n"
         << outcome_name(v.outcome) << "  " << row_name(v) << "  [" << v.scalar << "]: your step raised, as above\n";
      continue;
    }
    os << "\n" << outcome_name(v.outcome) << "  " << row_name(v) << "  [" << v.scalar << "]  spec " << v.spec;
    os << "\n  " << v.title;
    std::istringstream lines(v.message);
    for (std::string line; std::getline(lines, line);) os << "\n  | " << line;
    if (!v.counterexample.empty() && !inputs_in_message(v)) {
      os << "\n  " << counterexample_heading(v);
      for (const auto& [type, value] : v.counterexample) os << "\n    " << type << " = " << value;
    }
    if (v.outcome == Outcome::Fail && r.info.randomised)
      os << "\n  after " << v.cases << " passing cases; seed " << v.seed;
    os << "\n  reproduce: " << reproduce_command(r, v) << "\n";
  }
}

// What could not run, by reason.
void write_not_provided(std::ostream& os, const CheckResult& r) {
  const Missing m = missing_of(r);
  if (!m.by_reason.empty()) {
    os << "\nnot provided (" << r.count(Outcome::NotProvided) << " checks):\n";
    // A file with integrators and no slot of the notes wraps an engine: one line for the slots.
    const bool wrapper = is_engine_wrapper(r);
    std::size_t slot_checks = 0;
    for (const auto& [reason, rows] : m.by_reason) {
      if (wrapper && reason.rfind("needs slot '", 0) == 0) {
        slot_checks += rows.size();
        continue;
      }
      os << "  " << rows.size() << " x  " << reason << "\n";
    }
    if (slot_checks > 0)
      os << "  " << slot_checks << " x  an engine wrapper: slots not provided (the checks of the notes' slots; its "
         << "integrators are checked)\n";
  }
}

}  // namespace

std::string console_report(const CheckResult& r, const Catalogue* c, bool details) {
  std::ostringstream os;
  write_head(os, r);
  write_table(os, r, c);
  write_summary(os, r);
  write_claims(os, r);
  if (details) {
    write_problems(os, r);
    write_not_provided(os, r);
  }
  return os.str();
}

}  // namespace gm::harness
