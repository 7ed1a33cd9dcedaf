#include "harness/class/class_mode.hpp"
#include "harness/class/class_console.hpp"
#include "harness/class/class_html.hpp"
#include "harness/class/class_record.hpp"
#include "harness/class/feedback_files.hpp"
#include "harness/class/gradebook.hpp"
#include "harness/class/grader_machine.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/submission_intake.hpp"
#include "harness/languages/language.hpp"
#include "harness/remote/remote_subject.hpp"
#include "harness/remote/slot_names.hpp"
#include "harness/submissions/check_submission.hpp"

#include "harness/isolation/isolate.hpp"
#include "harness/isolation/process.hpp"
#include "harness/reports/report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The problem of a submission refused before anything of it was checked.
const std::string kNotRead = "the submission was not read: ";

struct Row {
  Implementation impl;
  bool built = false;
  std::string build_message;
  double build_seconds = 0;
  int exit_code = -1;
  double check_seconds = 0;
  std::string problem;        // the check program itself failed to run properly
  std::string machine_fault;  // the grader's machine or set-up failed it (ClassRow::machine_fault)
  json report;                // verdicts.json
  // The machine's faults of the runs before, of this same submission (ClassRow::earlier_faults),
  // and whether the lecturer is asked to decide (ClassRow::suspect).
  std::vector<std::string> earlier_faults;
  bool suspect = false;
};

// A row as class-shard.json and class-row.json keep it (its report is read from its folder).
json row_json(const Row& row) {
  return {{"name", row.impl.name},
          {"source", row.impl.source},
          {"built", row.built},
          {"build_message", row.build_message},
          {"build_seconds", row.build_seconds},
          {"exit_code", row.exit_code},
          {"check_seconds", row.check_seconds},
          {"problem", row.problem},
          {"machine_fault", row.machine_fault},
          {"earlier_faults", row.earlier_faults},
          {"suspect", row.suspect}};
}

// The row back, with the report of a checked implementation read from `reports`/<name>.
Row row_from_json(const json& r, const fs::path& reports) {
  Row row;
  row.impl.name = r.at("name");
  row.impl.source = r.at("source");

  row.built = r.at("built");
  row.build_message = r.at("build_message");
  row.build_seconds = r.at("build_seconds");
  row.exit_code = r.at("exit_code");
  row.check_seconds = r.at("check_seconds");
  row.problem = r.at("problem");
  row.machine_fault = r.value("machine_fault", "");
  row.earlier_faults = r.value("earlier_faults", std::vector<std::string>{});
  row.suspect = r.value("suspect", false);
  if (row.built && row.problem.empty() && row.machine_fault.empty()) {
    // A name from a file (a shard, a kept row) names a folder here only when it could name one.
    if (const std::string why = bad_implementation_name(row.impl.name); !why.empty())
      throw std::runtime_error("a class result names an implementation '" + inert_text(row.impl.name) + "': " + why);
    std::ifstream f(reports / row.impl.name / "verdicts.json");
    try {
      row.report = json::parse(f);
    } catch (const std::exception& e) {
      row.problem = std::string("its report cannot be read: ") + e.what();
    }
  }
  return row;
}

// What a check of an implementation depends on, as a fingerprint (FNV-1a, 64 bits): its source
// (the file, or every file of its folder, by name and content), the options it is checked with and
// the suite itself (this program's bytes). Equal fingerprints: the same check would run again.
struct Fingerprint {
  std::uint64_t h = 14695981039346656037ull;
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;  // a separator, so that ("ab", "c") differs from ("a", "bc")
  }
  void add_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream os;
    os << f.rdbuf();
    add(os.str());
  }
  // A submission's snapshot: every path and its bytes (harness/isolation/submission_intake.hpp).
  void add_tree(const SubmissionTree& t) {
    for (const auto& [path, text] : t.files) {
      add(path);
      add(text);
    }
  }
  std::string hex() const {
    std::ostringstream os;
    os << std::hex << std::setw(16) << std::setfill('0') << h;
    return os.str();
  }
};

// The language of a submission by its place in the class folder: its extension, or a folder of
// function files (an origin without one).
const Language* language_of_origin(const std::string& origin) {
  if (const Language* l = language_of_extension(fs::path(origin).extension().string())) return l;
  for (const auto& f : languages())
    if (f.folder_of_files) return &f;
  return nullptr;
}

}  // namespace

std::string check_conditions(const ClassOptions& o, const std::string& extension) {
  std::string text = o.untrusted ? "untrusted" : "trusted";
  for (const auto& a : to_args(o.check)) text += '\0' + a;
  const Language* l = language_of_origin("submission" + extension);  // no extension: a folder of function files
  if (l && l->route == Route::Compiled) {
    text += "\0libraries";
    for (const auto& a : library_args(o.build.libraries)) text += '\0' + a;
  }
  // The interpreter that runs a served file: another one (GEOMECH_PYTHON set after a refusal, a
  // venv) checks it again.
  if (l && l->interpreter) text += '\0' + l->id + '\0' + l->interpreter();
  // A notebook runs in the interpreter of the row its kernel names: any of them, so that another
  // one checks it again too.
  if (l && l->route == Route::Notebook)
    for (const auto& k : languages())
      if (!k.kernels.empty() && k.interpreter) text += '\0' + k.id + '\0' + k.interpreter();
  return text;
}

namespace {

const std::string& suite_identity() {
  static const std::string id = [] {
    Fingerprint f;
    f.add_file("/proc/self/exe");
    return f.hex();
  }();
  return id;
}

// A row as the class record reads it (harness/class/class_record.hpp): every view renders that.
ClassRow class_row(const Row& row) {
  ClassRow c;
  c.name = row.impl.name;
  c.source = row.impl.source;
  c.built = row.built;
  c.build_message = row.build_message;
  c.build_seconds = row.build_seconds;
  c.exit_code = row.exit_code;
  c.check_seconds = row.check_seconds;
  c.problem = row.problem;
  c.machine_fault = row.machine_fault;
  c.earlier_faults = row.earlier_faults;
  c.suspect = row.suspect;
  c.report = row.report;
  return c;
}

// A finished task's row (the payload of the task in run_class), with its report read.
Row row_of(const Implementation& impl, const TaskResult& t, const std::string& report_dir) {
  Row row;
  row.impl = impl;
  if (t.status == TaskResult::Status::Busy) {  // starved by the machine (or it cannot tell): not the code's
    row.machine_fault = "the machine's fault, not the submission's: checking it " + t.detail +
                        ". Fix: run the class again on a less busy machine, or with fewer at once (--parallel)";
    return row;
  }
  if (t.status != TaskResult::Status::Ok) {
    row.problem = "checking it " + (t.detail.empty() ? std::string("failed") : t.detail);
    return row;
  }
  json j = json::parse(t.payload);
  j["name"] = impl.name;
  j["source"] = impl.source;
  for (const char* k : {"build_message", "problem", "machine_fault"})
    if (!j.contains(k)) j[k] = "";
  for (const char* k : {"build_seconds", "check_seconds"})
    if (!j.contains(k)) j[k] = 0.0;
  if (!j.contains("exit_code")) j["exit_code"] = -1;
  return row_from_json(j, report_dir);
}

}  // namespace

