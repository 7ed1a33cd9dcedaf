#include "harness/class_mode.hpp"
#include "harness/sandbox.hpp"

#include "harness/isolate.hpp"
#include "harness/process.hpp"
#include "harness/report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool registers_student(const fs::path& p) {
  std::ifstream f(p);
  std::ostringstream os;
  os << f.rdbuf();
  return os.str().find("GEOMECH_STUDENT(") != std::string::npos;
}

struct Row {
  Implementation impl;
  bool built = false;
  std::string build_message;
  double build_seconds = 0;
  int exit_code = -1;
  double check_seconds = 0;
  std::string problem;  // the check program itself failed to run properly
  json report;          // verdicts.json
};

std::string cell(int pass, int run, int np, int problems) {
  if (run == 0 && np == 0) return "-";
  std::ostringstream os;
  os << pass << "/" << run;
  if (problems > 0) os << " (" << problems << " bad)";
  if (np > 0) os << " +" << np << " n/p";
  return os.str();
}

}  // namespace

std::vector<Implementation> find_implementations(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error(dir + " is not a folder");
  std::vector<Implementation> out;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.is_regular_file() && (e.path().extension() == ".cpp" || e.path().extension() == ".py" ||
                                e.path().extension() == ".m")) {
      out.push_back({e.path().stem().string(), e.path().string()});
    } else if (e.is_directory()) {
      // A student's folder: one .cpp that registers a student, else one .py, else .m files (an
      // Octave implementation may be a folder of function files).
      std::vector<fs::path> sources, python;
      bool octave = false;
      for (const auto& f : fs::directory_iterator(e.path(), ec)) {
        if (!f.is_regular_file()) continue;
        const auto ext = f.path().extension();
        if (ext == ".cpp" && registers_student(f.path())) sources.push_back(f.path());
        if (ext == ".py") python.push_back(f.path());
        if (ext == ".m") octave = true;
      }
      const std::string name = e.path().filename().string();
      if (sources.size() == 1) out.push_back({name, sources.front().string()});
      else if (sources.empty() && python.size() == 1) out.push_back({name, python.front().string()});
      else if (sources.empty() && python.empty() && octave) out.push_back({name, e.path().string()});
    }
  }
  if (ec) throw std::runtime_error("cannot read " + dir + ": " + ec.message());
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i].name == out[i - 1].name)
      throw std::runtime_error("two implementations in " + dir + " are both named '" + out[i].name +
                               "' (a file and a folder); rename one");
  if (out.empty())
    throw std::runtime_error(dir + " holds no implementation (*.cpp, *.py or *.m files, or folders with one .cpp using "
                             "GEOMECH_STUDENT, one .py, or .m files)");
  return out;
}


