#include "harness/reports/report.hpp"

#include "harness/reports/html_page.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/engine/integrator_verdicts.hpp"

#include "harness/reports/svg.hpp"
#include "harness/engine/verdict_io.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/engine/work_precision.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const Property* property_of(const Verdict& v) { return find_property(v.property); }

std::string eps_text(double units) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2g eps", units);
  return buf;
}

// The first line that says something: RapidCheck puts "Exception thrown with message:" on a line of
// its own before the exception's text, which is what a student needs to see first.
// How the report names a slot to fix: "slot `x`" for C++ (the slot is the function's name there);
// for an implementation in another language, the function in the student's file.
std::string slot_named(const CheckResult& r, const std::string& slot, const char* quote) {
  return harness::slot_named(r.info, slot, quote);
}

std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '-';
  return out;
}

std::string place_of(const Verdict& v, const Catalogue* c) {
  if (c)
    if (const SpecEntry* e = c->find(v.spec)) return e->place;
  return {};
}

// Rows of the result table: property (+ integrator) -> scalar -> verdict, in verdict order.
std::vector<std::pair<std::string, std::map<std::string, const Verdict*>>> table_rows(const CheckResult& r) {
  std::vector<std::pair<std::string, std::map<std::string, const Verdict*>>> rows;
  for (const auto& v : r.verdicts) {
    const std::string name = row_name(v);
    auto it = std::find_if(rows.begin(), rows.end(), [&](const auto& x) { return x.first == name; });
    if (it == rows.end()) {
      rows.push_back({name, {}});
      it = rows.end() - 1;
    }
    it->second[v.scalar] = &v;
  }
  return rows;
}

bool nothing_ran(const std::map<std::string, const Verdict*>& by_scalar) {
  for (const auto& [scalar, v] : by_scalar)
    if (v->outcome != Outcome::NotProvided) return false;
  return true;
}

// The table cell of a verdict: its word, decided once (harness/engine/integrator_verdicts.hpp),
// with what a pass measured: the order where one was measured, the cases run of those planned when
// the time budget was spent, the worst residual.
std::string verdict_cell(const Verdict& v, bool exact_column) {
  std::string cell = v.word.empty() ? outcome_name(v.outcome) : v.word;
  if (v.outcome != Outcome::Pass) return cell;
  for (const auto& f : v.claims)
    if (f.claim == "order" && f.measured.rfind("order ", 0) == 0) return cell + " p = " + f.measured.substr(6);
  const bool plain = cell == "PASS";
  if (plain && v.cases_planned > v.cases)  // the time budget was spent: cases run / planned
    cell += " " + std::to_string(v.cases) + "/" + std::to_string(v.cases_planned);
  if (!exact_column && v.checks > 0 && plain) cell += " " + eps_text(v.worst_eps_units);
  return cell;
}

std::string summary_counts(const CheckResult& r) {
  std::ostringstream os;
  bool first = true;
  for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout, Outcome::Error,
                    Outcome::NotCharacterised}) {
    const int n = r.count(o);
    if (n == 0 && o != Outcome::Pass && o != Outcome::Fail) continue;
    os << (first ? "" : ", ") << n << " " << outcome_name(o);
    first = false;
  }
  return os.str();
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

// Groups the slots a subject lacks, with the properties that need them.
struct Missing {
  std::map<std::string, std::set<std::string>> by_reason;  // reason -> "property [scalar]" rows
};

Missing missing_of(const CheckResult& r) {
  Missing m;
  for (const auto& v : r.verdicts)
    if (v.outcome == Outcome::NotProvided) m.by_reason[v.message].insert(v.property + " [" + v.scalar + "]");
  return m;
}