std::vector<Implementation> find_implementations(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error(dir + " is not a folder");
  const StrangerFolder folder(dir);
  std::vector<Implementation> out;
  auto is_source = [](const std::string& ext) { return language_of_extension(ext) != nullptr; };
  for (const auto& e : folder.list()) {
    const fs::path p(e.name);
    const std::string ext = p.extension().string();
    // Hidden: a .git folder, an editor's file, our own snapshots; but "..py" or "...py" would be
    // implementations named "." or "..", refused below by name.
    if (e.name[0] == '.' && p.stem() != "." && p.stem() != "..") continue;
    Implementation impl;
    impl.origin = e.name;
    impl.source = (fs::path(dir) / e.name).string();
    if (e.kind == EntryKind::File) {
      if (!is_source(ext)) continue;
      impl.name = p.stem().string();
    } else if (e.kind == EntryKind::Folder) {
      // A student's folder: one file of a language that marks its implementation (a .cpp that
      // registers a student), else the one file of a language without a marker (a .py), else a
      // folder of function files (Octave). Looked at without following anything: a link, FIFO,
      // socket or device in it refuses the submission, naming the entry.
      impl.name = e.name;
      std::vector<std::string> marked, single;
      bool function_files = false;
      try {
        for (const auto& f : folder.list(e.name)) {
          if (f.name[0] == '.' || f.name == "__pycache__") continue;
          const std::string rel = e.name + "/" + f.name;
          if (f.kind != EntryKind::File && f.kind != EntryKind::Folder) throw RefusedEntry(rel, describe(f.kind));
          if (f.kind != EntryKind::File) continue;
          const Language* l = language_of_extension(fs::path(f.name).extension().string());
          if (!l) continue;
          if (l->folder_of_files)
            function_files = true;
          else if (l->marker.empty())
            single.push_back(rel);
          else if (folder.read(rel, IntakeLimits{}.file_bytes).find(l->marker) != std::string::npos)
            marked.push_back(rel);
        }
        if (marked.size() == 1)
          impl.origin = marked.front();
        else if (marked.empty() && single.size() == 1)
          impl.origin = single.front();
        else if (marked.empty() && single.empty() && function_files)
          impl.origin = e.name;
        else
          continue;  // not a submission (a folder of shared material, an empty folder)
        impl.source = (fs::path(dir) / impl.origin).string();
      } catch (const RefusedEntry& r) {
        impl.refused = r.what();
      }
    } else {
      // A link, FIFO, socket or device: never followed or opened. Named like a submission (or like
      // a folder, which a link may stand for), it is one that cannot be checked; otherwise it is
      // not a submission and is left alone.
      if (!ext.empty() && !is_source(ext)) continue;
      impl.name = is_source(ext) ? p.stem().string() : e.name;
      impl.refused = e.name + ": " + describe(e.kind);
    }
    if (const std::string why = bad_implementation_name(impl.name); !why.empty()) {
      impl.refused = "'" + inert_text(e.name) + "' cannot be checked under the name '" + inert_text(impl.name) +
                     "': " + why + " (rename it)";
      impl.name = inert_text(impl.name);  // shown, never a folder: nothing of it is written
      impl.source.clear();
    }
    out.push_back(std::move(impl));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  // Two entries of one name (bob.py and a folder bob): neither is checked, and both rows say why.
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i].name == out[i - 1].name) {
      const std::string why = "two entries of the class folder are both named '" + out[i].name + "' (" +
                              out[i - 1].origin + " and " + out[i].origin + "); rename one";
      out[i].refused = out[i - 1].refused = why;
    }
  if (out.empty())
    throw std::runtime_error(dir +
                             " holds no implementation (*.cpp, *.py or *.m files, or folders with one .cpp using "
                             "GEOMECH_STUDENT, one .py, or .m files)");
  return out;
}

std::string default_class_report_dir(const std::string& class_dir) {
  std::error_code ec;
  fs::path p = fs::absolute(class_dir, ec).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // "week3/" is "week3"
  const std::string name = p.filename().string();
  return "geomech-reports/" + (name.empty() ? std::string("class") : name);
}

namespace {

// The gradebook's inputs, read and checked before anything is checked (a misspelt rubric key is
// found in a second, not after the class). The rubric grades the summary too, and the roster names
// the students who handed nothing in, with or without --grades.
struct Grades {
  std::string csv;           // empty: no gradebook file
  std::string feedback_dir;  // empty: no feedback files (harness/class/feedback_files.hpp)
  Rubric rubric;
  std::optional<Roster> roster;
};

std::string read_text(const std::string& path, const char* what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read the " + std::string(what) + " " + path);
  std::ostringstream os;
  os << f.rdbuf();
  return os.str();
}

Grades load_grades(const GradeOptions& g) {
  Grades out;
  out.csv = g.csv;
  out.feedback_dir = g.feedback_dir;
  if (!g.rubric.empty()) out.rubric = parse_rubric(read_text(g.rubric, "rubric"), g.rubric);
  if (!g.roster.empty()) out.roster = parse_roster(read_text(g.roster, "roster"), g.roster);
  return out;
}

// What a class's views are made from: the rows checked (in name order), the implementations not
// checked yet (a run going on, or stopped), and the roster's students with nothing in the folder.
struct ClassState {
  std::string class_dir;
  std::vector<Row> rows;
  std::vector<std::string> pending;
  std::vector<std::string> no_submission;
};

std::string md_cell_of(const std::string& text) { return md_inline(text); }

}  // namespace

