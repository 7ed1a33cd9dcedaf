#include "harness/program/cli.hpp"
#include "harness/checking/quick_profile.hpp"
#include "harness/checking/thorough_only.hpp"
#include "harness/program/report_tail.hpp"

#include "harness/isolation/process.hpp"
#include "harness/reports/console_stream.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"

#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace gm::harness {

int default_jobs() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

void add_check_options(CLI::App& app, CheckCliOptions& o) {
  app.add_option("--property,-p", o.properties, "only these properties (repeatable; see `geomech list`)");
  app.add_option("--spec", o.spec_prefix, "only properties whose spec entry starts with this (e.g. s2.)");
  app.add_option("--scalar", o.scalar, "double, mp50, exact or all (default)");
  app.add_option("--integrator", o.integrator, "only this integrator, for integrator properties");
  app.add_option("--seed", o.seed, "base seed (default 0: runs are reproducible)");
  app.add_option("--cases", o.cases, "cases per property (default: each property's own)")
      ->check(CLI::NonNegativeNumber);
  app.add_option_function<double>(
         "--case-factor",
         [&o](double f) {
           o.case_factor = f;
           o.case_factor_given = true;
         },
         "multiply every default case count (default 1; for an implementation behind the protocol, the factor the "
         "kill matrix ran at, spec/thorough_only.json, unless --thorough)")
      ->check(CLI::PositiveNumber);
  app.add_option("--reproduce", o.reproduce, "RapidCheck reproduce string printed with a failure");
  app.add_option_function<double>(
         "--timeout",
         [&o](double t) {
           o.timeout = t;
           o.timeout_given = true;
         },
         "seconds allowed per property and scalar (default 60; 180 for a Python implementation and 360 for an "
         "Octave one, whose arithmetic and calls are slower)")
      ->check(CLI::PositiveNumber);
  app.add_option("--case-budget", o.case_budget,
                 "seconds after which a check starts no new case (default: 40 % of --timeout; 0: none). A slow "
                 "implementation is then checked on fewer cases, which its verdict says, instead of timing out; "
                 "shrinking a failure likewise stops after a quarter of --timeout")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--jobs,-j", o.jobs, "checks run at once, each in its own process (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  app.add_option("--memory-limit", o.memory_limit_mb,
                 "memory per check, in MiB (default 4096): each check's writable memory; untrusted, the whole "
                 "sandbox's memory as root (a cgroup), else each of its processes' writable memory")
      ->check(CLI::Range(64L, 1L << 30));
  app.add_option("--report", o.report_dir, "write " + report_folder_files() + " into this directory");
  add_format_options(app, o.also);
  app.add_flag("--no-isolation", o.no_isolation, "run checks in this process (for a debugger; a crash ends the run)");
  app.add_flag("--no-portraits", o.no_portraits, "do not draw the integrator pictures");
  app.add_flag("--quiet,-q", o.quiet, "print only the summary");
  app.add_flag(
      "--quick", o.quick,
      "only the checks of the quick profile: the few that kill every mutant the whole suite kills, chosen from "
      "the kill matrix (spec/quick_profile.json); the full check stays the default");
  app.add_flag(
      "--thorough", o.thorough,
      "for a Python implementation or an untrusted one: also the costly 50-digit runs it otherwise leaves out "
      "(spec/thorough_only.json: in the kill matrix every mutant they kill is killed by a check that is kept)");
  app.add_flag("--definitions", o.definitions_only,
               "only every slot's own definition check, in double (a first look; no report unless --report)");
}

void add_library_options(CLI::App& app, LibraryCli& o) {
  app.add_option("--pkg", o.pkg,
                 "a library the C++ file uses, by its pkg-config name (repeatable; or the line `// geomech: pkg NAME` "
                 "in the file)");
  app.add_option("--cxxflags", o.cxxflags,
                 "compile flags for the C++ file (repeatable; or `// geomech: cxxflags ...`)");
  app.add_option("--ldflags", o.ldflags, "link flags for the C++ file (repeatable; or `// geomech: ldflags ...`)");
  app.add_option("-I", o.include, "an include folder for the C++ file (repeatable)");
  app.add_option("-L", o.libdir, "a library folder for the C++ file (repeatable)");
  app.add_option("-l", o.lib, "a library the C++ file links, by name (repeatable: -l ode)");
}

LibraryRequest LibraryCli::request() const {
  LibraryRequest r;
  r.pkgs = pkg;
  for (const auto& f : cxxflags)
    for (auto& w : split_flags(f)) r.cxxflags.push_back(std::move(w));
  for (const auto& d : include) r.cxxflags.push_back("-I" + d);
  for (const auto& f : ldflags)
    for (auto& w : split_flags(f)) r.ldflags.push_back(std::move(w));
  for (const auto& d : libdir) r.ldflags.push_back("-L" + d);
  for (const auto& l : lib) r.ldflags.push_back("-l" + l);
  return r;
}

std::vector<std::string> library_args(const LibraryRequest& r) {
  std::vector<std::string> a;
  for (const auto& p : r.pkgs) a.insert(a.end(), {"--pkg", p});
  for (const auto& f : r.cxxflags) a.push_back("--cxxflags=" + shell_quote(f));
  for (const auto& f : r.ldflags) a.push_back("--ldflags=" + shell_quote(f));
  return a;
}

CheckConfig config_from(const CheckCliOptions& o) {
  CheckConfig c;
  c.properties = o.properties;
  for (const auto& id : o.properties)
    if (!find_property(id))
      throw CLI::ValidationError("--property", "no property is named '" + id + "' (see `geomech list`)");
  c.spec_prefix = o.spec_prefix;
  if (o.scalar == "all") {
    c.scalars = {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact};
  } else if (auto k = scalar_from_name(o.scalar)) {
    c.scalars = {*k};
  } else {
    throw CLI::ValidationError("--scalar", "must be one of double, mp50, exact, all (got '" + o.scalar + "')");
  }
  c.integrator = o.integrator;
  c.run.seed = o.seed;
  c.run.cases = o.cases;
  c.run.case_factor = o.case_factor;
  if (std::string why; !o.reproduce.empty() && !is_reproduce_string(o.reproduce, &why))
    throw CLI::ValidationError("--reproduce", "not a reproduce string printed with a failure (" + why + ")");
  c.run.reproduce = o.reproduce;
  c.timeout_seconds = o.timeout;
  c.timeout_given = o.timeout_given;
  // The budgets leave room, within the timeout, for a case that was started just before the case
  // budget ran out and for the shrinking of a failure found late.
  c.run.case_budget_seconds = o.case_budget < 0 ? 0.4 * o.timeout : o.case_budget;
  c.run.shrink_budget_seconds = o.case_budget == 0 ? 0 : 0.25 * o.timeout;
  c.jobs = o.jobs;
  c.memory_limit_mb = o.memory_limit_mb;
  c.isolate = !o.no_isolation;
  c.portraits = !o.no_portraits && !o.selects_properties();
  if (o.quick) {
    try {
      const QuickSelection q = load_quick_profile(default_quick_profile_path());
      c.only_checks = q.checks;
      c.selection_note = "quick profile: " + q.provenance;
    } catch (const std::exception& e) {
      throw CLI::ValidationError("--quick", e.what());
    }
    c.portraits = false;
  }
  if (o.definitions_only) {
    for (const auto& p : properties())
      if (p.scope == Scope::Subject && p.needs.size() == 1 && p.id.rfind("definition_", 0) == 0 &&
          (o.properties.empty() || std::find(o.properties.begin(), o.properties.end(), p.id) != o.properties.end()))
        c.properties.push_back(p.id);
    c.scalars = {ScalarKind::Double};
    c.portraits = false;
  }
  return c;
}

std::vector<std::string> to_args(const CheckCliOptions& o) {
  std::vector<std::string> a;
  auto num = [](double x) {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
  };
  for (const auto& p : o.properties) a.insert(a.end(), {"--property", p});
  if (!o.spec_prefix.empty()) a.insert(a.end(), {"--spec", o.spec_prefix});
  if (o.scalar != "all") a.insert(a.end(), {"--scalar", o.scalar});
  if (!o.integrator.empty()) a.insert(a.end(), {"--integrator", o.integrator});
  a.insert(a.end(), {"--seed", std::to_string(o.seed)});
  if (o.cases > 0) a.insert(a.end(), {"--cases", std::to_string(o.cases)});
  if (o.case_factor_given || o.case_factor != 1.0) a.insert(a.end(), {"--case-factor", num(o.case_factor)});
  if (!o.reproduce.empty()) a.insert(a.end(), {"--reproduce", o.reproduce});
  if (o.timeout_given) a.insert(a.end(), {"--timeout", num(o.timeout)});
  if (o.case_budget >= 0) a.insert(a.end(), {"--case-budget", num(o.case_budget)});
  a.insert(a.end(), {"--jobs", std::to_string(o.jobs)});
  a.insert(a.end(), {"--memory-limit", std::to_string(o.memory_limit_mb)});
  if (!o.report_dir.empty()) a.insert(a.end(), {"--report", o.report_dir});
  for (const auto& [option, file] : o.also) a.insert(a.end(), {option, file});
  if (o.no_isolation) a.push_back("--no-isolation");
  if (o.no_portraits) a.push_back("--no-portraits");
  if (o.quiet) a.push_back("--quiet");
  if (o.definitions_only) a.push_back("--definitions");
  if (o.quick) a.push_back("--quick");
  if (o.thorough) a.push_back("--thorough");
  return a;
}

int run_check_cli(const SubjectSet& subject, const SubjectInfo& info, const CheckCliOptions& o) {
  const CheckConfig cfg = config_from(o);
  std::optional<Catalogue> cat;
  try {
    cat = load_catalogue(default_catalogue_path());
  } catch (const std::exception& e) {
    std::cerr << "geomech: warning: " << e.what() << " (places in the notes will not be shown)\n";
  }
  const Catalogue* c = cat ? &*cat : nullptr;
  // Results as they happen: the console listens to the run; the checks that failed in
  // the previous run of this report run first.
  CheckConfig streaming = cfg;
  streaming.failed_before = failed_checks_in_report(o.report_dir);
  // Behind the protocol, the whole check leaves its costliest 50-digit runs to --thorough
  // (a selection by name, a replay or --quick runs what it names).
  if (info.out_of_process && !o.thorough && !o.selects_properties() && !o.quick && !o.definitions_only) {
    try {
      const ThoroughOnlySelection t = load_thorough_only(default_thorough_only_path());
      streaming.thorough_only = t.checks;
      streaming.thorough_only_note = t.provenance;
      // Every call is a round trip: the share of each property's cases at which the kill matrix
      // kills every mutant, unless the user chose a factor.
      if (!o.case_factor_given && t.case_factor < 1) {
        streaming.run.case_factor = t.case_factor;
        streaming.case_factor_note = t.case_factor_note;
      }
      // A picture, not a check: its axis of cost would time the round trips, not the integrator.
      streaming.work_precision_left_out =
          "the work-precision diagram is drawn with --thorough: behind the protocol its cost axis would time the "
          "round trips of the calls, not the integrators";
    } catch (const std::exception& e) {
      std::cerr << "geomech: warning: " << e.what() << " (every 50-digit run is done)\n";
    }
  }
  ConsoleStream console(subject.name, info, cfg.run.seed, o.quiet, std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0);
  streaming.listeners.push_back(&console);
  const CheckResult r = run_check(subject, info, streaming);
  if (o.definitions_only && o.report_dir.empty()) {  // a first look: its failures were streamed
    std::cout << "geomech: first look: " << r.ran() << (r.ran() == 1 ? " slot check" : " slot checks") << " in double, "
              << console.failures_printed() << (console.failures_printed() == 1 ? " failure" : " failures") << "\n";
    return r.exit_code();
  }
  return finish_check(r, c, ReportTail{o.quiet, o.report_dir, o.also});
}

}  // namespace gm::harness
