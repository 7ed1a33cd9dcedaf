#include "harness/class/autograder.hpp"
#include "harness/languages/language.hpp"

#include "core/data_path.hpp"
#include "core/subject.hpp"
#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/reports/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* kConfigName = "geomech-autograder.json";
const char* kConfigFormat = "geomech-autograder 1";

// A score as the platforms show it: 4 decimals are enough, and 0.1 + 0.2 reads as 0.3.
double rounded(double x) { return std::round(x * 1e4) / 1e4; }

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// At most `max` bytes of `text`: its beginning and its end, the cut said in the middle.
std::string keep_ends(const std::string& text, std::size_t max) {
  if (text.size() <= max) return text;
  const std::string mark = "\n\n[... " + std::to_string(text.size() - max) +
                           " bytes of the report left out here; the "
                           "whole report is report.md ...]\n\n";
  std::size_t head = (max - mark.size()) * 2 / 3, tail = max - mark.size() - head;
  while (head > 0 && (static_cast<unsigned char>(text[head]) & 0xC0) == 0x80) --head;
  std::size_t from = text.size() - tail;
  while (from < text.size() && (static_cast<unsigned char>(text[from]) & 0xC0) == 0x80) ++from;
  return text.substr(0, head) + mark + text.substr(from);
}

const SlotInfo* slot_info(const std::string& name) {
  for (const auto& s : subject_slots())
    if (name == s.name) return &s;
  return nullptr;
}

// "slot casimir: c(Pi) = |Pi|^2/2 ((2.27), sec. 3.3)"
// What the compiler said, as a student sees it: the line naming the grader's own log file (a path
// of the grading machine the student cannot open) left out; the lecturer's summary keeps it.
std::string for_student(const std::string& build_message) {
  std::string out;
  std::istringstream in(build_message);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("the compiler's full output: ", 0) != 0) out += line + "\n";
  return out;
}

std::string item_title(const ScoreItem& i) {
  switch (i.kind) {
    case ScoreItem::Kind::Slot: {
      const SlotInfo* s = slot_info(i.name);
      if (!s) return "slot " + i.name;
      // The place in its parentheses once: "(2.11)" is already parenthesised, "Remark 2.1" is not.
      const std::string place = s->place;
      const bool wrapped = !place.empty() && place.front() == '(' && place.back() == ')';
      return "slot " + i.name + ": " + s->meaning + " " + (wrapped ? place : "(" + place + ")");
    }
    case ScoreItem::Kind::Area:
      return "area " + i.name + ": the checks of this part of the notes";
    case ScoreItem::Kind::Claim:
      return i.name == "claims" ? std::string("integrator claims") : "claim: integrator " + i.name;
  }
  return i.name;
}

// The check that shows a wrong slot, with its replay command, from the record.
std::string replay_of(const StudentView& s, const std::string& slot) {
  for (const auto& f : s.row->report.value("first_fix", json::array())) {
    if (f.value("slot", "") != slot) continue;
    for (const auto& v : s.row->report.value("verdicts", json::array()))
      if (v.value("property", "") == f.value("property", "") && v.value("scalar", "") == f.value("scalar", "") &&
          v.contains("reproduce_command"))
        return v["reproduce_command"].get<std::string>();
  }
  return "";
}

