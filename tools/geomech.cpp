// geomech: the command-line front end of the suite.
//
//   geomech check      run every property against a subject and print the report:
//                      `geomech check FILE.cpp` for anyone's implementation (see docs/STUDENTS.md),
//                      `geomech check FILE.py` / `FILE.m` for Python and Octave (docs/PROTOCOL.md),
//                      `geomech check FILE.ipynb` for a Jupyter notebook with either kernel
//   geomech check-class  a folder of implementations, in parallel, with a summary table
//   geomech check-trajectory  trajectory files written by programs in any language
//   geomech list       the registered properties with their spec entries
//   geomech slots      the subject slots an implementation can provide
//   geomech languages  the language table: the languages a submission may be written in
//   geomech subjects   the built-in subjects: the reference and its negative controls
//   geomech catalogue  the spec catalogue: Markdown table, traceability check
//   geomech mutants    mutation score: single-mistake variants of the reference through the properties
//   geomech golden     golden trajectories: regenerate/check the fixtures, make your own (golden/cli.hpp)
#include "golden/cli.hpp"
#include "harness/checking/trajectory.hpp"
#include "harness/class/class_mode.hpp"
#include "harness/class/lecturer_cli.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/private_copy.hpp"
#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/sandboxed_interpreter.hpp"
#include "harness/isolation/submission_intake.hpp"
#include "harness/languages/language.hpp"
#include "harness/program/build.hpp"
#include "harness/program/cli.hpp"
#include "harness/program/library_flags.hpp"
#include "harness/program/report_tail.hpp"
#include "harness/program/student_registry.hpp"
#include "harness/remote/protocol_codec.hpp"
#include "harness/remote/remote_subject.hpp"
#include "harness/remote/slot_conventions.hpp"
#include "harness/remote/slot_names.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_formats.hpp"
#include "harness/submissions/check_submission.hpp"
#include "impl/reference_subject.hpp"
#include "mutation/runner.hpp"
#include "mutation/served_mutant.hpp"
#include "properties/runner.hpp"
#include "spec/catalogue.hpp"
#include "tests/mutants/mutants.hpp"

#include <CLI/CLI.hpp>

#include <sys/prctl.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