// The summary table (summary.md and the console) of a class's rows, sharded or not.
static int summarise_class(const std::string& class_dir, const std::vector<Row>& rows, const std::string& report_dir) {
  // The summary table.
  const auto& areas = area_names();
  std::ostringstream md, console;
  md << "# geomech class report: " << class_dir << "\n\n"
     << rows.size() << " implementations. Each cell: checks passed / checks run (bad: FAIL, CRASH, TIMEOUT or "
        "ERROR), then the checks not provided (n/p). Details in each implementation's report.\n\n"
     << "| implementation | result |";
  for (const auto& a : areas) md << " " << a << " |";
  md << " report |\n|---|---|";
  for (std::size_t i = 0; i < areas.size(); ++i) md << "---|";
  md << "---|\n";
  console << "\n" << std::left << std::setw(26) << "implementation" << std::setw(18) << "result";
  for (const auto& a : areas) console << std::setw(24) << a;
  console << "\n" << std::string(26 + 18 + 24 * areas.size(), '-') << "\n";
  int bad = 0;
  for (const auto& row : rows) {
    std::string result;
    std::map<std::string, std::array<int, 4>> by_area;  // pass, run, np, problems
    if (!row.built && row.problem.empty()) {
      result = "DOES NOT COMPILE";
    } else if (!row.problem.empty()) {
      result = "NOT CHECKED";
    } else {
      for (const auto& v : row.report.at("verdicts")) {
        auto& c = by_area[v.value("area", "?")];
        const std::string out = v.at("outcome").get<std::string>();
        if (out == "NOT PROVIDED") {
          ++c[2];
          continue;
        }
        ++c[1];
        if (out == "PASS")
          ++c[0];
        else
          ++c[3];
      }
      result = row.exit_code == 0 ? "PASS" : row.report.value("verdict", std::string("FAIL"));
    }
    if (result != "PASS") ++bad;
    md << "| " << row.impl.name << " | " << (result == "PASS" ? result : "**" + result + "**") << " |";
    console << std::setw(26) << row.impl.name + " " << std::setw(18) << result + " ";
    for (const auto& a : areas) {
      auto it = by_area.find(a);
      const std::string c = it == by_area.end() ? "-" : cell(it->second[0], it->second[1], it->second[2], it->second[3]);
      md << " " << c << " |";
      console << std::setw(24) << c + " ";  // a cell wider than its column still ends with a space
    }
    const std::string link = row.impl.name + "/report.md";
    md << " " << (row.built && row.problem.empty() ? "[" + link + "](" + link + ")" : "-") << " |\n";
    console << "\n";
  }
  md << "\n";
  for (const auto& row : rows) {
    if (!row.built && row.problem.empty()) {
      md << "## " << row.impl.name << ": does not compile\n\n```\n" << row.build_message << "\n```\n\n";
      console << "\n" << row.impl.name << " does not compile:\n" << row.build_message << "\n";
    } else if (!row.problem.empty()) {
      md << "## " << row.impl.name << ": not checked\n\n```\n" << row.problem << "\n```\n\n";
      console << "\n" << row.impl.name << ": " << row.problem << "\n";
    }
  }
  write_file_atomically((fs::path(report_dir) / "summary.md").string(), md.str());
  std::cout << console.str() << "\nsummary: " << report_dir << "/summary.md; one report per implementation in "
            << report_dir << "/<name>/report.md\n";
  return bad == 0 ? 0 : 1;
}


std::vector<Implementation> shard_of(const std::vector<Implementation>& all, int k, int n) {
  std::vector<Implementation> out;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(n)) == k - 1) out.push_back(all[i]);
  return out;
}