// Every view of a class, from one decision (harness/class/class_record.hpp): summary.md,
// summary.html and the gradebook, rewritten together (each atomically) as each implementation
// finishes, so that they always agree, an interrupted run included: the students not checked yet
// are listed in the summaries and have no grade in the gradebook, which says why. When `final`,
// the console gets the table. Returns the exit status (0: every row PASS).
namespace {

// The title, what is still to check, and how to read the table.
void write_class_head(std::ostream& md, const ClassState& st, const ClassView& view, const Grades& grades) {
  const std::size_t total = view.students.size() + st.pending.size();
  md << "# geomech class report: " << md_inline(st.class_dir) << "\n\n";
  if (!st.pending.empty()) {
    md << "**In progress: " << view.students.size() << " of " << total
       << " implementations checked.** Not yet checked (the same command again resumes with them): ";
    for (std::size_t i = 0; i < st.pending.size(); ++i) md << (i ? ", " : "") << md_inline(st.pending[i]);
    md << "."
       << (grades.csv.empty() ? ""
                              : " The gradebook leaves their grades empty and says why in their row"
                                " (or is not written yet, while nothing checked can be graded).")
       << "\n\n";
  }
  md << view.students.size() << " implementations";
  if (!st.no_submission.empty()) md << " (" << st.no_submission.size() << " on the roster with no submission)";
  md << ". Grades: " << md_inline(grades.rubric.source) << ", " << view.assignment.size() << " slots in the assignment"
     << (view.assignment_from_rubric ? ""
                                     : " (every slot a student of the class provides; a rubric's \"assignment\" "
                                       "makes a PASS need all of them)")
     << ". Each area cell: checks passed / checks run (bad: FAIL, CRASH, TIMEOUT or ERROR), then the checks that did "
        "not run: n/w, of slots not written; d/o, in 50 digits or rationals, which the code or its language does not "
        "compute in (double only). Details in each implementation's report; summary.html is this page to read, "
        "sortable.\n\n";
  if (!view.no_grades.empty()) md << "**No grades**: " << md_inline(view.no_grades) << "\n\n";
}

// A row per student, in summary.md and on the console; the number that did not pass.
int write_student_table(std::ostream& md, std::ostream& console, const ClassView& view) {
  const auto& areas = area_names();
  int bad = 0;
  md << "| implementation | result | grade |";
  for (const auto& a : areas) md << " " << a << " |";
  md << " report |\n|---|---|---|";
  for (std::size_t i = 0; i < areas.size(); ++i) md << "---|";
  md << "---|\n";
  console << "\n"
          << std::left << std::setw(22) << "implementation" << std::setw(18) << "result" << std::setw(10) << "grade";
  for (const auto& a : areas) console << std::setw(22) << a;
  console << "\n" << std::string(22 + 18 + 10 + 22 * areas.size(), '-') << "\n";
  for (const auto& s : view.students) {
    if (s.result != "PASS") ++bad;
    const std::string grade = view.no_grades.empty() && !s.score.no_grade ? format_points(s.score.points) : "-";
    md << "| " << md_inline(s.row->name) << " | " << (s.result == "PASS" ? s.result : "**" + s.result + "**") << " | "
       << grade << " |";
    console << std::setw(22) << inert_text(s.row->name) + " " << std::setw(18) << s.result + " " << std::setw(10)
            << grade + " ";
    for (const auto& a : areas) {
      auto it = s.areas.find(a);
      const std::string c = it == s.areas.end() ? "-" : cell_text(it->second);
      md << " " << c << " |";
      console << std::setw(22) << c + " ";  // a cell wider than its column still ends with a space
    }
    const std::string link = s.row->name + "/report.md";
    md << " " << (s.report_link.empty() ? "-" : "[" + md_inline(link) + "](" + md_link_target(link) + ")") << " |\n";
    console << "\n";
  }
  return bad;
}

// What the class got wrong: the lecture to repeat (class_record.hpp, class_mistakes).
void write_class_mistakes(std::ostream& md, const ClassView& view) {
  if (view.mistakes.empty()) return;
  md << "\n## What the class got wrong\n\n| wrong | students | who | the most common first fix "
        "|\n|---|---|---|---|\n";
  for (const auto& m : view.mistakes) {
    std::string who;
    for (std::size_t i = 0; i < m.who.size(); ++i) who += (i ? ", " : "") + m.who[i];
    md << "| " << m.kind << " `" << md_inline(m.what) << "` | " << m.students << " of " << m.checked << " | "
       << md_cell_of(bounded_text(who, 200)) << " | "
       << (m.common_fix.empty() ? std::string("-")
                                : "(" + std::to_string(m.common_fix_students) + " of " + std::to_string(m.students) +
                                      ") " + md_cell_of(bounded_text(m.common_fix, 300)))
       << " |\n";
  }
}

// Each student in a sentence, with a link to the report.
void write_students_in_words(std::ostream& md, const ClassView& view) {
  md << "\n## Each student in words\n\n";
  for (const auto& s : view.students) {
    md << "- **" << md_inline(s.row->name) << "**" << (s.language.empty() ? "" : " (" + s.language + ")") << ": ";
    const auto words = words_of(s);
    for (std::size_t i = 0; i < words.size(); ++i) md << (i ? "; " : "") << md_cell_of(words[i]);
    md << ".";
    if (!s.report_link.empty()) md << " [report](" << md_link_target(s.report_link) << ")";
    md << "\n";
  }
  md << "\n";
}

// The students that did not compile, were not checked, or met the grader's fault, with why.
void write_student_problems(std::ostream& md, std::ostream& console, const ClassView& view) {
  for (const auto& s : view.students) {
    if (s.status == "does not compile") {
      md << "## " << md_inline(s.row->name) << ": does not compile\n\n"
         << md_fenced(bounded_text(s.row->build_message)) << "\n";
      console << "\n"
              << inert_text(s.row->name) << " does not compile:\n"
              << inert_text(bounded_text(s.row->build_message)) << "\n";
    } else if (s.status == "not checked") {
      md << "## " << md_inline(s.row->name) << ": not checked\n\n" << md_fenced(bounded_text(s.row->problem)) << "\n";
      console << "\n" << inert_text(s.row->name) << ": " << inert_text(bounded_text(s.row->problem)) << "\n";
    } else if (s.status == kGraderError && s.row->suspect) {
      // Met in every run of this submission alone: for the lecturer to decide, with each run's evidence.
      const std::string fault = bounded_text(grader_fault_of(*s.row));
      md << "## " << md_inline(s.row->name) << ": the same machine fault in each of "
         << s.row->earlier_faults.size() + 1
         << " runs of this unchanged submission, while classmates checked fine: suspect (no grade; the lecturer "
            "decides)\n\nThis machine's self-test passed and other submissions were checked on it, so a fault "
            "that only this submission meets may be the submission's doing that the kernel's accounting does not "
            "show, or a fault of the machine that only its check meets. It is not checked again by a plain run; "
            "`--regrade "
         << md_inline(s.row->name) << "` checks it again, `geomech check FILE --untrusted` checks it alone.\n\n";
      for (std::size_t k = 0; k < s.row->earlier_faults.size(); ++k)
        md << "Run " << k + 1 << ":\n\n" << md_fenced(bounded_text(s.row->earlier_faults[k])) << "\n";
      md << "The last run:\n\n" << md_fenced(fault) << "\n";
      console << "\n"
              << inert_text(s.row->name) << ": GRADER ERROR (no grade), suspect: the same machine fault in each of "
              << s.row->earlier_faults.size() + 1
              << " runs while classmates checked fine; the lecturer decides (summary.md): " << inert_text(fault)
              << "\n";
    } else if (s.status == kGraderError) {
      const std::string fault = bounded_text(grader_fault_of(*s.row));
      md << "## " << md_inline(s.row->name) << ": the grader's machine failed its check (no grade; checked again by "
         << "the next run)\n\n"
         << md_fenced(fault) << "\n";
      console << "\n" << inert_text(s.row->name) << ": GRADER ERROR (no grade): " << inert_text(fault) << "\n";
    }
  }
}

// The roster's warnings (a student with no roster row is graded under their implementation's
// name, which the LMS may not match): in the summary, where the lecturer reads, not only on the
// console. A roster row matching no implementation is a NO SUBMISSION row already.
void write_roster_warnings(std::ostream& md, const ClassView& view, const Grades& grades) {
  if (!grades.roster) return;
  std::vector<StudentResult> named;
  for (const auto& s : view.students) named.push_back(s.graded);
  std::vector<std::string> warnings;
  for (const auto& w : roster_warnings(named, *grades.roster))
    if (w.find("matches no implementation") == std::string::npos) warnings.push_back(w);
  if (!warnings.empty()) {
    md << "## Roster\n\n";
    for (const auto& w : warnings) md << "- " << md_cell_of(w) << "\n";
    md << "\n";
  }
}

// The gradebook, with the summary: the same students, the same grades; one not checked yet has
// no grade and says so (an empty cell is "no grade" to Moodle and Canvas). The students graded.
std::vector<StudentResult> write_class_gradebook(const ClassState& st, const ClassView& view, const Grades& grades,
                                                 bool final) {
  std::error_code ec;
  std::vector<StudentResult> students;
  for (const auto& s : view.students) students.push_back(s.graded);
  for (const auto& name : st.pending) {
    StudentResult p;
    p.name = name;
    p.status = kNotCheckedYet;
    students.push_back(p);
  }
  if (!grades.csv.empty() && view.no_grades.empty()) {
    std::string csv;
    try {
      csv = write_gradebook_csv(students, grades.rubric, grades.roster);
    } catch (const std::runtime_error&) {
      if (final) throw;
    }
    // Nothing gradable yet (a run that has checked nobody, under a rubric that learns its
    // assignment from the class): no gradebook at all rather than an earlier run's.
    if (csv.empty())
      fs::remove(grades.csv, ec);
    else
      write_file_atomically(grades.csv, csv);
  }
  return students;
}

// What a complete run prints: feedback files, the console table, where the summary and the
// gradebook are, the roster's warnings.
void say_class_done(const ClassView& view, const std::string& console, const std::string& report_dir,
                    const Grades& grades, const std::vector<StudentResult>& students) {
  // Feedback where students read it, once the class is complete (never a page of a run cut short).
  if (!grades.feedback_dir.empty())
    for (const auto& line : write_feedback_files(view, grades.feedback_dir))
      std::cout << "feedback: " << grades.feedback_dir << ": " << line << "\n";
  if (!grades.csv.empty() && !view.no_grades.empty())
    throw std::runtime_error("no gradebook written: " + view.no_grades + " (the summaries are written)");
  std::cout << console << "\nsummary: " << report_dir
            << "/summary.md and summary.html; one report per implementation in " << report_dir
            << "/<name>/report.md (and .html)\n";
  if (!grades.csv.empty()) {
    std::cout << "grades: " << grades.csv << " (" << grades.rubric.source << "; " << view.assignment.size()
              << " slots in the assignment";
    if (!grades.rubric.assignment) std::cout << ": every slot a student of the class provides";
    std::cout << "; docs/GRADEBOOK.md)\n";
  }
  if (grades.roster)
    for (const auto& w : roster_warnings(students, *grades.roster))
      if (w.find("matches no implementation") == std::string::npos) std::cout << "warning: " << w << "\n";
}

}  // namespace

