// geomech: the command-line front end of the suite.
//
//   geomech check      run every property against a subject and print the report
//   geomech list       the registered properties with their spec entries
//   geomech slots      the subject slots an implementation can provide
//   geomech subjects   the built-in subjects: the reference and its negative controls
//   geomech catalogue  the spec catalogue: Markdown table, traceability check
//   geomech golden     golden trajectories: regenerate/check the fixtures, make your own (golden/cli.hpp)
#include "golden/cli.hpp"
#include "impl/reference_subject.hpp"
#include "properties/runner.hpp"
#include "spec/catalogue.hpp"
#include "tests/mutants/mutants.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace gm {
namespace {

struct CheckOptions {
  std::string subject = "reference";
  std::vector<std::string> properties;
  std::string spec_prefix;
  std::string scalar = "all";
  std::uint64_t seed = 0;
  int cases = 0;
  double case_factor = 1.0;
  std::string reproduce;
};

std::vector<ScalarKind> scalars_from(const std::string& s) {
  if (s == "all") return {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact};
  if (s == "double") return {ScalarKind::Double};
  if (s == "mp50") return {ScalarKind::MP50};
  if (s == "exact") return {ScalarKind::Exact};
  throw CLI::ValidationError("--scalar", "must be one of double, mp50, exact, all (got '" + s + "')");
}

std::string cell(const Verdict& v) {
  std::string s = outcome_name(v.outcome);
  if (v.outcome == Outcome::Pass && v.scalar != "exact" && v.checks > 0) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " %.2g eps", v.worst_eps_units);
    s += buf;
  }
  return s;
}

int run_check(const CheckOptions& o) {
  SubjectSet subject;
  if (o.subject == "reference") {
    subject = reference_subject();
  } else if (const Mutant* m = find_mutant(o.subject)) {
    subject = m->make(reference_subject());
  } else {
    std::cerr << "geomech check: unknown subject '" << o.subject
              << "' (available: reference, or a negative control listed by `geomech subjects`)\n";
    return 2;
  }
  std::optional<Catalogue> cat;
  try {
    cat = load_catalogue(default_catalogue_path());
  } catch (const std::exception& e) {
    std::cerr << "geomech: warning: " << e.what() << " (spec places will not be shown)\n";
  }
  const auto kinds = scalars_from(o.scalar);

  std::vector<const Property*> selected;
  for (const auto& p : properties()) {
    if (!o.properties.empty() && std::find(o.properties.begin(), o.properties.end(), p.id) == o.properties.end())
      continue;
    if (!o.spec_prefix.empty() && p.spec.rfind(o.spec_prefix, 0) != 0) continue;
    selected.push_back(&p);
  }
  for (const auto& id : o.properties)
    if (!find_property(id)) {
      std::cerr << "geomech check: no property is named '" << id << "' (see `geomech list`)\n";
      return 2;
    }

  RunOptions ro;
  ro.seed = o.seed;
  ro.cases = o.cases;
  ro.case_factor = o.case_factor;
  ro.reproduce = o.reproduce;

  std::cout << "geomech check: subject '" << subject.name << "' (" << subject.description << ")\n"
            << "seed " << o.seed << "; " << selected.size() << " properties; residuals in units of eps * scale\n\n";
  std::cout << std::left << std::setw(40) << "property" << std::setw(28) << "spec entry (place)";
  for (auto k : kinds) std::cout << std::setw(22) << scalar_name(k);
  std::cout << "\n" << std::string(40 + 28 + 22 * kinds.size(), '-') << "\n";

  std::map<Outcome, int> counts;
  std::vector<Verdict> problems;
  for (const Property* p : selected) {
    std::map<std::string, std::map<ScalarKind, Verdict>> rows;  // integrator -> scalar -> verdict
    for (auto k : kinds) {
      if (!p->runs_in(k)) continue;
      for (auto& v : run_property(*p, subject, k, ro)) rows[v.integrator][k] = v;
    }
    for (auto& [integrator, by_scalar] : rows) {
      std::string name = p->id + (integrator.empty() ? "" : " [" + integrator + "]");
      std::string place = p->spec;
      if (cat)
        if (const SpecEntry* e = cat->find(p->spec)) place += " " + e->place.substr(0, e->place.find(','));
      if (place.size() > 27) place = place.substr(0, 26) + "~";
      std::cout << std::setw(40) << name << std::setw(28) << place;
      for (auto k : kinds) {
        auto it = by_scalar.find(k);
        std::cout << std::setw(22) << (it == by_scalar.end() ? std::string("-") : cell(it->second));
        if (it != by_scalar.end()) {
          ++counts[it->second.outcome];
          if (it->second.outcome != Outcome::Pass && it->second.outcome != Outcome::NotProvided)
            problems.push_back(it->second);
        }
      }
      std::cout << "\n";
    }
  }
  std::cout << "\nsummary:";
  for (auto o2 : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout, Outcome::Error})
    std::cout << " " << counts[o2] << " " << outcome_name(o2) << ",";
  std::cout << "\n";
  if (!problems.empty()) {
    std::cout << "\ndetails of every verdict that is not a pass:\n\n";
    for (const auto& v : problems) std::cout << format_verdict(v) << "\n\n";
  }
  return problems.empty() ? 0 : 1;
}