int run_class(const ClassOptions& o, const Toolchain& tc) {
  const auto all_impls = find_implementations(o.dir);
  if (o.shard_n < 1 || o.shard_k < 1 || o.shard_k > o.shard_n)
    throw std::runtime_error("--shard K/N needs 1 <= K <= N (got " + std::to_string(o.shard_k) + "/" +
                             std::to_string(o.shard_n) + ")");
  const auto impls = shard_of(all_impls, o.shard_k, o.shard_n);
  const std::string report_dir =
      o.report_dir.empty() ? "geomech-reports/" + fs::path(o.dir).lexically_normal().filename().string() : o.report_dir;
  std::error_code ec;
  fs::create_directories(report_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + report_dir + ": " + ec.message());
  const std::string front = o.front_door.empty() ? "geomech" : o.front_door;

  if (o.untrusted)
    if (const std::string why = sandbox_unavailable(); !why.empty()) throw std::runtime_error(why);
  std::cerr << "geomech check-class: " << impls.size() << " implementations in " << o.dir
            << (o.untrusted ? " (untrusted mode: each sandboxed)" : " (trusted: in-process)");
  if (o.shard_n > 1)
    std::cerr << " (shard " << o.shard_k << "/" << o.shard_n << " of " << all_impls.size() << ")";
  std::cerr << ", " << o.jobs << " at a time\n";
  // How one implementation's check ended, into its row's JSON: status 0 or 1 is a verdict, anything
  // else (a crash, a refusal, a bad option) is a problem shown in the summary.
  auto record_check = [](json& j, const ProcessResult& pr, const std::string& what) {
    j["exit_code"] = pr.exit_code;
    j["check_seconds"] = pr.seconds;
    if (pr.exit_code != 0 && pr.exit_code != 1)
      j["problem"] = what + " ended with " +
                     (pr.signal ? describe_signal(pr.signal) : "status " + std::to_string(pr.exit_code)) + ": " +
                     pr.output.substr(0, 2000);
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
  };
  std::vector<std::function<std::string()>> tasks;
  for (const auto& impl : impls) {
    tasks.push_back([&, impl]() {
      json j;
      const std::string ext = fs::path(impl.source).extension().string();
      std::error_code dir_ec;
      const bool other_language = ext == ".py" || ext == ".m" || fs::is_directory(impl.source, dir_ec);
      if (o.untrusted && !other_language) {
        // C++ in untrusted mode: the protocol server is compiled here (sandboxed), so that a file
        // that does not compile is reported as such; `geomech check --untrusted` then finds it built.
        BuildOptions bo = o.build;
        bo.jobs = 1;
        bo.name = impl.name;
        bo.server = bo.sandbox = true;
        const BuildResult b = build_student(impl.source, tc, bo);
        if (!b.ok) {
          j["built"] = false;
          j["build_message"] = b.message;
          j["build_seconds"] = b.seconds;
          return j.dump(-1, ' ', false, json::error_handler_t::replace);
        }
        j["build_seconds"] = b.seconds;
      }
      if (other_language || o.untrusted) {
        // Python and Octave, and every language in untrusted mode: `geomech check FILE` runs the
        // implementation as a protocol server (docs/PROTOCOL.md), sandboxed when untrusted.
        CheckCliOptions co = o.check;
        co.jobs = 1;
        co.quiet = true;
        co.report_dir = (fs::path(report_dir) / impl.name).string();
        std::vector<std::string> argv{fs::read_symlink("/proc/self/exe").string(), "check", impl.source};
        if (o.untrusted) argv.insert(argv.end(), {"--untrusted", "--name", impl.name});
        if (!o.build.cache_dir.empty()) argv.insert(argv.end(), {"--cache-dir", o.build.cache_dir});
        const auto args = to_args(co);
        argv.insert(argv.end(), args.begin(), args.end());
        j["built"] = true;
        if (!j.contains("build_seconds")) j["build_seconds"] = 0.0;  // the sandboxed build above, if any
        return record_check(j, run_process(ProcessSpec{argv, {}, false}), "the check");
      }
      BuildOptions bo = o.build;
      bo.jobs = 1;
      bo.name = impl.name;
      const BuildResult b = build_student(impl.source, tc, bo);
      j["built"] = b.ok;
      j["build_message"] = b.message;
      j["build_seconds"] = b.seconds;
      if (!b.ok) return j.dump(-1, ' ', false, json::error_handler_t::replace);
      CheckCliOptions co = o.check;
      co.jobs = 1;
      co.quiet = true;
      co.report_dir = (fs::path(report_dir) / impl.name).string();
      std::vector<std::string> argv{b.program};
      const auto args = to_args(co);
      argv.insert(argv.end(), args.begin(), args.end());
      argv.insert(argv.end(), {"--name", impl.name, "--source", impl.source, "--build-notes", b.notes_file,
                               "--reproduce-prefix", front + " check " + shell_quote(impl.source)});
      return record_check(j, run_process(ProcessSpec{argv, {}, false}), "the check program");
    });
  }
  IsolationOptions io;
  io.jobs = o.jobs;
  io.timeout_seconds = o.timeout_per_implementation;
  io.memory_limit_mb = 0;  // the compilers need what they need
  std::size_t done = 0;
  io.on_finished = [&](std::size_t i, const TaskResult&) {
    std::cerr << "  [" << ++done << "/" << impls.size() << "] " << impls[i].name << "\n";
  };
  const auto results = run_isolated(tasks, io);

  std::vector<Row> rows;
  for (std::size_t i = 0; i < impls.size(); ++i) {
    Row row;
    row.impl = impls[i];
    const TaskResult& t = results[i];
    if (t.status != TaskResult::Status::Ok) {
      row.problem = "checking it " + (t.detail.empty() ? std::string("failed") : t.detail);
      rows.push_back(row);
      continue;
    }
    const json j = json::parse(t.payload);
    row.built = j.at("built").get<bool>();
    row.build_message = j.value("build_message", "");
    row.build_seconds = j.value("build_seconds", 0.0);
    row.exit_code = j.value("exit_code", -1);
    row.check_seconds = j.value("check_seconds", 0.0);
    row.problem = j.value("problem", "");
    if (row.built && row.problem.empty()) {
      std::ifstream f(fs::path(report_dir) / impls[i].name / "verdicts.json");
      try {
        row.report = json::parse(f);
      } catch (const std::exception& e) {
        row.problem = std::string("its report cannot be read: ") + e.what();
      }
    }
    rows.push_back(row);
  }

  // What a merge needs to rebuild the summary: the rows, with the class and the shard they belong to.
  json shard;
  shard["format"] = "geomech-class-shard 1";
  shard["class"] = o.dir;
  shard["implementations"] = all_impls.size();
  shard["shard"] = {o.shard_k, o.shard_n};
  shard["rows"] = json::array();
  for (const auto& row : rows)
    shard["rows"].push_back({{"name", row.impl.name}, {"source", row.impl.source}, {"built", row.built},
                             {"build_message", row.build_message}, {"build_seconds", row.build_seconds},
                             {"exit_code", row.exit_code}, {"check_seconds", row.check_seconds},
                             {"problem", row.problem}});
  write_file_atomically((fs::path(report_dir) / "class-shard.json").string(), shard.dump(1));
  if (o.shard_n > 1)
    std::cerr << "geomech check-class: shard " << o.shard_k << "/" << o.shard_n << " written to " << report_dir
              << "; combine the shards with `geomech merge-class OUT SHARD_DIR...`\n";
  return summarise_class(o.dir, rows, report_dir);
}