static int summarise_class(const ClassState& st, const std::string& report_dir, const Grades& grades, bool final) {
  std::vector<ClassRow> class_rows;
  for (const auto& row : st.rows) class_rows.push_back(class_row(row));
  for (const auto& name : st.no_submission) class_rows.push_back(no_submission_row(name));
  std::sort(class_rows.begin(), class_rows.end(), [](const ClassRow& a, const ClassRow& b) { return a.name < b.name; });
  const ClassView view = decide_class(class_rows, grades.rubric);
  std::ostringstream md, console;
  write_class_head(md, st, view, grades);
  const int bad = write_student_table(md, console, view);
  write_class_mistakes(md, view);
  write_students_in_words(md, view);
  write_student_problems(md, console, view);
  write_roster_warnings(md, view, grades);
  write_file_atomically((fs::path(report_dir) / "summary.md").string(), md.str());
  ClassPage page;
  page.class_name = st.class_dir;
  page.rubric_source = grades.rubric.source;
  page.pending = st.pending;
  write_file_atomically((fs::path(report_dir) / "summary.html").string(), class_summary_html(view, page));
  const std::vector<StudentResult> students = write_class_gradebook(st, view, grades, final);
  if (final) say_class_done(view, console.str(), report_dir, grades, students);
  // The grader's machine failed a check: the run is not complete, as every command says (exit 3).
  for (const auto& s : view.students)
    if (s.status == kGraderError) return kExitMachine;
  return bad == 0 ? 0 : 1;
}

std::vector<Implementation> shard_of(const std::vector<Implementation>& all, int k, int n) {
  std::vector<Implementation> out;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(n)) == k - 1) out.push_back(all[i]);
  return out;
}