// Why a NOT PROVIDED check did not run: "not written" when a slot or integrator it needs
// is not in the implementation at all, "double only" when it is there but not in this scalar
// (Octave computes in double, numpy code does, a C++ slot written for double). A summary counts the
// two apart: the second is the language's or the code's precision, not missing work.
std::string not_provided_kind(const CheckResult& r, const Verdict& v) {
  auto in = [&](const std::string& scalar, const std::string& slot) {
    auto it = r.provided.find(scalar);
    return it != r.provided.end() && std::find(it->second.begin(), it->second.end(), slot) != it->second.end();
  };
  auto anywhere = [&](const std::string& slot) {
    for (const auto& [scalar, slots] : r.provided)
      if (std::find(slots.begin(), slots.end(), slot) != slots.end()) return true;
    return false;
  };
  const Property* p = property_of(v);
  if (!p) return r.info.scalar_unavailable.count(v.scalar) ? "double only" : "not written";
  bool other_scalar = false;
  for (const auto& need : p->needs) {
    if (!is_slot_name(need) || in(v.scalar, need)) continue;
    if (!anywhere(need)) return "not written";
    other_scalar = true;
  }
  if (p->scope == Scope::Integrator) {
    if (r.integrators.empty()) return "not written";
    bool here = false;
    for (const auto& i : r.integrators)
      here = here || std::find(i.scalars.begin(), i.scalars.end(), v.scalar) != i.scalars.end();
    other_scalar = other_scalar || !here;
  }
  return other_scalar || r.info.scalar_unavailable.count(v.scalar) ? "double only" : "not written";
}

// A table cell or a list item: inert, on one line, nothing Markdown or HTML would act on.
std::string md_cell(const std::string& s) { return md_inline(s); }

// A code block that no text inside can close.
std::string fence(const std::string& s) { return md_fenced(s); }

// " (declared domain: |Omega| <= 1e+06, h >= 1e-09; nothing outside it is checked)", or empty.
std::string domain_words(const StepDomain& d) {
  if (!d.declared()) return {};
  std::string w;
  char buf[64];
  if (d.max_omega > 0) std::snprintf(buf, sizeof buf, "|Omega| <= %.3g", d.max_omega), w += buf;
  if (d.max_pi > 0) std::snprintf(buf, sizeof buf, "%s|state| <= %.3g", w.empty() ? "" : ", ", d.max_pi), w += buf;
  if (d.min_h > 0) std::snprintf(buf, sizeof buf, "%s|h| >= %.3g", w.empty() ? "" : ", ", d.min_h), w += buf;
  return " (declared domain: " + w + "; nothing outside it is checked)";
}

// Whether the verdict is a check of a claim its integrator made.
bool judges_a_claim_made(const CheckResult& r, const Verdict& v) {
  if (v.integrator.empty()) return false;
  for (const auto& i : r.integrators)
    if (i.name == v.integrator) return i.has_claims && claims_any(i.claims, judged_claims(v));
  return false;
}

std::string anchor_of(const Verdict& v) {
  return file_safe(v.property + "-" + v.scalar + (v.integrator.empty() ? "" : "-" + v.integrator));
}

}  // namespace

const std::vector<std::string>& area_names() {
  static const std::vector<std::string> names = {"sec. 1", "sec. 2", "sec. 3", "momentum maps", "integrators"};
  return names;
}

std::string area_of(const Verdict& v, const Catalogue* c) {
  if (!v.integrator.empty()) return "integrators";
  if (const Property* p = property_of(v); p && p->scope == Scope::Integrator) return "integrators";
  std::string section;
  if (c)
    if (const SpecEntry* e = c->find(v.spec)) section = e->section;
  if (section.empty()) section = v.spec.substr(0, v.spec.find('.'));
  if (section == "1" || section == "s1") return "sec. 1";
  if (section == "2" || section == "s2") return "sec. 2";
  if (section == "3" || section == "s3") return "sec. 3";
  return "momentum maps";
}