// What one item says to the student, in words.
std::string item_output(const StudentView& s, const ScoreItem& i) {
  if (s.status != "checked")
    return "not graded: " + s.status + (s.graded.first_fix.empty() ? "" : " (" + s.graded.first_fix + ")");
  std::ostringstream os;
  if (i.kind == ScoreItem::Kind::Slot) {
    if (i.state == "correct") {
      os << "correct: every check that calls it passes";
      const json ex = s.row->report.value("exercised", json::object());
      if (ex.contains(i.name)) {
        os << " (";
        bool first = true;
        for (const auto& p : ex[i.name]) os << (first ? "" : ", ") << p.get<std::string>(), first = false;
        os << ")";
      }
    } else if (i.state == "wrong") {
      os << i.detail;
      const std::string replay = replay_of(s, i.name);
      if (!replay.empty()) os << "\nReplay this failure: " << replay;
    } else if (i.state == "missing") {
      std::string flags;  // the listings of the table's other languages: --python, --octave
      for (const auto& l : languages())
        if (l.signature && &l != &suite_language()) flags += (flags.empty() ? "--" : ", --") + l.id;
      os << "not provided: your submission has no function '" << i.name
         << "' (`geomech slots` lists each slot's name and signature; " << flags << " for yours)";
    } else {
      os << i.state << ": " << i.detail;
    }
  } else if (i.kind == ScoreItem::Kind::Area) {
    os << i.state << (i.detail.empty() ? "" : "; " + i.detail);
  } else {
    os << (i.name == "claims" ? "no integrator claims were made, so none earned credit" : i.state);
  }
  return os.str();
}

bool passed(const ScoreItem& i) {
  return i.kind == ScoreItem::Kind::Slot ? i.state == "correct" : i.points >= i.max_points - 1e-9 && i.max_points > 0;
}

// The words at the top of every platform's output: the result, the grade, what is wrong, the first fix.
std::string summary_text(const StudentView& s) {
  std::ostringstream os;
  const auto words = words_of(s);
  for (std::size_t i = 0; i < words.size(); ++i) os << (i ? "\n" : "") << words[i];
  if (s.status == "checked") {
    const std::string prefix = s.row->report.value("reproduce_prefix", "");
    if (!prefix.empty()) os << "\nCheck it yourself: " << prefix;
  }
  return os.str();
}

// Hidden tests (the rubric's "visibility"): the most withheld level among the grade's items, "" when
// every item is visible. The whole report and the overall words name every check, so they are
// withheld as long as the most withheld item is.
std::string withheld_level(const StudentView& s) {
  int most = 0;
  for (const auto& i : s.score.items)
    for (int k = 1; k < static_cast<int>(kVisibilityLevels.size()); ++k)
      if (i.visibility == kVisibilityLevels[k]) most = std::max(most, k);
  return most == 0 ? "" : kVisibilityLevels[most];
}

std::string withheld_until(const std::string& level) {
  if (level == "after_due_date") return "until after the due date";
  if (level == "after_published") return "until the grades are published";
  return "from students";
}

// The overall words when some tests are hidden: only what the visible tests say, and how many are not
// shown (their points count in the score). Nothing here names a hidden slot or claim, and no first fix
// or replay command of the whole check is given (either could be a hidden test's).
std::string shown_summary(const StudentView& s, const std::string& level) {
  if (s.status != "checked") return summary_text(s);
  int shown = 0, shown_passed = 0, hidden = 0;
  double points = 0, max_points = 0;
  const ScoreItem* first_wrong = nullptr;
  for (const auto& i : s.score.items) {
    if (i.visibility != "visible") {
      ++hidden;
      continue;
    }
    ++shown, points += i.points, max_points += i.max_points;
    if (passed(i))
      ++shown_passed;
    else if (!first_wrong && i.kind == ScoreItem::Kind::Slot && i.state == "wrong")
      first_wrong = &i;
  }
  std::ostringstream os;
  os << "The tests shown now: " << shown_passed << " of " << shown << " passed (" << format_points(points) << " of "
     << format_points(max_points) << " points).\n"
     << hidden << (hidden == 1 ? " test is" : " tests are") << " hidden " << withheld_until(level) << "; "
     << (hidden == 1 ? "it counts" : "they count") << " in the score.";
  if (first_wrong) os << "\nFirst fix among the tests shown: " << first_wrong->name << ": " << first_wrong->detail;
  return os.str();
}

void write_text(const fs::path& p, const std::string& text, bool executable = false) {
  write_file_atomically(p.string(), text);
  if (executable)
    fs::permissions(p, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                           fs::perms::others_exec);
}

std::string json_text(const json& j) { return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n"; }

}  // namespace