int merge_class(const std::vector<std::string>& shard_dirs, const std::string& out_dir) {
  if (shard_dirs.empty()) throw std::runtime_error("merge-class: no shard folders given");
  std::vector<Row> rows;
  std::string klass;
  std::size_t total = 0;
  int n = 0;
  std::set<int> seen;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + out_dir + ": " + ec.message());
  for (const auto& dir : shard_dirs) {
    const fs::path file = fs::path(dir) / "class-shard.json";
    std::ifstream f(file);
    if (!f) throw std::runtime_error(file.string() + ": no shard result here (run check-class --shard K/N first)");
    json j;
    try {
      j = json::parse(f);
      if (j.at("format") != "geomech-class-shard 1") throw std::runtime_error("unknown format");
    } catch (const std::exception& e) {
      throw std::runtime_error(file.string() + ": not a class shard result (" + e.what() + ")");
    }
    const int k = j.at("shard").at(0), nn = j.at("shard").at(1);
    if (n == 0) {
      n = nn;
      klass = j.at("class");
      total = j.at("implementations");
    } else if (nn != n || j.at("class") != klass) {
      throw std::runtime_error(file.string() + ": shard " + std::to_string(k) + "/" + std::to_string(nn) + " of " +
                               j.at("class").get<std::string>() + " does not belong with shards of " +
                               std::to_string(n) + " of " + klass);
    }
    if (!seen.insert(k).second) throw std::runtime_error(file.string() + ": shard " + std::to_string(k) + " given twice");
    for (const auto& r : j.at("rows")) {
      Row row;
      row.impl = {r.at("name"), r.at("source")};
      row.built = r.at("built");
      row.build_message = r.at("build_message");
      row.build_seconds = r.at("build_seconds");
      row.exit_code = r.at("exit_code");
      row.check_seconds = r.at("check_seconds");
      row.problem = r.at("problem");
      const fs::path report = fs::path(dir) / row.impl.name;
      if (row.built && row.problem.empty()) {
        std::ifstream rf(report / "verdicts.json");
        try {
          row.report = json::parse(rf);
        } catch (const std::exception& e) {
          row.problem = std::string("its report cannot be read: ") + e.what();
        }
      }
      if (fs::exists(report) && fs::absolute(report) != fs::absolute(fs::path(out_dir) / row.impl.name)) {
        fs::remove_all(fs::path(out_dir) / row.impl.name, ec);
        fs::copy(report, fs::path(out_dir) / row.impl.name, fs::copy_options::recursive, ec);
        if (ec) throw std::runtime_error("cannot copy " + report.string() + " into " + out_dir + ": " + ec.message());
      }
      rows.push_back(std::move(row));
    }
  }
  if (static_cast<int>(seen.size()) != n) {
    std::string missing;
    for (int k = 1; k <= n; ++k)
      if (!seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    throw std::runtime_error("merge-class: shards " + missing + " of " + std::to_string(n) + " are missing");
  }
  if (rows.size() != total)
    throw std::runtime_error("merge-class: the shards hold " + std::to_string(rows.size()) + " implementations, the class " +
                             std::to_string(total));
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.impl.name < b.impl.name; });
  return summarise_class(klass, rows, out_dir);
}

}  // namespace gm::harness