std::vector<ClaimRow> claim_rows(const CheckResult& r, const IntegratorInfo& integrator) {
  // The decisions of the check (harness/engine/integrator_verdicts.hpp), made once; a result assembled
  // without them (a test's) is decided here by the same function.
  const std::vector<ClaimDecision> decisions =
      integrator.decisions.empty() ? decide_claims(r, integrator) : integrator.decisions;
  std::vector<ClaimRow> rows;
  for (const auto& d : decisions) {
    ClaimRow row;
    row.claim = d.claim;
    row.claimed = d.claimed;
    row.status = d.word;
    row.measured = d.measured;
    row.why = d.why;
    row.fails = fails_check(d);
    for (const auto& e : d.evidence) row.evidence += (row.evidence.empty() ? "" : "\n") + e;
    rows.push_back(row);
  }
  return rows;
}

std::vector<Figure> report_figures(const CheckResult& r) {
  struct Group {
    std::string title, integrator;
    std::vector<Series> series;
  };
  std::vector<std::pair<std::string, Group>> groups;  // file name -> group, in first-seen order
  auto add = [&](const std::string& owner, const Verdict& v) {
    for (const auto& s : v.series) {
      const std::string file =
          "figures/" + file_safe(owner + (v.integrator.empty() ? "" : "-" + v.integrator) + "-" + s.figure) + ".svg";
      auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == file; });
      if (it == groups.end()) {
        Group g;
        g.title = s.figure + (v.integrator.empty() ? "" : " - " + v.integrator) + " (" + owner + ")";
        g.integrator = v.integrator;
        groups.push_back({file, g});
        it = groups.end() - 1;
      }
      Series copy = s;
      if (copy.name.find(v.scalar) == std::string::npos) copy.name += " (" + v.scalar + ")";
      it->second.series.push_back(std::move(copy));
    }
  };
  for (const auto& p : r.portraits) add(p.property, p);
  for (const auto& v : r.verdicts) add(v.property, v);
  std::vector<Figure> out;
  for (const auto& [file, g] : groups) out.push_back(Figure{file, svg_plot(g.title, g.series), g.integrator});
  return out;
}

std::string slot_named(const SubjectInfo& info, const std::string& slot, const char* quote) {
  const std::string q(quote), name = q + slot + q;
  const std::string file = std::filesystem::path(info.source).filename().string();
  if (info.language == "python") return "Python function " + name + (file.empty() ? "" : " in " + file);
  if (info.language == "octave") return "Octave function " + name + (file.empty() ? "" : " in " + file);
  return "slot " + name;
}

std::string first_line(const std::string& s) {
  std::size_t at = 0;
  std::string lead;  // "python function 'x' (mp50) raised an error:" says what follows, not what it is
  for (;;) {
    const auto n = s.find('\n', at);
    const std::string line = n == std::string::npos ? s.substr(at) : s.substr(at, n - at);
    if (n == std::string::npos) return lead.empty() ? line : lead + " " + line;
    if (line != "Exception thrown with message:" && !line.empty()) {
      if (line.back() != ':' || !lead.empty()) return lead.empty() ? line : lead + " " + line;
      lead = line;
    }
    at = n + 1;
  }
}