Platform platform_from_name(const std::string& name) {
  if (name == "gradescope") return Platform::gradescope;
  if (name == "prairielearn") return Platform::prairielearn;
  throw std::runtime_error("unknown platform '" + name + "': expected gradescope or prairielearn");
}

std::string platform_name(Platform p) { return p == Platform::gradescope ? "gradescope" : "prairielearn"; }

json gradescope_results(const StudentView& s, const std::string& report_md) {
  json tests = json::array();
  for (const auto& i : s.score.items) {
    tests.push_back({{"name", item_title(i)},
                     {"score", rounded(i.points)},
                     {"max_score", rounded(i.max_points)},
                     {"status", passed(i) ? "passed" : "failed"},
                     {"output", item_output(s, i)},
                     {"output_format", "text"},
                     {"visibility", i.visibility}});
  }
  const std::string withheld = withheld_level(s);
  if (s.status == "does not compile")
    tests.push_back({{"name", "it compiles"},
                     {"status", "failed"},
                     {"output", keep_ends(for_student(s.row->build_message), 60000)},
                     {"output_format", "text"},
                     {"visibility", "visible"}});
  if (!report_md.empty())
    tests.push_back({{"name", "the whole report (report.md)"},
                     {"status", s.result == "PASS" ? "passed" : "failed"},
                     {"output", keep_ends(report_md, 200000)},
                     {"output_format", "md"},
                     {"visibility", withheld.empty() ? "visible" : withheld}});
  json out;
  out["score"] = s.score.points;
  out["output"] = withheld.empty() ? summary_text(s) : shown_summary(s, withheld);
  out["output_format"] = "text";
  out["visibility"] = "visible";
  out["stdout_visibility"] = "hidden";  // the console names the grader's folders; the student's output is above
  out["execution_time"] = static_cast<long>(std::lround(s.row->build_seconds + s.row->check_seconds));
  out["tests"] = tests;
  return out;
}

json prairielearn_results(const StudentView& s, const std::string& report_md) {
  json out;
  const bool gradable = s.status == "checked";
  out["gradable"] = gradable;
  // Not gradable has no score to say (PrairieLearn records none): the result and why, not "0.00 of 100".
  std::string message = gradable ? s.result + ", " + s.score.headline : s.result + ": not graded";
  if (!s.graded.first_fix.empty()) message += ". First fix: " + s.graded.first_fix;
  out["message"] = message;
  if (!gradable) {
    // Not the student's attempt's fault to count: a file that does not compile (the compiler's
    // message says why), or a check that could not run.
    json errors = json::array();
    errors.push_back(s.status + (s.graded.first_fix.empty() ? "" : ": " + s.graded.first_fix));
    if (s.status == "does not compile") errors.push_back(keep_ends(for_student(s.row->build_message), 60000));
    if (s.status == "not checked") errors.push_back(keep_ends(s.row->problem, 60000));
    out["format_errors"] = errors;
    out["output"] = summary_text(s);
    return out;
  }
  out["score"] = s.score.max_points > 0 ? std::clamp(s.score.points / s.score.max_points, 0.0, 1.0) : 0.0;
  // PrairieLearn's results have no visibility per test (AUTOGRADERS.md): a test not visible is left
  // out, its points in the score, and the whole report with it.
  const std::string withheld = withheld_level(s);
  if (withheld.empty())
    out["output"] = keep_ends(summary_text(s) + (report_md.empty() ? "" : "\n\n" + report_md), 400000);
  else
    out["output"] = shown_summary(s, withheld),
    out["message"] =
        s.score.headline.substr(0, s.score.headline.find(':')) + "; some tests are hidden " + withheld_until(withheld);
  json tests = json::array();
  int hidden = 0;
  double hidden_points = 0, hidden_max = 0;
  for (const auto& i : s.score.items) {
    if (i.visibility != "visible") {
      ++hidden, hidden_points += i.points, hidden_max += i.max_points;
      continue;
    }
    std::string description;
    if (i.kind == ScoreItem::Kind::Slot)
      if (const SlotInfo* si = slot_info(i.name)) description = std::string(si->meaning) + " (" + si->place + ")";
    tests.push_back({{"name", i.kind == ScoreItem::Kind::Slot ? i.name : item_title(i)},
                     {"description", description},
                     {"points", rounded(i.points)},
                     {"max_points", rounded(i.max_points)},
                     {"message", i.state},
                     {"output", item_output(s, i)}});
  }
  // Their points in one row, named by no slot: the score shows them anyway (score minus the rows shown).
  if (hidden > 0)
    tests.push_back(
        {{"name", std::to_string(hidden) + (hidden == 1 ? " test" : " tests") + " hidden " + withheld_until(withheld)},
         {"description", "counted in the score; shown when the lecturer releases them"},
         {"points", rounded(hidden_points)},
         {"max_points", rounded(hidden_max)},
         {"message", ""},
         {"output", ""}});
  out["tests"] = tests;
  return out;
}