namespace gm {
namespace {

// How the user called us, for the commands we print: the front-door script sets GEOMECH_FRONT_DOOR.
std::string front_door() {
  if (const char* f = std::getenv("GEOMECH_FRONT_DOOR"); f && *f) return f;
  return "geomech";
}

// `geomech check` without a file: a built-in subject (the reference, or a negative control).
int run_builtin_check(const std::string& name, const harness::CheckCliOptions& o) {
  SubjectSet subject;
  if (name == "reference") {
    subject = reference_subject();
  } else if (const Mutant* m = find_mutant(name)) {
    subject = m->make(reference_subject());
  } else {
    std::cerr << "geomech check: unknown subject '" << name
              << "' (available: reference, or a negative control listed by `geomech subjects`)\n";
    return 2;
  }
  harness::SubmissionRequest r;
  r.check = o;
  r.front_door = front_door();
  return harness::check_builtin_subject(subject, name, r);
}

// `geomech bench-protocol mine.py`: the round-trip cost of one slot call, one at a time and batched.
int run_protocol_bench(const std::string& file, int calls) {
  std::string language, why;
  const auto cmd = harness::server_command(file, &language, &why);
  if (cmd.empty()) {
    std::cerr << "geomech bench-protocol: " << file << ": " << why << "\n";
    return 2;
  }
  auto t0 = std::chrono::steady_clock::now();
  protocol::Connection conn(cmd, language);
  const auto d = protocol::parse_hello(conn.hello());
  const double start = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << language << " server (" << std::filesystem::path(cmd.front()).filename().string()
            << "): start and handshake " << std::fixed << std::setprecision(3) << start << " s\n";
  for (const char* scalar : {"double", "mp50", "exact"}) {
    auto it = d.slots.find(scalar);
    const bool has = it != d.slots.end();
    if (!has || !it->second.count("euler_3_8")) continue;
    auto v = [&](double a, double b, double c) {
      Vec3<double> x(a, b, c);
      if (std::string(scalar) == "double") return protocol::encode<double>(x);
      if (std::string(scalar) == "mp50") return protocol::encode<Real50>(Vec3<Real50>(x.cast<Real50>()));
      return protocol::encode<Rational>(Vec3<Rational>(Rational(a), Rational(b), Rational(c)));
    };
    const protocol::Call c{"euler_3_8", scalar, nlohmann::json::array({v(2, 1, 0.5), v(0.25, -1.5, 3)}), ""};
    // call_batch of one call: a round trip each time (call() would answer the repeats from memory).
    t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < calls; ++i) conn.call_batch({c});
    const double one = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / calls;
    t0 = std::chrono::steady_clock::now();
    conn.call_batch(std::vector<protocol::Call>(calls, c));
    const double batched = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / calls;
    std::cout << scalar << ": euler_3_8, " << calls << " calls: " << std::setprecision(1) << one * 1e6
              << " us per call one at a time, " << batched * 1e6 << " us per call in one batch\n";
  }
  return 0;
}

// `geomech check-trajectory FILE...`: trajectories written by programs in any language.
int run_trajectory_check(const std::vector<std::string>& files, const harness::TrajectoryCheckOptions& o,
                         const std::string& report_dir, const harness::FormatFiles& also, bool quiet) {
  harness::CheckResult r;
  try {
    r = harness::check_trajectories(files, o);
  } catch (const harness::TrajectoryError& e) {
    std::cerr << "geomech check-trajectory: " << e.what() << "\n";
    return 2;
  }
  std::string cmd = front_door() + " check-trajectory";
  for (const auto& f : files) cmd += " " + harness::shell_quote(f);
  if (o.params.system) cmd += " --system " + harness::shell_quote(*o.params.system);
  if (o.params.inertia)
    cmd += " --inertia " +
           harness::shell_quote((*o.params.inertia)[0] + "," + (*o.params.inertia)[1] + "," + (*o.params.inertia)[2]);
  if (o.params.step) cmd += " --step " + harness::shell_quote(*o.params.step);
  if (o.order > 0) cmd += " --order " + std::to_string(o.order);
  if (!o.preserves.empty()) {
    std::string list;
    for (const auto& p : o.preserves) list += (list.empty() ? "" : ",") + p;
    cmd += " --preserves " + list;
  }
  if (o.tolerance != harness::TrajectoryCheckOptions{}.tolerance) {
    std::ostringstream t;
    t << o.tolerance;
    cmd += " --tolerance " + t.str();
  }
  r.info.reproduce_prefix = cmd;
  std::optional<Catalogue> cat;
  try {
    cat = load_catalogue(default_catalogue_path());
  } catch (const std::exception&) {}
  return harness::finish_check(r, cat ? &*cat : nullptr, harness::ReportTail{quiet, report_dir, also});
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

// `geomech languages`: the language table, a row each: its id, name, files, route and what runs it.
int run_languages(bool ids_only, bool listed) {
  for (const auto& l : harness::languages()) {
    if (listed) {  // the flags of `geomech slots` (the suite's own language is its default)
      if (l.signature && &l != &harness::suite_language()) std::cout << l.id << "\n";
      continue;
    }
    if (ids_only) {
      std::cout << l.id << " " << l.name << "\n";
      continue;
    }
    std::string files;
    for (const auto& e : l.extensions) files += (files.empty() ? "" : " ") + e;
    if (l.folder_of_files) files += " (or a folder of " + l.extensions.front() + " files)";
    std::cout << l.id << "  " << l.name << ": " << files << "\n    "
              << (l.route == harness::Route::Compiled ? "compiled with the suite"
                  : l.route == harness::Route::Served
                      ? "served behind the slot protocol"
                      : "its code cells served as its kernel's language: " + harness::kernels_in_words());
    if (l.interpreter) std::cout << ", in " << l.interpreter() << " ($" << l.interpreter_variable << ")";
    std::cout << "\n";
  }
  return 0;
}

int run_subjects() {
  std::cout << "reference\n    " << reference_subject().description << "\n";
  for (const auto& m : mutants()) std::cout << m.name << "\n    negative control: " << m.description << "\n";
  return 0;
}

// Each slot's convention (fixed by the notes, or free and learned from the student's own
// hat), after its meaning; then the integrators' interface. `prefix` starts each line of text.
// `text` wrapped at 100 columns after `prefix`, continuation lines indented under it.
void print_wrapped(const std::string& text, const std::string& prefix) {
  std::istringstream words(text);
  std::string line = prefix, word;
  while (words >> word) {
    if (line.size() > prefix.size() && line.size() + 1 + word.size() > 100) {
      std::cout << line << "\n";
      line = prefix + "  ";
    }
    line += (line.size() > prefix.size() && line.back() != ' ' ? " " : "") + word;
  }
  std::cout << line << "\n";
}

void print_convention(const std::string& slot, const std::string& prefix) {
  const std::string c = harness::slot_convention(slot);
  if (!c.empty()) print_wrapped("convention: " + c, prefix);
}

// The integrators' interface: its prose (wrapped, as a comment in the language's code block), then
// the language's code.
void print_interface(const harness::Language& l) {
  print_wrapped(harness::integrator_state(), l.comment);
  std::cout << l.integrator_interface();
}

// `geomech slots` (the suite's own language, with the index by concept) or `geomech slots --<id>`:
// each slot's signature in the language, its place and meaning, its convention, then the
// integrators' interface, all from the language's row.
int run_slots(const harness::Language& l) {
  if (!l.slots_heading.empty()) std::cout << l.slots_heading << "\n\n";
  if (!l.slots_fence.empty()) std::cout << "```" << l.slots_fence << "\n";
  for (const auto& s : subject_slots()) {
    std::cout << l.signature(s.name, s.signature) << "\n    " << l.comment << s.place << ": " << s.meaning << "\n";
    print_convention(s.name, "    " + l.comment);
  }
  std::cout << "\n";
  print_interface(l);
  if (!l.slots_fence.empty()) std::cout << "```\n";
  if (&l == &harness::suite_language()) {
    std::cout << "\nBy concept (slot names are the notes' equation numbers):\n";
    for (const auto& c : harness::slot_concepts())
      std::cout << "  " << std::left << std::setw(40) << c.concept_name << c.slot << "\n";
  }
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

// `geomech check`: anyone's implementation (a file, by its route) or a built-in subject.
struct CheckCommand {
  CLI::App* app = nullptr;
  harness::CheckCliOptions co;
  std::string subject = "reference";
  std::string student_file;
  harness::BuildOptions bo = [] {
    harness::BuildOptions b;
    // Compilers at once: the three scalars of one file compile in parallel even on two cores (the
    // kernel interleaves them; total wall time is then about their summed CPU time / cores).
    b.jobs = static_cast<int>(std::max(3u, std::thread::hardware_concurrency()));
    return b;
  }();
  std::string reproduce_prefix;
  std::string outcome_file;
  bool untrusted = false;
  harness::LibraryCli check_libs;
};

void add_check_command(CLI::App& app, CheckCommand& c) {
  auto& [unused_app, co, subject, student_file, bo, reproduce_prefix, outcome_file, untrusted, check_libs] = c;
  (void)unused_app;
  auto* check = c.app = app.add_subcommand(
      "check", "check an implementation: a student's FILE.cpp, or a built-in subject (default: the reference)");
  check->add_option("file", student_file,
                    "an implementation: a " + harness::extensions_in_words() + " file" +
                        harness::folder_in_words().replace(0, 6, ", or") + " (docs/STUDENTS.md)");
  check->add_option("--subject", subject, "built-in subject when no file is given (default: reference)");
  check->add_flag("--verbose", bo.verbose, "print the compiler commands");
  check->add_flag("--rebuild", bo.force, "compile again even if nothing changed");
  check->add_option("--cache-dir", bo.cache_dir,
                    "where compiled implementations are kept (default: in the build tree)");
  check->add_option("--name", bo.name, "the implementation's name in the report (default: the file's name)");
  check->add_option("--reproduce-prefix", reproduce_prefix,
                    "the command the report prints to replay a check (default: this one; check-class gives the "
                    "student's own, e.g. \"geomech check bob.py\")");
  check->add_option("--outcome", outcome_file, "write how the check ended (JSON) here, for a class row")->group("");
  check->add_option("--compile-jobs", bo.jobs, "compilers at once (default: the cores, at least 3)")
      ->check(CLI::Range(1, 256))
      ->group("");
  check->add_flag("--untrusted", untrusted,
                  "run the implementation as its own sandboxed process behind the slot protocol (docs/UNTRUSTED.md): "
                  "it cannot touch the verdicts, the machine or other files");
  harness::add_check_options(*check, co);
  harness::add_library_options(*check, check_libs);
  check->footer(
      "Interpreters: a .py file runs in $GEOMECH_PYTHON, else the python3 first on PATH (a venv or pyenv works), else "
      "/usr/bin/python3; it needs mpmath for the 50-digit checks. A .m file runs in geomech-octave-server (Octave's "
      "interpreter linked in) when the octave-cli on PATH is the system's, else in $GEOMECH_OCTAVE or the octave-cli "
      "on PATH. A .mjs or .js file runs in $GEOMECH_NODE, else the node first on PATH, else /usr/bin/node (double "
      "only). The report names the interpreter and its version.");
}

int run_check_command(CheckCommand& c) {
  auto& [check, co, subject, student_file, bo, reproduce_prefix, outcome_file, untrusted, check_libs] = c;
  if (!student_file.empty()) {
    if (check->count("--subject")) throw CLI::ValidationError("--subject", "give either a file or --subject, not both");
    bo.mp50 = co.scalar == "all" || co.scalar == "mp50";
    bo.exact = co.scalar == "all" || co.scalar == "exact";
    bo.libraries = check_libs.request();
    harness::SubmissionRequest r;
    r.file = student_file;
    r.sandboxed = untrusted;
    r.check = co;
    r.build = bo;
    r.front_door = front_door();
    r.reproduce_prefix = reproduce_prefix;
    r.first_look = !co.quiet;
    r.outcome_file = outcome_file;
    return harness::check_submission(r);
  }
  return run_builtin_check(subject, co);
}

// `geomech check-class` and `geomech merge-class`: a folder of submissions, and its shards combined.
struct ClassCommands {
  CLI::App* app = nullptr;
  CLI::App* merge = nullptr;
  harness::ClassOptions class_opts = [] {
    harness::ClassOptions o;
    o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return o;
  }();
  harness::LibraryCli class_libs;
  bool trusted = false;
  std::string shard;
  std::vector<std::string> merge_dirs;
  std::string merge_out;
  harness::GradeOptions merge_grades;
};

void add_class_commands(CLI::App& app, ClassCommands& c) {
  auto& [unused_app, unused_merge, class_opts, class_libs, trusted, shard, merge_dirs, merge_out, merge_grades] = c;
  (void)unused_app;
  (void)unused_merge;
  auto* klass = c.app =
      app.add_subcommand("check-class", "check every implementation in a folder, in parallel, with a summary table");
  klass
      ->add_option("folder", class_opts.dir,
                   "the class folder: one " + harness::extensions_in_words() +
                       " file per student, or one folder per student (holding one of them, or function files)")
      ->required();
  klass->add_option("--parallel", class_opts.jobs, "implementations checked at once (default: all cores)")
      ->check(CLI::Range(1, 256));
  klass->add_option("--timeout-per-implementation", class_opts.timeout_per_implementation,
                    "seconds allowed to build and check one implementation (default 1800)");
  klass->add_option("--cache-dir", class_opts.build.cache_dir,
                    "where compiled implementations are kept (default: in the build tree)");
  klass->add_flag("--trusted", trusted,
                  "check the implementations in-process, without the sandbox (faster; only for code you trust: "
                  "a submission can then forge its verdicts)");
  harness::add_check_options(*klass, class_opts.check);
  harness::add_library_options(*klass, class_libs);
  klass->add_option("--shard", shard,
                    "K/N: check only the K-th of N deterministic shares of the folder (CI matrix, Slurm array)");
  klass->add_option("--shared", class_opts.shared,
                    "FILE: a header every C++ submission may include (repeatable); nothing else of the class folder is "
                    "shared between students");
  klass->add_flag(
      "--fresh", class_opts.fresh,
      "check every implementation again (by default a re-run resumes: one unchanged since its last complete "
      "check, in source, options and suite, is not checked again)");
  klass->add_option("--regrade", class_opts.regrade,
                    "NAME: check this implementation again whatever its last result (repeatable); every other is "
                    "resumed as usual, and the summary and gradebook cover the whole class");
  klass->add_flag("--not-checked", class_opts.not_checked,
                  "check again the implementations whose last result is NOT CHECKED (a timeout, a check that "
                  "raised); every other is resumed as usual");
  auto add_grade_options = [](CLI::App& app, harness::GradeOptions& g) {
    app.add_option("--grades", g.csv, "write a gradebook CSV for Moodle or Canvas (docs/GRADEBOOK.md)");
    app.add_option("--rubric", g.rubric, "the rubric of --grades, JSON (default: partial credit per correct slot)");
    app.add_option("--roster", g.roster, "CSV: implementation name -> the identifiers the LMS matches students on");
    app.add_option("--feedback-dir", g.feedback_dir,
                   "DIR: one feedback page per student, named for Moodle's or Canvas's bulk upload when the class "
                   "folder came from their download (docs/GRADEBOOK.md)");
  };
  add_grade_options(*klass, class_opts.grades);
  auto* merge = c.merge = app.add_subcommand(
      "merge-class", "combine the report folders of check-class --shard K/N runs into one class report");
  merge->add_option("out", merge_out, "the folder for the combined report")->required();
  merge->add_option("shards", merge_dirs, "the shards' report folders")->required();
  add_grade_options(*merge, merge_grades);
}

int run_class_command(ClassCommands& c, int argc, char** argv) {
  auto& [klass, merge, class_opts, class_libs, trusted, shard, merge_dirs, merge_out, merge_grades] = c;
  if (*merge) return harness::merge_class(merge_dirs, merge_out, merge_grades);
  if (!shard.empty()) {
    const auto slash = shard.find('/');
    try {
      if (slash == std::string::npos) throw std::invalid_argument("no /");
      class_opts.shard_k = std::stoi(shard.substr(0, slash));
      class_opts.shard_n = std::stoi(shard.substr(slash + 1));
    } catch (const std::exception&) {
      throw CLI::ValidationError("--shard", "'" + shard + "' is not K/N (for example 2/8)");
    }
    if (class_opts.shard_n < 1 || class_opts.shard_k < 1 || class_opts.shard_k > class_opts.shard_n)
      throw CLI::ValidationError("--shard", "'" + shard + "' needs 1 <= K <= N");
  }
  if (class_opts.check.report_dir.size()) class_opts.report_dir = class_opts.check.report_dir;
  class_opts.check.report_dir.clear();
  class_opts.front_door = front_door();
  {  // the command that resumes this run (said on Ctrl-C): this one, without --fresh
    std::vector<std::string> again{front_door()};
    for (int a = 1; a < argc; ++a)
      if (std::string(argv[a]) != "--fresh") again.push_back(argv[a]);
    class_opts.command = harness::shell_join(again);
  }
  class_opts.build.mp50 = class_opts.check.scalar == "all" || class_opts.check.scalar == "mp50";
  class_opts.build.exact = class_opts.check.scalar == "all" || class_opts.check.scalar == "exact";
  class_opts.untrusted = !trusted;
  class_opts.build.libraries = class_libs.request();
  return harness::run_class(class_opts, harness::load_toolchain(harness::default_toolchain_path()));
}

// `geomech check-trajectory`: trajectory files written by programs in any language.
struct TrajectoryCommand {
  CLI::App* app = nullptr;
  harness::TrajectoryCheckOptions tro;
  std::vector<std::string> trajectory_files, tr_inertia, tr_preserves;
  std::string tr_system, tr_step, tr_report;
  harness::FormatFiles tr_also;  // each format's own option (harness/reports/report_formats.hpp)
  bool tr_quiet = false;
};

void add_trajectory_command(CLI::App& app, TrajectoryCommand& c) {
  auto& [unused_app, tro, trajectory_files, tr_inertia, tr_preserves, tr_system, tr_step, tr_report, tr_also,
         tr_quiet] = c;
  (void)unused_app;
  auto* traj = c.app = app.add_subcommand(
      "check-trajectory", "check trajectory files from any language (format: docs/TRAJECTORY_FORMAT.md)");
  traj->add_option("files", trajectory_files,
                   "trajectory files; several runs of one motion at different steps give the order")
      ->required();
  traj->add_option("--system", tr_system, "the system, for files without a header (rigid_body)");
  traj->add_option("--inertia", tr_inertia, "I1,I2,I3 for files without a header")->expected(3)->delimiter(',');
  traj->add_option("--step", tr_step, "step size h, for files without a header");
  traj->add_option("--order", tro.order, "claimed order of the method (judged from the log-log slope)")
      ->check(CLI::Range(1, 20));
  traj->add_option("--preserves", tr_preserves,
                   "claimed exact invariants: casimir, energy, orthogonality, spatial_momentum (comma-separated)")
      ->delimiter(',');
  traj->add_option("--tolerance", tro.tolerance,
                   "allowed error against the reference, relative to |Pi(0)| (default 0.05: catches wrong equations)")
      ->check(CLI::PositiveNumber);
  traj->add_option(
      "--report", tr_report,
      "write " + harness::report_folder_files() + " here (default: geomech-reports/trajectory-<first file>)");
  harness::add_format_options(*traj, tr_also);
  traj->add_flag("--quiet,-q", tr_quiet, "print only the summary");
  traj->add_flag(
      "--allow-nonphysical", tro.params.allow_nonphysical,
      "accept moments of inertia that violate the triangle inequality (no body has them; the notes' examples do)");
}

int run_trajectory_command(TrajectoryCommand& c) {
  auto& [traj, tro, trajectory_files, tr_inertia, tr_preserves, tr_system, tr_step, tr_report, tr_also, tr_quiet] = c;
  if (!tr_system.empty()) tro.params.system = tr_system;
  if (!tr_inertia.empty()) tro.params.inertia = std::array<std::string, 3>{tr_inertia[0], tr_inertia[1], tr_inertia[2]};
  if (!tr_step.empty()) tro.params.step = tr_step;
  tro.preserves.insert(tr_preserves.begin(), tr_preserves.end());
  // A report by default, as `geomech check` writes one: named after the first file.
  if (tr_report.empty())
    tr_report = "geomech-reports/trajectory-" + std::filesystem::path(trajectory_files.front()).stem().string();
  return run_trajectory_check(trajectory_files, tro, tr_report, tr_also, tr_quiet);
}

// The commands that describe the suite: list, slots, subjects, catalogue, and bench-protocol.
struct InfoCommands {
  CLI::App *list = nullptr, *slots = nullptr, *bench = nullptr, *subjects = nullptr, *cat = nullptr, *langs = nullptr;
  bool ids_only = false, listed = false;
  std::map<std::string, bool> slots_in;  // a language's id -> --<id> given (its listing)
  std::string bench_file;
  int bench_calls = 1000;
  bool markdown = false, trace = false;
  std::string catalogue_path;
};

void add_info_commands(CLI::App& app, InfoCommands& c) {
  c.list = app.add_subcommand("list", "list the registered properties");
  auto* slots = c.slots = app.add_subcommand("slots", "list the subject slots an implementation can provide");
  for (const auto& l : harness::languages())  // --<id> for every other language with a listing
    if (l.signature && &l != &harness::suite_language())
      slots->add_flag("--" + l.id, c.slots_in[l.id], "as " + l.name + " functions (docs/STUDENTS.md)");
  auto* bench = c.bench =
      app.add_subcommand("bench-protocol", "round-trip cost of a slot call to a .py/.m implementation");
  bench->add_option("file", c.bench_file, "a .py or .m implementation providing euler_3_8")->required();
  bench->add_option("--calls", c.bench_calls, "calls per measurement (default 1000)");
  c.subjects = app.add_subcommand("subjects", "list the built-in subjects (reference and negative controls)");
  c.langs = app.add_subcommand("languages", "list the languages a submission may be written in (the language table)");
  c.langs->add_flag("--ids", c.ids_only, "only each language's id and name, one a line");
  c.langs->add_flag("--listed", c.listed, "only the ids of the languages `geomech slots --<id>` lists, one a line");

  auto* cat = c.cat = app.add_subcommand("catalogue", "the spec catalogue");
  cat->add_flag("--markdown", c.markdown, "print the generated Markdown table (spec/CATALOGUE.md)");
  cat->add_flag("--check", c.trace, "check traceability between catalogue, notes and properties");
  cat->add_option("--file", c.catalogue_path, "catalogue file (default: the source tree's spec/catalogue.json)");
}

// The status of the info command given, or -1 when none was.
int run_info_command(InfoCommands& c) {
  auto& [list, slots, bench, subjects, cat, langs, ids_only, listed, slots_in, bench_file, bench_calls, markdown, trace,
         catalogue_path] = c;
  if (*list) return run_list();
  if (*langs) return run_languages(ids_only, listed);
  if (*slots) {
    for (const auto& [id, given] : slots_in)
      if (given) return run_slots(*harness::language_named(id));
    return run_slots(harness::suite_language());
  }
  if (*bench) return run_protocol_bench(bench_file, bench_calls);
  if (*subjects) return run_subjects();
  if (*cat) return run_catalogue(markdown, trace, catalogue_path);
  return -1;
}

// `geomech mutants` (the mutation score) and `geomech serve-mutant` (one mutant behind the protocol).
struct MutantsCommands {
  CLI::App* app = nullptr;
  CLI::App* serve = nullptr;
  mutation::MutantsOptions mo;
  bool no_alone = false;
  std::string served_name;
};

void add_mutants_commands(CLI::App& app, MutantsCommands& c) {
  auto& [unused_app, unused_serve, mo, no_alone, served_name] = c;
  (void)unused_app;
  (void)unused_serve;
  auto* mut = c.app = app.add_subcommand(
      "mutants",
      "mutation score: run the properties on single-mistake variants of the reference (docs: DESIGN.md, mutants)");
  mut->add_option("--slot", mo.slot, "only the mutants of this slot (rigid_body_step / manakov_step for integrators)");
  mut->add_option("--mutant", mo.mutant, "only this mutant (e.g. euler_3_8:negate_result)");
  mut->add_flag("--verbose", mo.verbose, "every property's verdict on each mutant (no early stop)");
  mut->add_flag(
      "--matrix", mo.matrix,
      "the kill matrix: every property and scalar on every mutant of the full reference, timed, and the quick "
      "profile chosen from it (in the report)");
  mut->add_option(
      "--write-quick-profile", mo.quick_profile_out,
      "with --matrix: write the quick profile (`geomech check --quick`) to this file (spec/quick_profile.json)");
  mut->add_option(
      "--write-thorough-only", mo.thorough_only_out,
      "with --matrix: write the 50-digit runs an implementation behind the protocol leaves to `geomech check "
      "--thorough` to this file (spec/thorough_only.json)");
  mut->add_option(
         "--from-report", mo.from_report,
         "read the kill matrix of an earlier `--matrix --report DIR` run (DIR/mutants.json) instead of running the "
         "mutants again, and choose the profiles from it")
      ->check(CLI::ExistingFile);
  mut->add_option("--case-factor", mo.case_factor, "multiplies the properties' case counts (default 0.3)")
      ->check(CLI::PositiveNumber);
  mut->add_option("--seed", mo.seed, "base seed (default fixed)");
  mut->add_option("--jobs,-j", mo.jobs, "mutants run at once, each in its own process (default 2)")
      ->check(CLI::Range(1, 256));
  mut->add_option("--timeout", mo.timeout_seconds, "seconds allowed per mutant (default 900)")
      ->check(CLI::PositiveNumber);
  mut->add_option("--min-score", mo.min_score,
                  "exit 1 when the score in the full reference is below this (default 0.98)")
      ->check(CLI::Range(0.0, 1.0));
  mut->add_option("--report", mo.report_dir, "write mutants.md and mutants.json into this directory");
  mut->add_option("--equivalent", mo.equivalent_file, "equivalent mutants (default: spec/equivalent_mutants.json)");
  mut->add_flag("--no-alone", no_alone, "skip the run with the mutated slot alone");
  mut->add_flag("--through-protocol", mo.through_protocol,
                "also serve each mutant out of process by the C++ protocol server (as untrusted mode serves a "
                "submission) and check it through the protocol: the score through the protocol, and any verdict that "
                "differs from the in-process one (exit 1 if one does)");
  auto* serve_mut = c.serve = app.add_subcommand("serve-mutant",
                                                 "serve one mutant of the reference over the slot protocol "
                                                 "(used by `geomech mutants --through-protocol`)");
  serve_mut->add_option("name", served_name, "the mutant's name (e.g. euler_3_8:negate_result)")->required();
  serve_mut->group("");
}

int run_mutants_command(MutantsCommands& c) {
  auto& [mut, serve_mut, mo, no_alone, served_name] = c;
  if (*serve_mut) return mutation::serve_mutant_command(served_name);
  mo.alone = !no_alone;
  mo.front_door = front_door();
  if (mo.program.empty()) mo.program = std::filesystem::read_symlink("/proc/self/exe").string();
  return mutation::mutants_command(mo);
}

// A first word that is no command gets named (CLI11 would only say that a command is required):
// the status 2 when it is not one, 0 when it is (or there is none).
int refuse_an_unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc <= 1 || argv[1][0] == '-') return 0;
  std::string names;
  for (const auto* sub : app.get_subcommands({})) {
    if (sub->get_name() == argv[1]) return 0;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  std::cerr << "geomech: unknown command '" << argv[1] << "' (commands: " << names << ")\n";
  return 2;
}

}  // namespace
}  // namespace gm