std::string console_report(const CheckResult& r, const Catalogue* c, bool details) {
  std::ostringstream os;
  os << "geomech check: subject '" << r.subject << "'";
  if (!r.description.empty()) os << " (" << r.description << ")";
  os << "\nseed " << r.seed << "; " << r.selection << "; residuals in units of eps * scale\n";
  if (!r.info.interpreter.empty()) os << "interpreter: " << inert_text(r.info.interpreter) << "\n";
  for (const auto& w : r.info.warnings) os << "warning: " << w << "\n";
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
      os << ", " << (unexercised == 0 ? std::string("all checked") : std::to_string(provided.size() - unexercised) + " checked");
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
  for (const auto& integ : r.integrators) {
    std::ostringstream rows;
    rows << std::left;
    for (const auto& row : claim_rows(r, integ))
      if (row.status != "-" && row.status.find("not selected") == std::string::npos) {
        rows << "\n  " << std::setw(18) << row.claim << std::setw(6) << row.claimed << row.status;
        if (!row.measured.empty()) rows << ": " << row.measured;
        // Why, where it is not in the measurement: what kept a claim from being decided, what
        // contradicts a claim made.
        if (!row.why.empty() && (row.fails || row.status.rfind("not established", 0) == 0 ||
                                 row.status.find("by the checks that ran") != std::string::npos))
          rows << "\n  " << std::setw(24) << "" << "(" << row.why << ")";
      }
    if (rows.str().empty()) continue;
    os << "\nintegrator '" << integ.name << "'";
    if (!integ.form.is_notes()) os << " (state: " << state_form_words(integ.form) << ")";
    if (!integ.claims.precision.empty())
      os << " (computes in " << bounded_text(inert_text(integ.claims.precision), 40)
         << (integ.claims.precision_reason.empty() ? std::string("")
                                                    : ": " + bounded_text(inert_text(integ.claims.precision_reason), 300))
         << ")";
    os << " claims" << domain_words(integ.claims.domain) << ":" << rows.str() << "\n";
  }
  if (details) {
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
        os << "\n" << outcome_name(v.outcome) << "  " << row_name(v) << "  [" << v.scalar << "]: your step raised, as above\n";
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
  return os.str();
}

bool is_engine_wrapper(const CheckResult& r) {
  for (const auto& [scalar, slots] : r.provided)
    if (!slots.empty()) return false;
  return !r.integrators.empty();
}

std::string markdown_report(const CheckResult& r, const Catalogue* c) {
  std::ostringstream md;
  md << "# geomech report: " << md_inline(r.subject) << "\n\n";
  if (!r.description.empty()) md << md_inline(r.description) << "\n\n";
  if (!r.info.source.empty()) {
    // The file's own name: a report handed back to a student names their file, not the
    // folders of the machine that checked it.
    fs::path src = fs::path(r.info.source).lexically_normal();
    if (!src.has_filename()) src = src.parent_path();
    md << "Source: " << md_inline(src.filename().string()) << "\n\n";
  }
  if (!r.info.interpreter.empty()) md << "Interpreter: " << md_inline(r.info.interpreter) << "\n\n";
  md << "**Result: " << r.verdict_word() << "** - " << summary_counts(r) << ". Exit status "
     << r.exit_code() << ".\n\n";
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

  std::vector<const Verdict*> problems;
  for (const auto& v : r.verdicts)
    if (is_problem(v.outcome)) problems.push_back(&v);
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
        md << "- **" << slot_named(r, slot, "`") << " is wrong**: its own check `" << direct->property << "` fails in [" << direct->scalar
           << "](#" << anchor_of(*direct) << "): " << md_cell(first_line(direct->message)) << "\n";
      auto it = rc.downstream.find(slot);
      if (it != rc.downstream.end() && !it->second.empty()) {
        md << "  - these fail too, and call `" << slot << "` (fix it first): ";
        for (std::size_t i = 0; i < it->second.size(); ++i) md << (i ? ", " : "") << "`" << it->second[i] << "`";
        md << "\n";
      }
    }
    // A step that raises: one line per integrator and message, with the checks it stopped.
    std::vector<std::pair<std::string, std::vector<const Verdict*>>> raises;
    for (const Verdict* v : problems) {
      if (v->step_raised.empty()) continue;
      const std::string key = v->integrator + "\n" + v->step_raised;
      auto it = std::find_if(raises.begin(), raises.end(), [&](const auto& g) { return g.first == key; });
      if (it == raises.end()) raises.push_back({key, {v}});
      else it->second.push_back(v);
    }
    // The integrator's domain check says where it raises (properties/integrators/integrator_domain.cpp): its
    // line leads, and it is not repeated below.
    std::set<const Verdict*> said;
    auto domain_of = [&](const std::string& integrator) -> const Verdict* {
      for (const Verdict* v : problems)
        if (v->integrator == integrator && v->property.find("integrator_domain") != std::string::npos) return v;
      return nullptr;
    };
    for (const auto& [key, vs] : raises) {
      const Verdict* domain = domain_of(vs.front()->integrator);
      md << "- **integrator `" << vs.front()->integrator << "`: your step raises**: ";
      if (domain) {
        std::string line = first_line(domain->message);
        if (line.rfind(domain->integrator + ": ", 0) == 0) line = line.substr(domain->integrator.size() + 2);
        md << md_cell(line);
        for (const Verdict* v : problems)
          if (v->property == domain->property && v->integrator == domain->integrator) said.insert(v);
      } else {
        md << "at " << md_cell(vs.front()->step_raised_where) << ": " << md_cell(first_line(vs.front()->step_raised));
      }
      md << ". The claimed checks it stopped: ";
      for (std::size_t i = 0; i < vs.size(); ++i)
        md << (i ? ", " : "") << "[`" << vs[i]->property << "` " << vs[i]->scalar << "](#" << anchor_of(*vs[i]) << ")";
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
      if (it == groups.end()) groups.push_back({key, {v}});
      else it->second.push_back(v);
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
      if (!integ.claims.precision.empty())
        md << "Precision: computes in " << md_inline(bounded_text(integ.claims.precision, 40)) << ", "
           << (integ.claims.precision_reason.empty() ? std::string("stated without a reason")
                                                      : "stated: " + md_inline(bounded_text(integ.claims.precision_reason, 300)))
           << ".\n\n";
      bool any_row = false;
      for (const auto& row : claim_rows(r, integ)) any_row = any_row || row.status != "-";
      if (!any_row) md << "Nothing claimed, and no property reported on any claim.\n\n";
      else md << "| claim | claimed | finding | measured | evidence |\n|---|---|---|---|---|\n";
      for (const auto& row : claim_rows(r, integ)) {
        if (row.status == "-") continue;  // neither claimed nor checked
        std::string status = md_cell(row.status);
        if (row.fails) status = "**" + status + "**";
        std::string finding = row.measured.empty() ? "" : md_cell(row.measured);
        if (!row.why.empty() && row.status.rfind("verified", 0) != 0)
          finding += (finding.empty() ? "" : "; ") + md_cell(row.why);
        md << "| " << row.claim << " | " << row.claimed << " | " << status << " | " << finding << " | " << md_cell(row.evidence)
           << " |\n";
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

  // What did not run, short for a short submission. The checks of what is not written at
  // all are one count per missing slot (a three-slot file's report was 223 lines, mostly these);
  // the checks that what is written cannot run in a scalar (double only) keep their reason, as
  // they say something about the code.
  md << "## Not provided\n\n";
  if (r.count(Outcome::NotProvided) == 0) {
    md << "Nothing: every property ran.\n\n";
  } else {
    std::map<std::string, int> missing_slots;  // a slot or integrator step not written -> its checks
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
    md << r.count(Outcome::NotProvided) << " checks could not run; none is skipped silently (each, by name and "
          "scalar, is in verdicts.json).\n\n";
    if (not_written > 0 && is_engine_wrapper(r)) {
      md << "- " << not_written << " need slots of the notes: an engine wrapper: slots not provided (its integrators "
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
  if (!r.left_to_thorough.empty()) {
    md << "## Left to --thorough\n\n"
       << r.left_to_thorough.size() << " costly 50-digit runs were not done: an implementation behind the protocol leaves "
          "them to `--thorough`, since " << md_cell(r.thorough_only_note) << ". Each of these properties ran in double "
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
       << "Every check ran " << r.case_factor << " of its property's cases: an implementation behind the protocol "
          "makes every call a round trip, and " << md_cell(r.case_factor_note) << ". `--thorough` runs every case.\n\n";
  }
  if (!r.work_precision_left_out.empty()) md << "Not drawn: " << md_cell(r.work_precision_left_out) << ".\n\n";
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
                               : counterexample_by_name(*v)
                                   ? "\nCounterexample (shrunk, full precision), by the notes' names:\n\n"
                                   : "\nCounterexample (shrunk, full precision):\n\n");
        std::string ce;
        for (const auto& [type, value] : v->counterexample) ce += type + " = " + value + "\n";
        md << fence(ce);
      }
      md << "\n";
      if (v->outcome == Outcome::Fail && r.info.randomised) md << "Failed after " << v->cases << " passing cases; seed " << v->seed << ".\n\n";
      md << "Reproduce:\n\n" << fence(reproduce_command(r, *v)) << "\n";
    }
  }
  return md.str();
}