namespace {

// For the test of an interrupted run (tests/run_class_resume.cmake): after N implementations,
// this process stops itself with the signal named (INT, as Ctrl-C; KILL, as a killed job); -1: never.
std::pair<long, int> stop_for_a_test() {
  const char* t = std::getenv("GEOMECH_TEST_STOP_AFTER");
  if (!t) return {-1, 0};
  const std::string spec(t);
  return {std::atol(spec.c_str()), spec.find("KILL") != std::string::npos ? SIGKILL : SIGINT};
}

// What an interrupted run says: what is kept, what is not, and the command that resumes it.
std::string interrupted_words(const ClassState& st, std::size_t count, const std::string& report_dir,
                              const Grades& grades, const std::string& resume) {
  std::ostringstream say;
  say << "\n\ngeomech check-class: interrupted. " << st.rows.size() << " of " << count << " results are kept in "
      << report_dir
      << "/ (a report and class-row.json each); summary.md and "
         "summary.html"
      << (grades.csv.empty() ? "" : " and the gradebook " + grades.csv) << " list the " << st.pending.size()
      << " not checked yet" << (grades.csv.empty() ? "" : " (no grade in the gradebook)")
      << ". The same command resumes, checking only those:\n  " << resume << "\n";
  return say.str();
}

// The result is kept the moment it is known (class-row.json, then the summary, both atomic), so an
// interruption loses at most the checks still running.
void keep_row(const std::string& report_dir, const std::string& name, const std::string& print, const Row& row) {
  std::error_code dir_ec;
  fs::create_directories(fs::path(report_dir) / name, dir_ec);
  json keep{{"format", "geomech-class-row 1"}, {"fingerprint", print}, {"row", row_json(row)}};
  write_file_atomically((fs::path(report_dir) / name / "class-row.json").string(), keep.dump(1));
}

// A finished implementation's console line: the verdict and grade the summary now shows for it.
void say_finished(ClassConsole& console, const std::vector<std::optional<Row>>& finished, const Grades& grades,
                  const std::string& name, double seconds) {
  std::vector<ClassRow> rows_now;
  for (const auto& f : finished)
    if (f) rows_now.push_back(class_row(*f));
  const ClassView view = decide_class(rows_now, grades.rubric);
  for (const auto& sv : view.students)
    if (sv.row->name == name)
      console.finished(name, sv.result,
                       view.no_grades.empty() ? sv.score.headline.substr(0, sv.score.headline.find(':')) : "", seconds);
}

// The roster's students with nothing in the class folder get a row each (0, "no submission"), in
// a run of the whole class (a shard does not know the other shards' names; merge-class adds them).
std::vector<std::string> roster_without_submission(const ClassOptions& o, const Grades& grades,
                                                   const std::vector<Implementation>& all_impls) {
  std::vector<std::string> no_submission;
  if (grades.roster && o.shard_n == 1)
    for (const auto& [name, entry] : *grades.roster)
      if (std::none_of(all_impls.begin(), all_impls.end(), [&](const Implementation& i) { return i.name == name; }))
        no_submission.push_back(name);
  return no_submission;
}

// The shard and the names to regrade, said before anything runs.
void refuse_a_bad_request(const ClassOptions& o, const std::vector<Implementation>& all_impls) {
  if (o.shard_n < 1 || o.shard_k < 1 || o.shard_k > o.shard_n)
    throw std::runtime_error("--shard K/N needs 1 <= K <= N (got " + std::to_string(o.shard_k) + "/" +
                             std::to_string(o.shard_n) + ")");
  for (const auto& name : o.regrade)  // a regrade names a student of the class
    if (std::none_of(all_impls.begin(), all_impls.end(), [&](const Implementation& i) { return i.name == name; })) {
      std::vector<std::string> names;
      for (const auto& i : all_impls) names.push_back(i.name);
      throw std::runtime_error("--regrade " + name + ": no implementation of that name in " + o.dir +
                               did_you_mean(name, names) + " (names are the files' stems or the folders' names)");
    }
}

// The grader's machine, checked once, first: a fault there is one refusal with its fix, not a
// grade for every student (harness/class/grader_machine.hpp).
void refuse_on_the_graders_machine(const ClassOptions& o, const Toolchain& tc,
                                   const std::vector<Implementation>& impls) {
  GraderNeeds needs;
  needs.untrusted = o.untrusted;
  needs.cache_dir = o.build.cache_dir.empty() ? tc.cache_dir : o.build.cache_dir;
  for (const auto& impl : impls) {
    if (!impl.refused.empty()) continue;
    const Language* l = language_of_origin(impl.origin);
    if (l && l->route == Route::Served) needs.served.insert(l->id);
    if (l && l->route == Route::Notebook)  // its kernel's row, any of them (not read here)
      for (const auto& k : languages())
        if (!k.kernels.empty() && k.route == Route::Served) needs.served.insert(k.id);
  }
  if (const auto problems = grader_machine_problems(needs); !problems.empty())
    throw MachineError(grader_machine_message(problems));
}

// How one implementation's check ended, into its row's JSON: status 0 or 1 is a verdict, anything
// else (a crash, a refusal, a bad option) is a problem shown in the summary.
// `check_seconds` is the check's own time (its outcome's), else the whole process's.
// `checked`: the check ran and wrote its outcome (and its report): a machine's fault it met is then
// in its verdicts (verdicts.json's machine_fault), which the row's report says.
std::string record_check(json& j, const ProcessResult& pr, const std::string& what, double check_seconds,
                         bool checked) {
  j["exit_code"] = pr.exit_code;
  j["check_seconds"] = check_seconds;
  if (pr.exit_code == kExitMachine) {  // the set-up's (harness/submissions/check_submission.cpp): said with its fix
    if (!checked) j["machine_fault"] = pr.output.substr(0, 2000);
  } else if (pr.exit_code != 0 && pr.exit_code != 1) {
    j["problem"] = what + " ended with " +
                   (pr.signal ? describe_signal(pr.signal) : "status " + std::to_string(pr.exit_code)) + ": " +
                   pr.output.substr(0, 2000);
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

// The command a student runs on their own file, as the reports print it: their file's
// name, no folder of the lecturer's, no lecturer's option ("geomech check bob.py", "geomech check
// dave/" for a folder of Octave files).
std::string student_command(const Implementation& impl) {
  const fs::path origin(impl.origin);
  const bool octave_folder = impl.origin.find('/') == std::string::npos && origin.extension().empty();
  return std::string("geomech check ") + shell_quote(octave_folder ? impl.origin + "/" : origin.filename().string());
}

// One implementation's check, in the task's process: every route through the one entry
// (harness/submissions/check_submission.hpp), as the student's own `geomech check` takes it: a C++
// file built and checked (sandboxed when untrusted), a Python or Octave file behind the protocol.
// Its outcome says whether the file compiled and whether the set-up failed; the exit status is the
// verdict. The row's JSON.
std::string check_one(const Implementation& impl, const ClassOptions& o, const std::string& report_dir,
                      const fs::path& outcomes, int check_jobs) {
  // A check started here dies with this run (a Ctrl-C or a killed job stops the class, not
  // just its parent): harness/isolation/process.hpp, die_with_parent_when_asked.
  ::setenv("GEOMECH_DIE_WITH_PARENT", "1", 1);
  const fs::path outcome = outcomes / (impl.name + ".json");
  std::error_code rm_ec;
  fs::remove(outcome, rm_ec);
  CheckCliOptions co = o.check;
  co.jobs = check_jobs;
  co.quiet = true;
  co.report_dir = (fs::path(report_dir) / impl.name).string();
  std::vector<std::string> argv{fs::read_symlink("/proc/self/exe").string(),
                                "check",
                                impl.source,
                                "--reproduce-prefix",
                                student_command(impl),
                                "--name",
                                impl.name,
                                "--outcome",
                                outcome.string(),
                                "--compile-jobs",
                                "1"};
  if (o.untrusted) argv.push_back("--untrusted");
  if (!o.build.cache_dir.empty()) argv.insert(argv.end(), {"--cache-dir", o.build.cache_dir});
  const auto args = to_args(co);
  argv.insert(argv.end(), args.begin(), args.end());
  if (const Language* lang = language_of(impl.source); lang && lang->route == Route::Compiled) {
    const auto libs = library_args(o.build.libraries);  // --pkg, --cxxflags, --ldflags
    argv.insert(argv.end(), libs.begin(), libs.end());
  }
  const ProcessResult pr = run_process(ProcessSpec{argv, {}, false});
  json j;
  j["built"] = true;
  j["build_seconds"] = 0.0;
  if (const auto out = read_outcome(outcome.string())) {
    j["built"] = out->built;
    j["build_seconds"] = out->build_seconds;
    if (!out->built) {  // the file does not compile: its row says so, with the compiler's words
      j["build_message"] = out->build_message;
      return j.dump(-1, ' ', false, json::error_handler_t::replace);
    }
    if (!out->machine_fault.empty()) {  // the set-up's, said with its fix
      j["machine_fault"] = out->machine_fault;
      j["check_seconds"] = out->check_seconds;
      return j.dump(-1, ' ', false, json::error_handler_t::replace);
    }
    return record_check(j, pr, "the check", out->check_seconds, true);
  }
  return record_check(j, pr, "the check", pr.seconds, false);  // it ended before saying how (a crash, a signal)
}

// What this run checks, and what it resumes: each submission's snapshot and fingerprint, and
// the earlier complete results it keeps.
struct ClassPlan {
  std::vector<std::string> prints;           // each implementation's fingerprint
  std::vector<std::optional<Row>> finished;  // the rows known before any check: refused, resumed
  std::vector<std::size_t> to_check;         // the implementations checked in this run
  std::size_t resumed = 0, regraded = 0, not_checked_again = 0;
  fs::path outcomes;  // where each check writes its outcome
  // The machine's faults each unchanged submission met in the runs before (ClassRow::earlier_faults),
  // and how many are kept as suspect, not checked again.
  std::vector<std::vector<std::string>> earlier_faults;
  std::size_t kept_suspect = 0;
};

// The files the lecturer shares with every C++ submission (--shared).
SubmissionTree read_shared_files(const ClassOptions& o) {
  SubmissionTree shared;
  for (const auto& file : o.shared) {
    try {
      shared.files.emplace_back(fs::path(file).filename().string(), read_stranger_file(file));
    } catch (const RefusedEntry& e) {
      throw std::runtime_error("--shared " + file + ": " + e.why());
    }
  }
  return shared;
}

// The folder of the class's snapshots in the compilers' cache, named by the class folder.
fs::path snapshots_folder(const ClassOptions& o, const Toolchain& tc) {
  return fs::absolute(o.build.cache_dir.empty() ? tc.cache_dir : o.build.cache_dir) /
         ("class-" +
          [&] {
            Fingerprint f;
            f.add(fs::absolute(o.dir).lexically_normal().string());
            return f.hex();
          }()) /
         "submissions";
}

// The row of an implementation that could not be read: never checked.
Row refused_row(const Implementation& impl) {
  Row row;
  row.impl = impl;
  row.problem = kNotRead + impl.refused;
  return row;
}

// An implementation's complete result from an earlier run with the same fingerprint, kept in the
// plan (true) unless it must be checked again (false): the machine's fault it met is then recorded.
bool keep_earlier_row(const ClassOptions& o, const std::string& report_dir, const fs::path& row_file, std::size_t i,
                      ClassPlan& plan) {
  try {
    std::ifstream in(row_file);
    const json j = json::parse(in);
    if (j.at("format") == "geomech-class-row 1" && j.at("fingerprint") == plan.prints[i]) {
      Row row = row_from_json(j.at("row"), report_dir);
      // The grader's fault is checked again: the condition may have changed since; so is one
      // not checked, when the lecturer asks (--not-checked).
      const bool retry = o.not_checked && status_of(class_row(row)) == "not checked";
      if (retry) ++plan.not_checked_again;
      const std::string fault = grader_fault_of(class_row(row));
      // A machine's fault is checked again, once: the machine may have been busy. The same fault
      // again, while classmates checked fine, is suspect and left to the lecturer (the busy limit
      // is not spent on it at every run); --regrade NAME checks it again.
      if (!fault.empty() && row.suspect) {
        plan.finished[i] = std::move(row);
        ++plan.kept_suspect;
        return true;
      }
      if (!fault.empty()) {
        plan.earlier_faults[i] = row.earlier_faults;
        plan.earlier_faults[i].push_back(fault);
      }
      if (!retry && row.problem.rfind("its report cannot be read", 0) != 0 && fault.empty()) {
        plan.finished[i] = std::move(row);
        ++plan.resumed;
        return true;
      }
    }
  } catch (const std::exception&) {
    // unreadable: checked again
  }
  return false;
}

ClassPlan plan_checks(const ClassOptions& o, const Toolchain& tc, const std::string& report_dir,
                      std::vector<Implementation>& impls) {
  // Resuming: what each check depends on, and the implementations whose complete result
  // from an earlier run (class-row.json beside the report, written once the check has ended) has
  // the same fingerprint. A check cut off by an interruption left no class-row.json: it runs again.
  ClassPlan plan;
  plan.prints.resize(impls.size());
  plan.finished.resize(impls.size());
  plan.earlier_faults.resize(impls.size());
  auto& [prints, finished, to_check, resumed, regraded, not_checked_again, outcomes, earlier_faults, kept_suspect] =
      plan;
  std::error_code ec;
  // The files the lecturer shares with every C++ submission (--shared), read once.
  const SubmissionTree shared = read_shared_files(o);
  // Each submission's snapshot (harness/isolation/submission_intake.hpp): read without following anything,
  // within limits, into a folder of ours; what is fingerprinted, compiled and checked is that copy.
  const StrangerFolder class_folder(o.dir);
  // In the compilers' cache, under a name of the class folder: a whole run, its shards and a resumed
  // run check the same copies (and a C++ one compiled once is not compiled again).
  const fs::path snapshots = snapshots_folder(o, tc);
  // Where each check writes its outcome (harness/submissions/check_submission.hpp).
  outcomes = snapshots.parent_path() / "outcomes";
  fs::create_directories(outcomes, ec);
  if (ec) throw std::runtime_error("cannot create " + outcomes.string() + ": " + ec.message());
  for (std::size_t i = 0; i < impls.size(); ++i) {
    Implementation& impl = impls[i];
    if (!impl.refused.empty()) {
      finished[i] = refused_row(impl);
      continue;
    }
    const bool folder =
        impl.origin.find('/') != std::string::npos || class_folder.look(impl.origin).kind == EntryKind::Folder;
    const std::string root = folder ? impl.origin.substr(0, impl.origin.find('/')) : impl.origin;
    SubmissionTree tree;
    try {
      tree = read_submission(class_folder, root);
    } catch (const RefusedEntry& e) {
      impl.refused = e.what();
      finished[i] = refused_row(impl);
      continue;
    }
    const std::string ext = fs::path(impl.origin).extension().string();
    const Language* lang = language_of_extension(ext);
    if (lang && lang->files_beside)  // headers shared on purpose; a file of the student's own name stays theirs
      for (const auto& [name, text] : shared.files)
        if (std::none_of(tree.files.begin(), tree.files.end(), [&](const auto& f) { return f.first == name; }))
          tree.files.emplace_back(name, text);
    const fs::path dest = snapshots / impl.name;
    write_tree(tree, dest);
    impl.source = (folder && impl.origin.find('/') == std::string::npos)
                      ? dest.string()  // an Octave folder
                      : (dest / fs::path(impl.origin).filename()).string();
    Fingerprint f;
    f.add(suite_identity());
    f.add(check_conditions(o, ext));
    f.add_tree(tree);
    prints[i] = f.hex();
    const fs::path row_file = fs::path(report_dir) / impls[i].name / "class-row.json";
    const bool named = std::find(o.regrade.begin(), o.regrade.end(), impl.name) != o.regrade.end();
    if (named) ++regraded;
    if (!o.fresh && !named && fs::exists(row_file, ec) && keep_earlier_row(o, report_dir, row_file, i, plan)) continue;
    fs::remove(row_file, ec);
    to_check.push_back(i);
  }
  return plan;
}

// What the plan keeps and checks again, said before the checks start.
void say_plan(const ClassPlan& plan, std::size_t count, const ClassOptions& o) {
  if (plan.kept_suspect > 0)
    std::cerr << "geomech check-class: " << plan.kept_suspect << " of " << count
              << " implementations met the same machine fault in every run while classmates checked fine: kept "
                 "for the lecturer to decide (summary.md says why), not checked again (--regrade NAME checks one)\n";
  if (plan.resumed > 0)
    std::cerr << "geomech check-class: " << plan.resumed << " of " << count
              << " implementations are unchanged since their last complete check (source, options and suite) and are "
                 "not checked again (--fresh checks everyone)\n";
  if (plan.regraded > 0 || plan.not_checked_again > 0 || o.not_checked) {
    std::cerr << "geomech check-class: checked again on request: " << plan.regraded << " named (--regrade), "
              << plan.not_checked_again << " last NOT CHECKED (--not-checked)";
    const std::size_t others = plan.to_check.size() - plan.regraded - plan.not_checked_again;
    if (others > 0) std::cerr << "; " << others << " more changed or never checked, checked too";
    std::cerr << "\n";
  }
}

// What a merge needs to rebuild the summary (class-shard.json): the rows, with the class and the
// shard they belong to.
void write_shard(const ClassOptions& o, std::size_t implementations, const std::vector<Row>& rows,
                 const std::vector<std::string>& no_submission, const std::string& report_dir) {
  json shard;
  shard["format"] = "geomech-class-shard 1";
  shard["class"] = o.dir;
  shard["implementations"] = implementations;
  shard["shard"] = {o.shard_k, o.shard_n};
  shard["rows"] = json::array();
  for (const auto& row : rows) shard["rows"].push_back(row_json(row));
  for (const auto& name : no_submission) shard["rows"].push_back(class_row_to_json(no_submission_row(name)));
  write_file_atomically((fs::path(report_dir) / "class-shard.json").string(), shard.dump(1));
}

// What the class run checks, and how, said as it starts.
void say_class_start(const ClassOptions& o, std::size_t count, std::size_t class_size) {
  std::cerr << "geomech check-class: " << count << " implementations in " << o.dir
            << (o.untrusted ? " (untrusted mode: each sandboxed)" : " (trusted: in-process)");
  if (o.shard_n > 1) std::cerr << " (shard " << o.shard_k << "/" << o.shard_n << " of " << class_size << ")";
  std::cerr << ", " << o.jobs << " at a time\n";
}

// The checks of this run, a task each.
std::vector<std::function<std::string()>> class_check_tasks(const ClassOptions& o,
                                                            const std::vector<Implementation>& impls,
                                                            const std::vector<std::size_t>& to_check,
                                                            const std::string& report_dir, const fs::path& outcomes) {
  std::vector<std::function<std::string()>> tasks;
  // The cores are shared among the checks that run at once: a class of one (a regrade, an
  // autograder's submission) or fewer students than --parallel gives each check more than one
  // worker, so that no core idles (a complete Python file took 2.6x its direct check with one).
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int at_once = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(o.jobs, to_check.size())));
  const int check_jobs = std::max(1, cores / at_once);
  for (std::size_t i : to_check) {
    const Implementation& impl = impls[i];
    tasks.push_back([&o, &report_dir, &outcomes, check_jobs, impl] {
      return check_one(impl, o, report_dir, outcomes, check_jobs);
    });
  }
  return tasks;
}

// The command that runs the class again, resuming it.
std::string resume_command(const ClassOptions& o) {
  return o.command.empty() ? (o.front_door.empty() ? "geomech" : o.front_door) + " check-class " + shell_quote(o.dir)
                           : o.command;
}

// The class as it stands: the rows finished, the implementations still to check, and the roster's
// names with no submission.
ClassState class_state_now(const ClassOptions& o, const std::vector<Implementation>& impls,
                           const std::vector<std::optional<Row>>& finished,
                           const std::vector<std::string>& no_submission) {
  ClassState st;
  st.class_dir = o.dir;
  for (std::size_t k = 0; k < impls.size(); ++k)
    if (finished[k])
      st.rows.push_back(*finished[k]);
    else
      st.pending.push_back(impls[k].name);
  st.no_submission = no_submission;
  return st;
}

// Whether a classmate of implementation i has checked fine.
bool classmates_fine(const std::vector<std::optional<Row>>& finished, std::size_t i) {
  for (std::size_t k = 0; k < finished.size(); ++k)
    if (k != i && finished[k] && status_of(class_row(*finished[k])) == "checked") return true;
  return false;
}

// A machine's fault this unchanged submission met in the run before, met again: the evidence of
// each run is kept with its row, and it is suspect once a classmate checked fine (this run's
// self-test passed: refuse_on_the_graders_machine).
bool judge_repeat(const std::vector<std::string>& before, const std::vector<std::optional<Row>>& finished,
                  std::size_t i, Row& row) {
  const std::string fault = grader_fault_of(class_row(row));
  if (fault.empty() || before.empty() || row.suspect || !same_machine_fault(fault, before.back())) return false;
  row.earlier_faults = before;
  row.suspect = classmates_fine(finished, i);
  return true;
}

// A repeated fault met before any classmate had checked fine: judged again now the run is done.
void judge_repeats_again(ClassPlan& plan, const std::vector<Implementation>& impls, const std::string& report_dir) {
  auto& finished = plan.finished;
  for (std::size_t i : plan.to_check)
    if (finished[i] && !finished[i]->suspect && !finished[i]->earlier_faults.empty() && classmates_fine(finished, i) &&
        !grader_fault_of(class_row(*finished[i])).empty()) {
      finished[i]->suspect = true;
      keep_row(report_dir, impls[i].name, plan.prints[i], *finished[i]);
    }
}

// Where this run's shard was written, and how many implementations were resumed, said at its end.
void say_run_written(const ClassOptions& o, const std::string& report_dir, std::size_t resumed, std::size_t count) {
  if (o.shard_n > 1)
    std::cerr << "geomech check-class: shard " << o.shard_k << "/" << o.shard_n << " written to " << report_dir
              << "; combine the shards with `geomech merge-class OUT SHARD_DIR...`\n";
  if (resumed > 0)
    std::cout << "(" << resumed << " of " << count << " implementations resumed from the previous run, unchanged)\n";
}

}  // namespace