int main(int argc, char** argv) {
  // A check started by a class run dies with it (harness/class/class_mode.cpp): an interrupted class
  // leaves no check running behind it, writing into the reports a resumed run is writing.
  if (!gm::harness::die_with_parent_when_asked()) return 2;
  CLI::App app{"geomech: the rigid-body lecture notes as an executable specification"};
  app.require_subcommand(1);
  gm::CheckCommand check;
  gm::add_check_command(app, check);
  gm::ClassCommands klass;
  gm::add_class_commands(app, klass);
  gm::TrajectoryCommand traj;
  gm::add_trajectory_command(app, traj);
  gm::InfoCommands info;
  gm::add_info_commands(app, info);
  gm::MutantsCommands mut;
  gm::add_mutants_commands(app, mut);
  gm::golden::add_commands(app);            // runs from its own callbacks (golden/cli.hpp)
  gm::harness::add_lecturer_commands(app);  // autograder, grade-submission, class-html (harness/class/lecturer_cli.hpp)

  // Bad arguments exit with 2, like every other input error of the tool (CLI11's own codes are
  // 100 and up); --help exits with 0.
  if (const int refused = gm::refuse_an_unknown_command(app, argc, argv)) return refused;
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a subcommand that ran from its callback (golden) and set its status
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*check.app) return gm::run_check_command(check);
    if (*klass.app || *klass.merge) return gm::run_class_command(klass, argc, argv);
    if (*traj.app) return gm::run_trajectory_command(traj);
    if (*mut.app || *mut.serve) return gm::run_mutants_command(mut);
    if (const int status = gm::run_info_command(info); status >= 0) return status;
  } catch (const CLI::Error& e) {
    app.exit(e);
    return 2;
  } catch (const gm::harness::MachineError& e) {  // the grader's machine or set-up, not the code
    std::cerr << "geomech: " << e.what() << "\n";
    return gm::harness::kExitMachine;
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