std::string junit_report(const CheckResult& r) {
  int failures = 0, errors = 0, skipped = 0;
  for (const auto& v : r.verdicts) {
    if (v.outcome == Outcome::Fail) ++failures;
    if (v.outcome == Outcome::Crash || v.outcome == Outcome::Timeout || v.outcome == Outcome::Error) ++errors;
    if (v.outcome == Outcome::NotProvided || v.outcome == Outcome::NotCharacterised) ++skipped;
  }
  skipped += static_cast<int>(r.left_to_thorough.size());
  const std::size_t tests = r.verdicts.size() + r.left_to_thorough.size();
  char time_buf[32];
  std::snprintf(time_buf, sizeof time_buf, "%.3f", r.seconds);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << "<testsuites name=\"geomech\" tests=\"" << tests << "\" failures=\"" << failures << "\" errors=\""
    << errors << "\" skipped=\"" << skipped << "\" time=\"" << time_buf << "\">\n";
  x << "  <testsuite name=\"geomech." << xml_escape(r.subject) << "\" tests=\"" << tests
    << "\" failures=\"" << failures << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\""
    << time_buf << "\">\n";
  x << "    <properties><property name=\"seed\" value=\"" << r.seed << "\"/></properties>\n";
  for (const auto& v : r.verdicts) {
    char t[32];
    std::snprintf(t, sizeof t, "%.3f", v.seconds);
    x << "    <testcase classname=\"" << xml_escape(r.subject + "." + v.scalar) << "\" name=\""
      << xml_escape(row_name(v)) << "\" time=\"" << t << "\">\n";
    std::string body = v.title + "\nspec entry: " + v.spec + "\n" + v.message;
    if (!inputs_in_message(v))
      for (const auto& [type, value] : v.counterexample) body += "\n" + type + " = " + value;
    if (is_problem(v.outcome)) body += "\nreproduce: " + reproduce_command(r, v);
    switch (v.outcome) {
      case Outcome::Fail:
        x << "      <failure type=\"FAIL\" message=\"" << xml_escape(first_line(v.message)) << "\">"
          << xml_escape(body) << "</failure>\n";
        break;
      case Outcome::Crash:
      case Outcome::Timeout:
      case Outcome::Error:
        if (!v.machine_fault.empty())  // the machine's: said as such, with its fix
          x << "      <error type=\"" << kMachineErrorWord << "\" message=\"" << xml_escape(first_line(v.machine_fault))
            << "\">" << xml_escape(body) << "</error>\n";
        else
          x << "      <error type=\"" << outcome_name(v.outcome) << "\" message=\"" << xml_escape(first_line(v.message))
            << "\">" << xml_escape(body) << "</error>\n";
        break;
      case Outcome::NotProvided:
        x << "      <skipped message=\"NOT PROVIDED: " << xml_escape(v.message) << "\"/>\n";
        break;
      case Outcome::NotCharacterised:
        x << "      <skipped message=\"NOT CHARACTERISED: " << xml_escape(first_line(v.message)) << "\"/>\n";
        break;
      case Outcome::Pass:
        break;
    }
    // The verdict's word ("holds (not claimed)", "does not hold (not claimed)", ...), as
    // every other view shows it.
    if (!v.integrator.empty() && !v.word.empty())
      x << "      <properties><property name=\"verdict\" value=\"" << xml_escape(v.word) << "\"/></properties>\n";
    x << "    </testcase>\n";
  }
  for (const auto& c : r.left_to_thorough)
    x << "    <testcase classname=\"" << xml_escape(r.subject + ".mp50") << "\" name=\"" << xml_escape(c)
      << "\" time=\"0.000\">\n      <skipped message=\"LEFT TO --thorough: " << xml_escape(r.thorough_only_note)
      << "\"/>\n    </testcase>\n";
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

json json_report(const CheckResult& r, const Catalogue* c) {
  json j;
  j["format"] = "geomech-report 1";
  j["subject"] = r.subject;
  j["description"] = r.description;
  j["source"] = r.info.source;
  j["reproduce_prefix"] = r.info.reproduce_prefix;
  j["seed"] = r.seed;
  j["selection"] = r.selection;
  j["seconds"] = number_to_json(r.seconds);
  j["exit_code"] = r.exit_code();
  j["warnings"] = r.info.warnings;
  j["verdict"] = r.verdict_word();
  j["unchecked"] = r.unchecked;
  j["unexercised"] = r.unexercised;
  j["exercised"] = r.exercised;
  j["scalar_unavailable"] = r.info.scalar_unavailable;
  j["provided"] = r.provided;
  json counts;
  for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout, Outcome::Error,
                    Outcome::NotCharacterised})
    counts[outcome_name(o)] = r.count(o);
  j["counts"] = counts;
  j["left_to_thorough"] = r.left_to_thorough;
  if (!r.left_to_thorough.empty()) j["left_to_thorough_why"] = r.thorough_only_note;
  if (r.case_factor > 0) j["case_factor"] = {{"factor", r.case_factor}, {"why", r.case_factor_note}};
  if (!r.work_precision_left_out.empty()) j["work_precision_left_out"] = r.work_precision_left_out;
  json integrators = json::array();
  for (const auto& i : r.integrators) {
    json claims = json::array();
    for (const auto& row : claim_rows(r, i))
      claims.push_back({{"claim", row.claim}, {"claimed", row.claimed}, {"status", row.status}, {"measured", row.measured},
                        {"why", row.why}, {"fails", row.fails}, {"evidence", row.evidence}});
    json one{{"name", i.name}, {"steps", i.steps}, {"scalars", i.scalars}, {"claims", claims}};
    if (!i.form.is_notes()) one["state"] = state_form_words(i.form);
    if (!i.claims.precision.empty()) one["precision"] = {{"stated", i.claims.precision}, {"reason", i.claims.precision_reason}};
    json domain = json::object();
    if (i.claims.domain.max_omega > 0) domain["max_omega"] = i.claims.domain.max_omega;
    if (i.claims.domain.max_pi > 0) domain["max_pi"] = i.claims.domain.max_pi;
    if (i.claims.domain.min_h > 0) domain["min_h"] = i.claims.domain.min_h;
    one["domain"] = domain;
    integrators.push_back(std::move(one));
  }
  j["integrators"] = integrators;
  // The slots wrong by their own check, the one most other failures call first, each with the line
  // the console's FIRST FIX prints (a class summary says them in words).
  j["language"] = r.info.language.empty() ? "c++" : r.info.language;
  if (!r.info.interpreter.empty()) j["interpreter"] = r.info.interpreter;
  json first_fix = json::array();
  {
    const RootCauses& rc = r.first_fixes;
    for (const auto& slot : rc.order) {
      const Verdict* direct = &rc.broken.at(slot);
      json entry = {{"slot", slot}, {"property", direct->property}, {"scalar", direct->scalar}};
      if (auto c = rc.calls_broken.find(slot); c != rc.calls_broken.end()) {
        entry["calls"] = c->second;
        entry["line"] = slot_named(r, slot, "'") + " fails its own check " + direct->property + " in " + direct->scalar +
                        ", and it calls '" + c->second + "', which is wrong: fix that first";
      } else {
        entry["line"] = slot_named(r, slot, "'") + " is wrong: its own check " + direct->property + " fails in " +
                        direct->scalar + ": " + first_line(direct->message);
      }
      first_fix.push_back(std::move(entry));
    }
  }
  j["first_fix"] = first_fix;
  json verdicts = json::array();
  for (const auto& v : r.verdicts) {
    json jv = to_json(v);
    jv["area"] = area_of(v, c);
    if (is_problem(v.outcome)) jv["reproduce_command"] = reproduce_command(r, v);
    if (v.outcome == Outcome::NotProvided) jv["not_provided"] = not_provided_kind(r, v);
    verdicts.push_back(std::move(jv));
  }
  j["verdicts"] = verdicts;
  json portraits = json::array();
  for (const auto& p : r.portraits) portraits.push_back(to_json(p));
  j["portraits"] = portraits;
  return j;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const fs::path p(path);
  const fs::path tmp = p.parent_path() / ("." + p.filename().string() + ".tmp." + std::to_string(::getpid()));
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
    f << content;
    f.flush();
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::error_code ec;
  fs::rename(tmp, p, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path);
  }
}