std::string lay_out_submission(const std::string& submission, const std::string& class_dir) {
  std::error_code ec;
  fs::path root = submission;
  if (!fs::is_directory(fs::symlink_status(root, ec)))
    throw std::runtime_error("the submission folder " + submission + " is missing (or not a folder)");
  auto entries = [](const fs::path& dir) {
    std::vector<fs::path> out;
    std::error_code e;
    for (const auto& x : fs::directory_iterator(dir, e)) {
      const std::string n = x.path().filename().string();
      if (n.empty() || n[0] == '.' || n == "__MACOSX" || n == "__pycache__") continue;
      out.push_back(x.path());
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  // A folder uploaded whole (a zip of one folder) is read inside.
  for (int depth = 0; depth < 2; ++depth) {
    const auto top = entries(root);
    if (top.size() == 1 && fs::is_directory(fs::symlink_status(top[0], ec))) root = top[0];
  }
  // The files of each language at the top of the submission (harness/languages/language.hpp).
  std::map<const Language*, std::vector<fs::path>> files;
  for (const auto& e : entries(root))
    if (const Language* l = language_of_extension(e.extension().string())) files[l].push_back(e);
  fs::create_directories(class_dir, ec);
  auto copy_folder = [&](const fs::path& to) {
    fs::create_directories(to, ec);
    for (const auto& e : entries(root)) {
      // Links stay links: the class run refuses them rather than anything reading through them.
      fs::copy(e, to / e.filename(), fs::copy_options::copy_symlinks | fs::copy_options::recursive, ec);
      if (ec) throw std::runtime_error("cannot copy " + e.string() + ": " + ec.message());
    }
  };
  // Function files (.m) beside a file of another language are that language's material: the one
  // other language is the submission.
  std::vector<const Language*> present;
  for (const auto& [l, f] : files)
    if (!l->folder_of_files) present.push_back(l);
  if (present.empty())
    for (const auto& [l, f] : files) present.push_back(l);
  if (present.size() == 1) {
    const Language* l = present.front();
    const auto& mine = files[l];
    if (mine.size() == 1) {
      const std::string name = mine[0].stem().string();
      if (l->files_beside) {  // a C++ file with its headers
        copy_folder(fs::path(class_dir) / name);
        return name;
      }
      fs::copy(mine[0], fs::path(class_dir) / mine[0].filename(), fs::copy_options::copy_symlinks, ec);
      if (ec) throw std::runtime_error("cannot copy " + mine[0].string() + ": " + ec.message());
      return name;
    }
    if (l->folder_of_files) {
      copy_folder(fs::path(class_dir) / "submission");  // one function per file
      return "submission";
    }
  }
  std::ostringstream why;
  why << "the submission holds ";
  std::vector<std::string> counts, expected;
  for (const auto& l : languages()) {
    for (const auto& ext : l.extensions) {
      std::size_t k = 0;
      for (const auto& f : files[&l]) k += f.extension() == ext;
      counts.push_back(std::to_string(k) + " " + ext);
    }
    std::string exts;
    for (const auto& ext : l.extensions) exts += (exts.empty() ? "" : " or ") + ext;
    std::string one = "one " + exts + " file";
    if (!l.marker.empty()) one += " using " + l.marker.substr(0, l.marker.find('('));
    if (l.files_beside) one += " (with its headers beside it)";
    if (l.folder_of_files)
      one =
          l.name + ": " + one + ", or a folder of function files (one function per " + l.extensions.front() + " file)";
    expected.push_back(one);
  }
  for (std::size_t i = 0; i < counts.size(); ++i)
    why << (i == 0 ? "" : i + 1 == counts.size() ? " and " : ", ") << counts[i];
  why << " files; expected ";
  for (std::size_t i = 0; i < expected.size(); ++i)
    why << (i == 0 ? "" : i + 1 == expected.size() ? ", or " : ", ") << expected[i];
  throw std::runtime_error(why.str());
}

int grade_submission(const GradeSubmissionOptions& o) {
  const json config = json::parse(read_text(o.config));
  if (config.value("format", "") != kConfigFormat)
    throw std::runtime_error(o.config + ": not an autograder configuration written by `geomech autograder`");
  const Rubric rubric =
      parse_rubric(config.at("rubric").get<std::string>(), config.value("rubric_source", "rubric.json"));
  std::string work = o.work;
  struct Scratch {  // a work folder of its own is removed at the end, whatever happens
    std::string path;
    ~Scratch() {
      std::error_code ec;
      if (!path.empty()) fs::remove_all(path, ec);
    }
  } scratch;
  if (work.empty()) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/geomech-grade-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a scratch folder in " + pattern);
    work = pattern;
    scratch.path = work;
  }
  const fs::path class_dir = fs::path(work) / "class", report_dir = fs::path(work) / "report";
  std::error_code ec;
  fs::create_directories(fs::path(o.results).parent_path(), ec);
  auto write_results = [&](const json& j) {
    write_file_atomically(o.results, json_text(j));
    std::cout << "geomech grade-submission: " << o.results << " written\n";
  };
  std::vector<ClassRow> rows(1);
  std::string name;
  try {
    name = lay_out_submission(o.submission, class_dir.string());
  } catch (const std::exception& e) {
    // Nothing to check: said as a problem of the submission, with what is expected.
    rows[0].name = "submission";
    rows[0].problem = std::string("nothing to check: ") + e.what();
  }
  std::string report_md;
  if (!name.empty()) {
    const fs::path self = fs::read_symlink("/proc/self/exe");
    std::vector<std::string> argv{self.string(),
                                  "check-class",
                                  class_dir.string(),
                                  "--report",
                                  report_dir.string(),
                                  "--parallel",
                                  "1",
                                  "--timeout-per-implementation",
                                  std::to_string(config.value("timeout", 540.0))};
    if (config.value("trusted", false)) argv.push_back("--trusted");
    // With the rubric, so that the instructor's log says the grade results.json gives.
    const fs::path rubric_file = fs::path(work) / "rubric.json";
    write_file_atomically(rubric_file.string(), config.at("rubric").get<std::string>());
    argv.insert(argv.end(), {"--rubric", rubric_file.string()});
    for (const auto& a : config.value("check_args", json::array())) argv.push_back(a.get<std::string>());
    std::cout << "geomech grade-submission: " << shell_join(argv) << "\n" << std::flush;
    const fs::path log = fs::path(work) / "check-class.log";
    const ProcessResult pr = run_process(ProcessSpec{argv, log.string(), false});
    std::cout << read_text(log) << std::flush;
    if (auto row = read_class_row(report_dir.string(), name)) {
      rows[0] = *row;
      if (grader_fault_of(rows[0]).empty()) report_md = read_text(report_dir / name / "report.md");
    } else {
      // No row: the class check refused before checking anyone (the grader's machine, exit 3, or
      // its own set-up): never the student's.
      rows[0].name = name;
      rows[0].machine_fault = "the class check left no result (exit status " + std::to_string(pr.exit_code) +
                              "): " + keep_ends(read_text(log), 4000);
    }
  }
  const ClassView view = decide_class(rows, rubric);
  const StudentView& s = view.students.front();
  if (s.status == kGraderError) {
    // The grading machine's failure is the platform's grader error, never a score: no results file
    // and a failing exit (Gradescope: "The autograder failed to execute correctly"; PrairieLearn: the
    // grading job failed). The instructor's log says what and the fix.
    std::error_code gone;
    fs::remove(o.results, gone);
    std::cout << "geomech grade-submission: GRADER ERROR, no results written (the grading machine, not the "
                 "submission): "
              << grader_fault_of(*s.row) << "\n";
    return kExitMachine;
  }
  write_results(o.platform == Platform::gradescope ? gradescope_results(s, report_md)
                                                   : prairielearn_results(s, report_md));
  std::cout << "geomech grade-submission: " << s.result << ", " << s.score.headline << "\n";
  return 0;
}

namespace {

// Packs the suite's source tree into the tarball the grader builds it from.
void pack_suite_source(const fs::path& src, const fs::path& tarball) {
  const ProcessResult tar =
      run_process(ProcessSpec{{"tar", "-czf", tarball.string(), "-C", src.string(), "--exclude=./build*",
                               "--exclude=./.git", "--exclude=./geomech-reports", "--exclude=__pycache__", "."},
                              "",
                              false});
  if (tar.exit_code != 0) throw std::runtime_error("tar could not pack " + src.string() + ": " + tar.output);
}

// Gradescope's two scripts: setup.sh, which builds the suite in the image, and run_autograder,
// which grades one submission.
void write_gradescope_scripts(const AutograderOptions& o, const fs::path& out) {
  write_text(out / "setup.sh",
             "#!/usr/bin/env bash\n"
             "# Gradescope runs this once, as root, when it builds the autograder's image\n"
             "# (gradescope-autograders.readthedocs.io/en/latest/specs/). Written by `geomech autograder gradescope`.\n"
             "# It unpacks the suite and builds it with its own front door, which installs the Debian packages the\n"
             "# suite needs (apt-get) and nothing from anywhere else.\n"
             "set -euo pipefail\n"
             "here=$(cd \"$(dirname \"${BASH_SOURCE[0]}\")\" && pwd)\n"
             "mkdir -p /opt/geomech-spec\n"
             "tar -xzf \"$here/geomech-src.tar.gz\" -C /opt/geomech-spec\n"
             "cd /opt/geomech-spec\n"
             "GEOMECH_JOBS=$(nproc) ./geomech build\n"
             "ln -sf /opt/geomech-spec/build/bin/geomech /usr/local/bin/geomech\n"
             "geomech slots >/dev/null  # the tool runs\n"
             "# The grader's machine, tried as a submission's check needs it (the sandbox, the cache, Python):\n"
             "# a container that cannot run the sandbox fails here, with the fix, instead of grading anyone 0.\n"
             "geomech self-test" +
                 std::string(o.trusted ? " --trusted" : "") + "\n",
             true);
  write_text(out / "run_autograder",
             "#!/usr/bin/env bash\n"
             "# Gradescope runs this for every submission, from /autograder: the student's files are in\n"
             "# /autograder/submission, and /autograder/results/results.json is what Gradescope shows\n"
             "# (gradescope-autograders.readthedocs.io/en/latest/specs/). Written by `geomech autograder gradescope`.\n"
             "# GEOMECH_AUTOGRADER_ROOT (default /autograder) and GEOMECH (default: geomech on PATH) are for\n"
             "# trying it outside Gradescope.\n"
             "set -u\n"
             "root=${GEOMECH_AUTOGRADER_ROOT:-/autograder}\n"
             "mkdir -p \"$root/results\"\n"
             "exec \"${GEOMECH:-geomech}\" grade-submission gradescope --submission \"$root/submission\" \\\n"
             "  --results \"$root/results/results.json\" --config \"$root/source/" +
                 std::string(kConfigName) + "\"\n",
             true);
}

// PrairieLearn's external grader: its run.sh, the Dockerfile of its image and the question's info.json.
void write_prairielearn_files(const AutograderOptions& o, const fs::path& out, const fs::path& code_dir) {
  write_text(code_dir / "run.sh",
             "#!/usr/bin/env bash\n"
             "# PrairieLearn's external grader runs this in the image built from ../../Dockerfile: the student's\n"
             "# files are in /grade/student, and /grade/results/results.json is what PrairieLearn records\n"
             "# (prairielearn.readthedocs.io, External Grading). Written by `geomech autograder prairielearn`.\n"
             "# GEOMECH_GRADER_ROOT (default /grade) and GEOMECH (default: geomech on PATH) are for trying it\n"
             "# outside PrairieLearn.\n"
             "set -u\n"
             "root=${GEOMECH_GRADER_ROOT:-/grade}\n"
             "mkdir -p \"$root/results\"\n"
             "exec \"${GEOMECH:-geomech}\" grade-submission prairielearn --submission \"$root/student\" \\\n"
             "  --results \"$root/results/results.json\" --config \"$root/serverFilesCourse/geomech/" +
                 std::string(kConfigName) + "\"\n",
             true);
  write_text(out / "Dockerfile",
             "# The external grader's image: Debian 12 with the suite built by its own front door.\n"
             "#   docker build -t YOUR_REGISTRY/geomech-grader . && docker push YOUR_REGISTRY/geomech-grader\n"
             "FROM debian:12\n"
             "COPY geomech-src.tar.gz /tmp/\n"
             "RUN apt-get update && apt-get install -y --no-install-recommends ca-certificates && \\\n"
             "    mkdir -p /opt/geomech-spec && tar -xzf /tmp/geomech-src.tar.gz -C /opt/geomech-spec && \\\n"
             "    cd /opt/geomech-spec && ./geomech build && \\\n"
             "    ln -s /opt/geomech-spec/build/bin/geomech /usr/local/bin/geomech && rm /tmp/geomech-src.tar.gz\n");
  json info;
  info["externalGradingOptions"] = {{"enabled", true},
                                    {"image", "YOUR_REGISTRY/geomech-grader"},
                                    {"serverFilesCourse", {"geomech/"}},
                                    {"entrypoint", "/grade/serverFilesCourse/geomech/run.sh"},
                                    {"timeout", std::min(600.0, o.timeout_seconds + 60)}};
  write_text(out / "info.json", json_text(info));
}

// The autograder folder's README.md: what wrote it, how it checks and grades, and how to install it.
void write_autograder_readme(const AutograderOptions& o, const fs::path& out, bool gs, const std::string& check_line,
                             const std::string& rubric_source, std::size_t assignment_slots) {
  std::ostringstream readme;
  readme << "# A geomech autograder for " << (gs ? "Gradescope" : "PrairieLearn") << "\n\n"
         << "Written by `geomech autograder " << platform_name(o.platform)
         << "` (docs/AUTOGRADERS.md). Every submission is "
         << "checked " << (o.trusted ? "in-process (--trusted: a submission can forge its own verdicts)" : "sandboxed")
         << " with the options `" << check_line << " ` and graded by the rubric `" << rubric_source
         << "` (its assignment: " << assignment_slots << " slots).\n\n";
  if (gs)
    readme << "Upload `" << out.filename().string()
           << ".zip` (setup.sh, run_autograder and the rest at its root) as the "
           << "assignment's autograder. `setup.sh` builds the suite from `geomech-src.tar.gz` with its Debian "
           << "packages (about 7 minutes on 2 cores).\n";
  else
    readme << "Build the image from `Dockerfile`, copy `serverFilesCourse/geomech/` into your course's "
           << "`serverFilesCourse/`, and give each question the `externalGradingOptions` of `info.json` with your "
           << "image's name.\n";
  write_text(out / "README.md", readme.str());
}

// The zip to upload to Gradescope, beside the autograder folder.
void write_gradescope_zip(const fs::path& out) {
  // Gradescope wants the files at the zip's root; Python's zipfile keeps their modes (run_autograder
  // stays executable).
  const fs::path zip = out.parent_path() / (out.filename().string() + ".zip");
  std::error_code ec;
  fs::remove(zip, ec);
  std::vector<std::string> argv{"python3", "-m", "zipfile", "-c", zip.string()};
  for (const char* f : {"setup.sh", "run_autograder", kConfigName, "geomech-src.tar.gz", "README.md"})
    argv.push_back((out / f).string());
  const ProcessResult z = run_process(ProcessSpec{argv, "", false});
  if (z.exit_code != 0) throw std::runtime_error("could not write " + zip.string() + ": " + z.output);
  std::cout << "autograder: " << zip.string() << " (upload it to Gradescope)\n";
}

}  // namespace

int write_autograder(const AutograderOptions& o) {
  if (o.rubric_file.empty())
    throw std::runtime_error(
        "an autograder needs --rubric FILE.json with an \"assignment\": it grades one submission at a "
        "time, so there is no class to learn the assignment from (docs/GRADEBOOK.md)");
  const std::string rubric_text = read_text(o.rubric_file);
  const Rubric rubric = parse_rubric(rubric_text, fs::path(o.rubric_file).filename().string());
  if (!rubric.assignment)
    throw std::runtime_error("rubric \"" + o.rubric_file +
                             "\": an autograder needs its \"assignment\" (the slots the "
                             "assignment asks for): one submission is graded at a time, so there is no class to learn "
                             "them from");
  const fs::path src =
      o.source_dir.empty() ? fs::path(suite_data_path("geomech")).parent_path() : fs::path(o.source_dir);
  std::error_code ec;
  if (!fs::exists(src / "geomech", ec) || !fs::exists(src / "CMakeLists.txt", ec))
    throw std::runtime_error("the suite's source tree is not at " + src.string() +
                             " (an autograder packs it, to build the suite where it runs); give --source DIR");
  const fs::path out = fs::absolute(o.out_dir).lexically_normal();
  if (fs::exists(out, ec) && !fs::is_empty(out, ec) && !fs::exists(out / "README.md", ec))
    throw std::runtime_error("refusing to write into " + out.string() +
                             ": it is not empty and not an autograder folder");
  fs::remove_all(out, ec);
  const bool gs = o.platform == Platform::gradescope;
  const fs::path code_dir = gs ? out : out / "serverFilesCourse" / "geomech";
  fs::create_directories(code_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + code_dir.string() + ": " + ec.message());

  json config;
  config["format"] = kConfigFormat;
  config["platform"] = platform_name(o.platform);
  config["rubric"] = rubric_text;
  config["rubric_source"] = fs::path(o.rubric_file).filename().string();
  config["check_args"] = o.check_args;
  config["trusted"] = o.trusted;
  config["timeout"] = o.timeout_seconds;
  write_text(code_dir / kConfigName, json_text(config));

  // The suite's source, to be built where the grader runs (Debian packages only, by ./geomech).
  const fs::path tarball = (gs ? out : out) / "geomech-src.tar.gz";
  pack_suite_source(src, tarball);

  std::string check_line;
  for (const auto& a : o.check_args) check_line += " " + shell_quote(a);
  if (gs) {
    write_gradescope_scripts(o, out);
  } else {
    write_prairielearn_files(o, out, code_dir);
  }
  write_autograder_readme(o, out, gs, check_line, config["rubric_source"].get<std::string>(),
                          rubric.assignment->size());

  if (gs && o.zip) write_gradescope_zip(out);
  std::cout << "autograder: " << out.string() << " (" << platform_name(o.platform) << "; rubric "
            << config["rubric_source"].get<std::string>() << ", " << rubric.assignment->size()
            << " slots in the assignment; checks:" << (check_line.empty() ? " the whole check" : check_line) << ")\n";
  return 0;
}

}  // namespace gm::harness