int run_list() {
  std::cout << std::left << std::setw(44) << "property" << std::setw(30) << "spec entry" << std::setw(12) << "tolerance"
            << "scalars\n";
  for (const auto& p : properties()) {
    std::string sc;
    for (auto k : {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact})
      if (p.runs_in(k)) sc += std::string(sc.empty() ? "" : ",") + scalar_name(k);
    std::cout << std::setw(44) << p.id << std::setw(30) << p.spec << std::setw(12) << tolerance_name(p.tolerance) << sc
              << "\n    " << p.title << "\n";
  }
  return 0;
}

int run_subjects() {
  std::cout << "reference\n    " << reference_subject().description << "\n";
  for (const auto& m : mutants()) std::cout << m.name << "\n    negative control: " << m.description << "\n";
  return 0;
}

int run_slots() {
  for (const auto& s : subject_slots())
    std::cout << s.name << "  " << s.signature << "\n    " << s.place << ": " << s.meaning << "\n";
  return 0;
}

int run_catalogue(bool markdown, bool check, const std::string& path) {
  Catalogue c;
  try {
    c = load_catalogue(path.empty() ? default_catalogue_path() : path);
  } catch (const std::exception& e) {
    std::cerr << "geomech catalogue: " << e.what() << "\n";
    return 2;
  }
  if (markdown) std::cout << catalogue_markdown(c, properties());
  if (check) {
    auto problems = traceability_problems(c, properties(), nullptr);
    for (const auto& p : problems) std::cerr << "traceability: " << p << "\n";
    if (!problems.empty()) return 1;
    std::cerr << "traceability: " << c.entries.size() << " entries and " << properties().size()
              << " properties are consistent\n";
  }
  if (!markdown && !check) {
    std::map<std::string, int> by;
    for (const auto& e : c.entries) ++by[e.status];
    std::cout << c.entries.size() << " entries: " << by["checked"] << " checked, " << by["erratum"] << " erratum, "
              << by["pending"] << " pending\n";
  }
  return 0;
}

}  // namespace
}  // namespace gm

int main(int argc, char** argv) {
  CLI::App app{"geomech: the rigid-body lecture notes as an executable specification"};
  app.require_subcommand(1);

  gm::CheckOptions co;
  auto* check = app.add_subcommand("check", "run the properties against a subject and print the report");
  check->add_option("--subject", co.subject, "subject to check (default: reference)");
  check->add_option("--property,-p", co.properties, "only these properties (repeatable)");
  check->add_option("--spec", co.spec_prefix, "only properties whose spec entry starts with this (e.g. s2.)");
  check->add_option("--scalar", co.scalar, "double, mp50, exact or all (default)");
  check->add_option("--seed", co.seed, "base seed (default 0; fixed so runs are reproducible)");
  check->add_option("--cases", co.cases, "cases per property (default: each property's own)");
  check->add_option("--case-factor", co.case_factor, "multiply every default case count");
  check->add_option("--reproduce", co.reproduce, "RapidCheck reproduce string printed with a failure");

  auto* list = app.add_subcommand("list", "list the registered properties");
  auto* slots = app.add_subcommand("slots", "list the subject slots an implementation can provide");
  auto* subjects = app.add_subcommand("subjects", "list the built-in subjects (reference and negative controls)");

  bool markdown = false, trace = false;
  std::string catalogue_path;
  auto* cat = app.add_subcommand("catalogue", "the spec catalogue");
  cat->add_flag("--markdown", markdown, "print the generated Markdown table (spec/CATALOGUE.md)");
  cat->add_flag("--check", trace, "check traceability between catalogue, notes and properties");
  cat->add_option("--file", catalogue_path, "catalogue file (default: the source tree's spec/catalogue.json)");

  gm::golden::add_commands(app);  // runs from its own callbacks (golden/cli.hpp)

  CLI11_PARSE(app, argc, argv);
  try {
    if (*check) return gm::run_check(co);
    if (*list) return gm::run_list();
    if (*slots) return gm::run_slots();
    if (*subjects) return gm::run_subjects();
    if (*cat) return gm::run_catalogue(markdown, trace, catalogue_path);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