void write_report_dir(const CheckResult& r, const std::string& dir, const Catalogue* c) {
  fs::path target = fs::absolute(dir).lexically_normal();
  while (target.has_relative_path() && target.filename().empty()) target = target.parent_path();  // "dir/" -> "dir"
  if (!target.has_relative_path() || target.filename() == "." || target.filename() == "..")
    throw std::runtime_error("cannot write a report into " + dir + ": give a directory of its own");
  const fs::path parent = target.parent_path();
  std::error_code ec;
  // Only a previous report (or an empty directory) is ever replaced: never someone's own files.
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec))
      throw std::runtime_error("cannot write a report into " + target.string() + ": it is a file");
    if (!fs::is_empty(target, ec) && !fs::exists(target / "verdicts.json", ec))
      throw std::runtime_error("refusing to replace " + target.string() +
                               ": it is not empty and not a geomech report (no verdicts.json); choose another --report");
  }
  fs::create_directories(parent, ec);
  if (ec) throw std::runtime_error("cannot create " + parent.string() + ": " + ec.message());
  const std::string pid = std::to_string(::getpid());
  const fs::path tmp = parent / ("." + target.filename().string() + ".tmp." + pid);
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp / "figures", ec);
  if (ec) throw std::runtime_error("cannot create " + tmp.string() + ": " + ec.message());
  auto put = [&](const std::string& name, const std::string& content) {
    std::ofstream f(tmp / name, std::ios::binary | std::ios::trunc);
    f << content;
    f.flush();
    if (!f) throw std::runtime_error("cannot write " + (tmp / name).string());
  };
  try {
    const std::string md = markdown_report(r, c);
    const auto figures = report_figures(r);
    put("report.md", md);
    // The same report as a page: report.md in HTML, its figures inline.
    MarkdownHtml to_html;
    to_html.image = [&](const std::string& path) {
      for (const auto& f : figures)
        if (f.file == path) return "data:image/svg+xml;base64," + base64(f.svg);
      return std::string();
    };
    put("report.html", html_page("geomech report: " + r.subject, markdown_to_html(md, to_html)));
    put("junit.xml", junit_report(r));
    put("verdicts.json", json_report(r, c).dump(1, ' ', false, json::error_handler_t::replace) + "\n");
    for (const auto& f : figures) put(f.file, f.svg);
    if (const std::string csv = work_precision_csv(r); !csv.empty()) put("figures/work-precision.csv", csv);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  // Swap in: the old report (if any) moves aside, the new one takes its name, the old one goes.
  const fs::path old = parent / ("." + target.filename().string() + ".old." + pid);
  const bool had_old = fs::exists(target);
  if (had_old) {
    fs::rename(target, old, ec);
    if (ec) {
      fs::remove_all(tmp, ec);
      throw std::runtime_error("cannot replace " + target.string() + ": " + ec.message());
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    const std::string why = ec.message();
    if (had_old) fs::rename(old, target, ec);
    fs::remove_all(tmp, ec);
    throw std::runtime_error("cannot move the new report into " + target.string() + ": " + why);
  }
  if (had_old) fs::remove_all(old, ec);
}

}  // namespace gm::harness