int run_class(const ClassOptions& o, const Toolchain& tc) {
  const auto all_impls = find_implementations(o.dir);
  refuse_a_bad_request(o, all_impls);
  auto impls = shard_of(all_impls, o.shard_k, o.shard_n);
  const std::string report_dir = o.report_dir.empty() ? default_class_report_dir(o.dir) : o.report_dir;
  // A bad rubric or roster is said before anything runs, and before the report folder is made (a
  // refused rubric leaves no empty report folder behind).
  const auto grades = load_grades(o.grades);
  std::error_code ec;
  fs::create_directories(report_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + report_dir + ": " + ec.message());

  const std::vector<std::string> no_submission = roster_without_submission(o, grades, all_impls);
  refuse_on_the_graders_machine(o, tc, impls);
  say_class_start(o, impls.size(), all_impls.size());
  ClassPlan plan = plan_checks(o, tc, report_dir, impls);
  say_plan(plan, impls.size(), o);
  auto& prints = plan.prints;
  auto& finished = plan.finished;
  const auto& to_check = plan.to_check;
  const std::size_t resumed = plan.resumed;
  const fs::path& outcomes = plan.outcomes;

  std::vector<std::function<std::string()>> tasks = class_check_tasks(o, impls, to_check, report_dir, outcomes);
  IsolationOptions io;
  io.jobs = o.jobs;
  io.timeout_seconds = o.timeout_per_implementation;
  io.memory_limit_mb = 0;  // the compilers need what they need
  const auto [stop_after, stop_signal] = stop_for_a_test();
  // The views of the class as it stands (summary.md, summary.html, the gradebook), rewritten
  // together, now (so that an earlier run's complete summary and gradebook never stand beside this
  // run's deleted results) and as each implementation finishes.
  const std::string resume = resume_command(o);
  ClassConsole console(impls.size(), impls.size() - to_check.size());
  auto rewrite_views = [&] {
    const ClassState st = class_state_now(o, impls, finished, no_submission);
    summarise_class(st, report_dir, grades, false);
    console.on_interrupt_say(interrupted_words(st, impls.size(), report_dir, grades, resume));
  };
  rewrite_views();
  io.on_started = [&](std::size_t t) { console.started(impls[to_check[t]].name); };
  io.on_idle = [&] { console.tick(); };
  std::size_t done = 0;
  io.on_finished = [&](std::size_t t, const TaskResult& result) {
    const std::size_t i = to_check[t];
    Row row = row_of(impls[i], result, report_dir);
    judge_repeat(plan.earlier_faults[i], finished, i, row);
    keep_row(report_dir, impls[i].name, prints[i], row);
    const double seconds = result.seconds;
    finished[i] = std::move(row);
    rewrite_views();
    say_finished(console, finished, grades, impls[i].name, seconds);
    ++done;
    if (stop_after >= 0 && static_cast<long>(done) >= stop_after) ::raise(stop_signal);
  };
  run_isolated(tasks, io);
  judge_repeats_again(plan, impls, report_dir);

  std::vector<Row> rows;
  for (auto& r : finished) rows.push_back(*r);

  write_shard(o, all_impls.size(), rows, no_submission, report_dir);
  say_run_written(o, report_dir, resumed, impls.size());
  ClassState st;
  st.class_dir = o.dir;
  st.rows = rows;
  st.no_submission = no_submission;
  return summarise_class(st, report_dir, grades, true);
}

int merge_class(const std::vector<std::string>& shard_dirs, const std::string& out_dir,
                const GradeOptions& grade_options) {
  if (shard_dirs.empty()) throw std::runtime_error("merge-class: no shard folders given");
  const auto grades = load_grades(grade_options);
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
    if (!seen.insert(k).second)
      throw std::runtime_error(file.string() + ": shard " + std::to_string(k) + " given twice");
    for (const auto& r : j.at("rows")) {
      if (!r.value("submitted", true)) continue;  // a roster name with no submission: added below
      Row row = row_from_json(r, dir);
      const fs::path report = fs::path(dir) / row.impl.name;
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
    throw std::runtime_error("merge-class: the shards hold " + std::to_string(rows.size()) +
                             " implementations, the class " + std::to_string(total));
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.impl.name < b.impl.name; });
  ClassState st;
  st.class_dir = klass;
  st.rows = rows;
  if (grades.roster)
    for (const auto& [name, entry] : *grades.roster)
      if (std::none_of(rows.begin(), rows.end(), [&](const Row& r) { return r.impl.name == name; }))
        st.no_submission.push_back(name);
  return summarise_class(st, out_dir, grades, true);
}

}  // namespace gm::harness
