#include "golden/cli.hpp"

#include "golden/arguments.hpp"

#include "golden/catalogue.hpp"
#include "golden/consistency.hpp"
#include "golden/generate.hpp"
#include "golden/regenerate.hpp"
#include "golden/systems.hpp"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace gm::golden {

namespace {

[[noreturn]] void exit_with(int status) { throw CLI::RuntimeError(status); }

struct TrajectoryOptions {
  std::string system;
  std::vector<std::string> params, initial;
  std::string times;
  int digits = kDefaultDigits;
  std::string name = "trajectory";
  std::string title;
  std::string output;
  bool allow_nonphysical = false;  // accept moments violating the triangle inequality
  bool certify = false;            // prove the digits (golden/certify.hpp)
  int certified_digits = 45;       // refuse below this many certified digits
};

int run_trajectory(const TrajectoryOptions& o) {
  try {
    std::vector<NamedValues> params, initial;
    for (const auto& p : o.params) params.push_back(parse_block_argument("--param", p));
    for (const auto& p : o.initial) initial.push_back(parse_block_argument("--initial", p));
    if (o.digits < kMinDigits || o.digits > kMaxDigits)
      throw InputError("--digits " + std::to_string(o.digits), 0,
                       "digits must be in [" + std::to_string(kMinDigits) + ", " + std::to_string(kMaxDigits) + "]");
    bool ident = !o.name.empty() && o.name.size() <= 64 && std::isalpha(static_cast<unsigned char>(o.name[0]));
    for (char c : o.name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ident) throw InputError("--name " + o.name, 0, "a name is a letter, then letters, digits or _ (at most 64)");
    for (char c : o.title)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        throw InputError("--title", 0, "the title must be one line of printable text");
    Request rq;
    rq.name = o.name;
    rq.title = o.title;
    rq.digits = o.digits;
    rq.certify = o.certify;
    rq.certified_digits = std::min(o.certified_digits, o.digits - 1);
    rq.problem = make_problem(o.system, "--system " + o.system, 0, std::move(params), std::move(initial), true);
    rq.times = parse_times_argument(o.times);
    if (const std::string note = nonphysical_inertia(rq.problem); !note.empty()) {
      if (!o.allow_nonphysical)
        throw InputError("--param I", 0,
                         note +
                             ". Pass --allow-nonphysical to integrate them anyway (as for the notes' "
                             "example I = diag(1, 1/2, 1/3))");
      std::cerr << "geomech golden trajectory: note: " << note << "\n";
    }
    GenerationReport rep;
    const Fixture f = generate(rq, &rep);
    const std::string text = write_fixture(f);
    if (o.output.empty()) {
      std::cout << text << std::flush;
    } else {
      write_file_atomically(o.output, text);
      std::cerr << "geomech golden trajectory: wrote " << o.output << "\n";
    }
    std::cerr << "geomech golden trajectory: verified, the independent methods agree to " << rep.max_abs_diff
              << " (required <= " << rep.allowed << "), accuracy " << f.accuracy << "\n";
    return 0;
  } catch (const InputError& e) {
    std::cerr << "geomech golden trajectory: " << e.what() << "\n";
    return 2;
  } catch (const VerificationError& e) {
    std::cerr << "geomech golden trajectory: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "geomech golden trajectory: " << e.what() << "\n";
    return 1;
  }
}

int run_validate(const std::vector<std::string>& files) {
  int status = 0;
  for (const auto& path : files) {
    try {
      const Fixture f = load_fixture(path);
      const Problem pr = validate_fixture(f);
      const ConsistencyReport rep = check_consistency(f, pr);
      for (const auto& p : rep.problems) std::cerr << p << "\n";
      char buf[160];
      std::snprintf(buf, sizeof buf, "%zu samples to t = %s, %d digits, accuracy %s; invariants constant to %.2g",
                    f.times.size(), f.times.back().c_str(), f.digits, f.accuracy.c_str(), rep.max_drift);
      std::cout << path << ": " << (rep.ok() ? "OK" : "INCONSISTENT") << ", " << f.system << ", " << buf << "\n";
      if (!rep.ok() && status == 0) status = 1;
    } catch (const InputError& e) {
      std::cerr << e.what() << "\n";
      status = 2;
    } catch (const std::exception& e) {
      std::cerr << path << ": " << e.what() << "\n";
      status = 2;
    }
  }
  return status;
}

int run_list(const std::string& dir_option) {
  const std::string dir = dir_option.empty() ? default_fixture_dir() : dir_option;
  for (const auto& d : fixture_definitions()) {
    const std::string path = fixture_path(dir, d.name);
    std::cout << d.name << "  (" << d.system << ", t = " << d.times.front() << " .. " << d.times.back() << ")"
              << (std::filesystem::exists(path) ? "" : "  [file missing]") << "\n    " << d.title << "\n";
  }
  return 0;
}

}  // namespace

