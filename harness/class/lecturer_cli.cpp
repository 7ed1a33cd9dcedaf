#include "harness/class/lecturer_cli.hpp"

#include "harness/class/autograder.hpp"
#include "harness/class/class_html.hpp"
#include "harness/class/grader_machine.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/sandbox_cgroup.hpp"
#include "harness/languages/language.hpp"
#include "harness/program/build.hpp"
#include "harness/program/cli.hpp"
#include "harness/reports/report.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Runs a command's body: its status leaves through CLI::RuntimeError (0 included, so that the
// tool's main returns it), an error is printed with status 2.
template <class F>
void run_command(F&& body) {
  int status = 2;
  try {
    status = body();
  } catch (const CLI::Error&) {
    throw;
  } catch (const MachineError& e) {  // the grader's machine, not the code: its own status
    std::cerr << "geomech: " << e.what() << "\n";
    status = kExitMachine;
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << e.what() << "\n";
    status = 2;
  }
  throw CLI::RuntimeError(status);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// geomech autograder PLATFORM DIR
void add_autograder_command(CLI::App& app) {
  struct Autograder {
    std::string platform, dir;
    AutograderOptions o;
    CheckCliOptions check;
    bool no_zip = false;
  };
  auto ag = std::make_shared<Autograder>();
  auto* a = app.add_subcommand("autograder",
                               "write a Gradescope or PrairieLearn autograder for an assignment "
                               "(docs/AUTOGRADERS.md)");
  a->add_option("platform", ag->platform, "gradescope or prairielearn")
      ->required()
      ->check(CLI::IsMember({"gradescope", "prairielearn"}));
  a->add_option("dir", ag->dir, "the folder to write it into (and, for Gradescope, DIR.zip beside it)")->required();
  a->add_option("--rubric", ag->o.rubric_file, "the rubric, with the assignment's slots (docs/GRADEBOOK.md)")
      ->required();
  a->add_flag("--trusted", ag->o.trusted,
              "check in-process, without the sandbox: only where the grader cannot make user namespaces (a "
              "submission can then forge its verdicts)");
  a->add_option("--timeout-per-submission", ag->o.timeout_seconds,
                "seconds for one submission's build and check (default 540; PrairieLearn allows 600 in all)");
  a->add_option("--source", ag->o.source_dir,
                "the suite's source tree to pack (default: the one this tool was built from)");
  a->add_flag("--no-zip", ag->no_zip, "Gradescope: do not write DIR.zip");
  add_check_options(*a, ag->check);
  a->callback([ag] {
    run_command([&] {
      ag->o.platform = platform_from_name(ag->platform);
      ag->o.out_dir = ag->dir;
      ag->o.zip = !ag->no_zip;
      CheckCliOptions c = ag->check;
      c.jobs = default_jobs();  // each grader's own cores, not this machine's: left to the grader
      ag->o.check_args.clear();
      for (const auto& arg : to_args(c)) ag->o.check_args.push_back(arg);
      // --jobs is the grader's business: drop what to_args wrote for this machine.
      for (std::size_t i = 0; i + 1 < ag->o.check_args.size(); ++i)
        if (ag->o.check_args[i] == "--jobs")
          ag->o.check_args.erase(ag->o.check_args.begin() + i, ag->o.check_args.begin() + i + 2);
      return write_autograder(ag->o);
    });
  });
}

// geomech grade-submission PLATFORM --submission DIR --results FILE --config FILE
void add_grade_submission_command(CLI::App& app) {
  struct Grade {
    std::string platform;
    GradeSubmissionOptions o;
  };
  auto gr = std::make_shared<Grade>();
  auto* g = app.add_subcommand("grade-submission",
                               "check one submission and write the platform's results.json (run by "
                               "an autograder's run_autograder or run.sh)");
  g->add_option("platform", gr->platform, "gradescope or prairielearn")
      ->required()
      ->check(CLI::IsMember({"gradescope", "prairielearn"}));
  g->add_option("--submission", gr->o.submission, "the folder holding the student's files")->required();
  g->add_option("--results", gr->o.results, "the results.json to write")->required();
  g->add_option("--config", gr->o.config, "the autograder's geomech-autograder.json")->required();
  g->add_option("--work", gr->o.work, "a scratch folder (default: a new one in $TMPDIR)");
  g->callback([gr] {
    run_command([&] {
      gr->o.platform = platform_from_name(gr->platform);
      return grade_submission(gr->o);
    });
  });
}

// geomech self-test: the grader's machine, checked as a class run checks it before any student.
void add_self_test_command(CLI::App& app) {
  struct SelfTest {
    bool trusted = false;
    std::map<std::string, bool> flag;  // a served language's id -> its flag (--no-<id> or --<id>) given
    std::string cache_dir;
  };
  auto st = std::make_shared<SelfTest>();
  auto* t = app.add_subcommand("self-test",
                               "try what checking submissions needs on this machine, as the sandbox's "
                               "user: the sandbox, the compilers' cache, the interpreters (exit 3 and the "
                               "fix when something fails)");
  t->add_flag("--trusted", st->trusted, "checks will run in-process (nothing of the sandbox is needed)");
  t->add_option("--cache-dir", st->cache_dir, "the compilers' cache to try (default: the build tree's)");
  // A flag per served language of the table: --no-<id> for one tried unless told not to, --<id> for
  // one tried only when asked.
  for (const auto& l : languages()) {
    if (l.route != Route::Served) continue;
    auto& given = st->flag[l.id];
    if (l.self_test_by_default)
      t->add_flag("--no-" + l.id, given, "do not try the " + l.name + " interpreter");
    else
      t->add_flag("--" + l.id, given, "try the " + l.name + " interpreter too");
  }
  t->callback([st] {
    run_command([&] {
      GraderNeeds needs;
      needs.untrusted = !st->trusted;
      needs.cache_dir = st->cache_dir.empty() ? load_toolchain(default_toolchain_path()).cache_dir : st->cache_dir;
      std::string tried;
      for (const auto& l : languages()) {
        if (l.route != Route::Served || l.self_test_by_default == st->flag[l.id]) continue;
        needs.served.insert(l.id);
        // A language with a start probe is started in the sandbox; one without is shown to it.
        tried += ", " + l.name + (l.start_probe.empty() ? " can be shown to it" : " starts in it");
      }
      const auto problems = grader_machine_problems(needs);
      if (!problems.empty()) throw MachineError(grader_machine_message(problems));
      std::cout << "geomech self-test: this machine can check submissions"
                << (needs.untrusted ? " sandboxed (the sandbox starts, the cache " + needs.cache_dir +
                                          " is within its reach" + tried + ")"
                                    : " in-process (trusted)")
                << "\n";
      // What the kernel keeps of a sandbox here (a cgroup as root; per user namespace and per process
      // otherwise): docs/UNTRUSTED.md, "The sandbox's limits".
      if (needs.untrusted)
        std::cout << "geomech self-test: a check's sandbox limits: " << sandbox_limits_in_words() << "\n"
                  << "geomech self-test: control groups: " << cgroup_limits_in_words() << "\n";
      return 0;
    });
  });
}

// geomech class-html REPORT_DIR
void add_class_html_command(CLI::App& app) {
  struct Html {
    std::string dir, rubric;
  };
  auto h = std::make_shared<Html>();
  auto* c =
      app.add_subcommand("class-html", "write summary.html again from a class report folder (its class-shard.json)");
  c->add_option("report_dir", h->dir, "the report folder of a check-class run")->required();
  c->add_option("--rubric", h->rubric, "the rubric of the grades shown (default: partial credit per correct slot)");
  c->callback([h] {
    run_command([&] {
      const fs::path shard = fs::path(h->dir) / "class-shard.json";
      json j;
      try {
        j = json::parse(read_text(shard.string()));
      } catch (const std::exception& e) {
        throw std::runtime_error(shard.string() + ": not the record of a class run (" + e.what() + ")");
      }
      std::vector<ClassRow> rows;
      for (const auto& r : j.at("rows")) rows.push_back(class_row_from_json(r, h->dir));
      const Rubric rubric =
          h->rubric.empty() ? Rubric{} : parse_rubric(read_text(h->rubric), fs::path(h->rubric).filename().string());
      ClassPage page;
      page.class_name = j.value("class", h->dir);
      page.rubric_source = rubric.source;
      const ClassView view = decide_class(rows, rubric);
      const std::string out = (fs::path(h->dir) / "summary.html").string();
      write_file_atomically(out, class_summary_html(view, page));
      std::cout << "summary: " << out << "\n";
      return 0;
    });
  });
}

}  // namespace

void add_lecturer_commands(CLI::App& app) {
  add_autograder_command(app);
  add_grade_submission_command(app);
  add_self_test_command(app);
  add_class_html_command(app);
}

}  // namespace gm::harness