void add_commands(CLI::App& app) {
  auto* golden = app.add_subcommand("golden", "golden trajectories: regenerate and check the fixtures, make your own");
  golden->require_subcommand(1);

  auto regen = std::make_shared<RegenerateOptions>();
  auto* r =
      golden->add_subcommand("regenerate", "regenerate every fixture in golden/fixtures (byte-identical re-runs)");
  r->add_flag("--check", regen->check,
              "write nothing; fail, listing every differing value, if a committed fixture differs");
  r->add_option("--only", regen->only, "only this fixture (repeatable; see `geomech golden list`)");
  r->add_option("--dir", regen->dir, "fixture directory (default: the source tree's golden/fixtures)");
  r->add_flag("--quiet", regen->quiet, "no per-fixture timing lines");
  r->add_flag("--no-certify", regen->no_certify,
              "leave out the certificates (ball-arithmetic enclosures): to time them against the rest; the committed "
              "fixtures carry theirs");
  r->callback([regen] {
    const int s = regenerate(*regen, std::cout, std::cerr);
    if (s != 0) exit_with(s);
  });

  auto traj = std::make_shared<TrajectoryOptions>();
  auto* t = golden->add_subcommand("trajectory", "print a verified trajectory of any system in the fixture format");
  t->add_option("--system", traj->system, "free_rigid_body, rigid_body_attitude, clebsch, manakov or nambu_3_16")
      ->required();
  t->add_option("--param", traj->params,
                "a parameter, NAME=v1,v2,... with exact numbers (2, 0.5, 2/3), e.g. I=2,1,2/3");
  t->add_option("--initial", traj->initial, "an initial block, NAME=v1,v2,..., e.g. Pi=1,0.1,0.05 (O defaults to Id)");
  t->add_option("--times", traj->times, "sample times: t1,t2,... or start:step:stop (decimals, from 0)")->required();
  t->add_option("--digits", traj->digits, "significant digits of the values, 17..55 (default 50)");
  t->add_option("--name", traj->name, "the trajectory's name (default: trajectory)");
  t->add_option("--title", traj->title, "one line describing it (default: the system's)");
  t->add_option("--output,-o", traj->output, "write to this file (atomically) instead of standard output");
  t->add_flag("--certify", traj->certify,
              "prove the printed digits by a validated Taylor method in ball arithmetic (Arb) and write each row's "
              "certified radius; refused, naming the time, where fewer digits than --certified-digits can be proved");
  t->add_option("--certified-digits", traj->certified_digits,
                "digits --certify must prove (default 45, at most --digits - 1)")
      ->check(CLI::Range(1, 55));
  t->add_flag(
      "--allow-nonphysical", traj->allow_nonphysical,
      "accept moments of inertia that violate the triangle inequality (no body has them; the notes' examples do)");
  t->callback([traj] {
    const int s = run_trajectory(*traj);
    if (s != 0) exit_with(s);
  });

  auto files = std::make_shared<std::vector<std::string>>();
  auto* v = golden->add_subcommand("validate", "read fixture files, check their format and consistency (invariants)");
  v->add_option("files", *files, "fixture files")->required();
  v->callback([files] {
    const int s = run_validate(*files);
    if (s != 0) exit_with(s);
  });

  auto dir = std::make_shared<std::string>();
  auto* l = golden->add_subcommand("list", "list the fixture set");
  l->add_option("--dir", *dir, "fixture directory (default: the source tree's golden/fixtures)");
  l->callback([dir] { run_list(*dir); });
}

}  // namespace gm::golden
