#include "harness/class/class_record.hpp"
#include "harness/languages/language.hpp"

#include "harness/isolation/inert_text.hpp"
#include "harness/reports/report.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The slots a report says were provided, in any scalar.
std::set<std::string> provided_slots(const json& report) {
  std::set<std::string> out;
  const json by_scalar = report.value("provided", json::object());  // (items() of a temporary would dangle)
  for (const auto& [scalar, slots] : by_scalar.items())
    for (const auto& slot : slots) out.insert(slot.get<std::string>());
  return out;
}

// The first line of a compiler's message that says what is wrong (an "error:" line), else its first.
std::string first_error_line(const std::string& message) {
  std::istringstream lines(message);
  std::string line, first;
  while (std::getline(lines, line)) {
    line.erase(0, line.find_first_not_of(" \t"));
    if (first.empty() && !line.empty()) first = line;
    if (line.find("error") != std::string::npos) return line;
  }
  return first;
}

// Why a NOT PROVIDED check did not run, from the record: "not written" or "double only".
bool is_double_only(const json& v, const json& report) {
  if (v.contains("not_provided")) return v["not_provided"] == "double only";
  // Reports written before the field: a scalar the implementation cannot compute in at all.
  return report.value("scalar_unavailable", json::object()).contains(v.value("scalar", ""));
}

}  // namespace

json class_row_to_json(const ClassRow& row) {
  json j = {{"name", row.name},
            {"source", row.source},
            {"built", row.built},
            {"build_message", row.build_message},
            {"build_seconds", row.build_seconds},
            {"exit_code", row.exit_code},
            {"check_seconds", row.check_seconds},
            {"problem", row.problem}};
  if (!row.submitted) j["submitted"] = false;
  if (!row.machine_fault.empty()) j["machine_fault"] = row.machine_fault;
  if (!row.earlier_faults.empty()) j["earlier_faults"] = row.earlier_faults;
  if (row.suspect) j["suspect"] = true;
  return j;
}

ClassRow class_row_from_json(const json& r, const std::string& report_dir) {
  ClassRow row;
  row.name = r.at("name").get<std::string>();
  row.source = r.value("source", "");
  row.submitted = r.value("submitted", true);
  row.built = r.value("built", false);
  row.build_message = r.value("build_message", "");
  row.build_seconds = r.value("build_seconds", 0.0);
  row.exit_code = r.value("exit_code", -1);
  row.check_seconds = r.value("check_seconds", 0.0);
  row.problem = r.value("problem", "");
  row.machine_fault = r.value("machine_fault", "");
  row.earlier_faults = r.value("earlier_faults", std::vector<std::string>{});
  row.suspect = r.value("suspect", false);
  if (row.submitted && row.built && row.problem.empty() && row.machine_fault.empty()) {
    std::ifstream f(fs::path(report_dir) / row.name / "verdicts.json");
    try {
      row.report = json::parse(f);
    } catch (const std::exception& e) {
      row.problem = std::string("its report cannot be read: ") + e.what();
    }
  }
  return row;
}

std::optional<ClassRow> read_class_row(const std::string& report_dir, const std::string& name) {
  std::ifstream in(fs::path(report_dir) / name / "class-row.json");
  if (!in) return std::nullopt;
  try {
    const json j = json::parse(in);
    return class_row_from_json(j.at("row"), report_dir);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

ClassRow no_submission_row(const std::string& name) {
  ClassRow row;
  row.name = name;
  row.submitted = false;
  return row;
}

std::string grader_fault_of(const ClassRow& row) {
  if (!row.machine_fault.empty()) return row.machine_fault;
  if (row.report.is_object())
    for (const auto& v : row.report.value("verdicts", json::array()))
      if (v.contains("machine_fault")) return v.at("machine_fault").get<std::string>();
  return {};
}

namespace {

// A machine fault's kind, from the words every fault of that kind is said in.
std::string fault_kind(const std::string& f) {
  for (const char* kind :
       {"the machine starved it", "run-queue accounting", "the sandbox could not start", "could not run the compiler",
        "out of the sandbox's reach", "cannot be shown to the sandbox"})
    if (f.find(kind) != std::string::npos) return kind;
  return f.substr(0, 80);
}

}  // namespace

bool same_machine_fault(const std::string& a, const std::string& b) { return fault_kind(a) == fault_kind(b); }

std::string status_of(const ClassRow& row) {
  if (!row.submitted) return "no submission";
  if (!grader_fault_of(row).empty()) return kGraderError;
  if (!row.problem.empty()) return "not checked";
  if (!row.built) return "does not compile";
  return "checked";
}

std::string cell_text(const AreaCell& c) {
  if (c.run == 0 && c.not_written == 0 && c.double_only == 0) return "-";
  std::ostringstream os;
  os << c.passed << "/" << c.run;
  if (c.bad > 0) os << " (" << c.bad << " bad)";
  if (c.not_written > 0) os << " +" << c.not_written << " n/w";
  if (c.double_only > 0) os << " +" << c.double_only << " d/o";
  return os.str();
}

StudentResult student_result(const ClassRow& row) {
  StudentResult s;
  s.name = row.name;
  s.status = status_of(row);
  s.report = row.submitted && (row.built || !row.problem.empty()) ? row.name + "/report.md" : "";
  if (s.status == "no submission") return s;
  if (s.status == "does not compile") {
    s.first_fix = inert_text(bounded_text(first_error_line(row.build_message)));
    return s;
  }
  if (s.status == "not checked") {
    s.first_fix = inert_text(bounded_text(row.problem.substr(0, row.problem.find('\n'))));
    s.report.clear();
    return s;
  }
  if (s.status == kGraderError) {  // the machine's: nothing of it is the student's to fix
    s.report.clear();
    s.left_to_lecturer = row.suspect;
    return s;
  }
  const std::set<std::string> provided = provided_slots(row.report);
  // Credit only for what a check exercised: a slot no selected property calls is not known correct.
  const json exercised = row.report.value("exercised", json::object());
  for (const auto& slot : provided) {
    if (exercised.contains(slot) && !exercised.at(slot).empty())
      s.provided.push_back(slot);
    else
      s.unexercised.push_back(slot);
  }
  for (const auto& f : row.report.value("first_fix", json::array())) {
    const std::string slot = f.at("slot");
    s.wrong.push_back(slot);
    s.why_wrong[slot] = f.at("line");
    if (s.first_fix.empty()) s.first_fix = f.at("line");
  }
  for (const auto& v : row.report.value("verdicts", json::array())) {
    const std::string out = v.at("outcome").get<std::string>();
    if (out == "NOT PROVIDED") continue;
    auto& a = s.areas[v.value("area", "?")];
    ++a.second;
    if (out == "PASS") ++a.first;
  }
  for (const auto& integ : row.report.value("integrators", json::array()))
    for (const auto& c : integ.at("claims")) {
      const std::string claimed = c.value("claimed", "");
      if (claimed.empty() || claimed == "no" || claimed == "-") continue;  // a claim nobody made
      // A run narrowed by the lecturer (-p, --integrator) that selected no check of a claim has no
      // evidence on it either way: it is left out, as a claim not made.
      if (c.value("status", "").find("not selected") != std::string::npos) continue;
      s.claims.push_back({integ.at("name"), c.at("claim"), c.at("status")});
    }
  return s;
}

namespace {

// A first fix as a grouping key: the student's own names (their implementation, its file) and the
// numbers (inputs, residuals) left out, so that two students told the same fix group together.
std::string fix_key(const std::string& fix, const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < fix.size();) {
    if (!name.empty() && fix.compare(i, name.size(), name) == 0) {
      out += "~";
      i += name.size();
      while (i < fix.size() && (std::isalnum(static_cast<unsigned char>(fix[i])) || fix[i] == '.' || fix[i] == '_'))
        ++i;
    } else if (std::isdigit(static_cast<unsigned char>(fix[i])) ||
               (fix[i] == '-' && i + 1 < fix.size() && std::isdigit(static_cast<unsigned char>(fix[i + 1])))) {
      out += "#";
      ++i;
      while (i < fix.size() && (std::isdigit(static_cast<unsigned char>(fix[i])) || fix[i] == '.' || fix[i] == 'e' ||
                                fix[i] == '-' || fix[i] == '+'))
        ++i;
    } else {
      out += fix[i++];
    }
  }
  return out;
}

}  // namespace

std::vector<ClassMistake> class_mistakes(const ClassView& view) {
  struct Seen {
    ClassMistake m;
    std::map<std::string, std::pair<int, std::string>> fixes;  // key -> (students, one student's words)
  };
  std::map<std::pair<std::string, std::string>, Seen> seen;
  int checked = 0;
  for (const auto& s : view.students) {
    if (s.status != "checked") continue;
    ++checked;
    auto note = [&](const std::string& kind, const std::string& what, const std::string& fix) {
      Seen& e = seen[{kind, what}];
      e.m.kind = kind, e.m.what = what;
      ++e.m.students;
      e.m.who.push_back(s.row->name);
      if (!fix.empty()) {
        auto& f = e.fixes[fix_key(fix, s.row->name)];
        if (f.first++ == 0) f.second = fix;
      }
    };
    for (const auto& slot : s.graded.wrong) {
      const auto why = s.graded.why_wrong.find(slot);
      note("slot", slot, why == s.graded.why_wrong.end() ? std::string() : why->second);
    }
    for (const auto& c : s.graded.claims)
      if (c.status == "FALSE CLAIM" || c.status == "DOES NOT CONVERGE") note("claim", c.integrator + " " + c.claim, "");
  }
  std::vector<ClassMistake> out;
  for (auto& [key, e] : seen) {
    e.m.checked = checked;
    std::sort(e.m.who.begin(), e.m.who.end());
    for (const auto& [k, f] : e.fixes)
      if (f.first > e.m.common_fix_students) e.m.common_fix_students = f.first, e.m.common_fix = f.second;
    out.push_back(std::move(e.m));
  }
  std::stable_sort(out.begin(), out.end(), [](const ClassMistake& a, const ClassMistake& b) {
    return a.students != b.students ? a.students > b.students : a.what < b.what;
  });
  return out;
}

ClassView decide_class(const std::vector<ClassRow>& rows, const Rubric& rubric) {
  ClassView view;
  std::vector<StudentResult> results;
  for (const auto& row : rows) results.push_back(student_result(row));
  view.assignment = resolve_assignment(rubric, results);
  view.assignment_from_rubric = rubric.assignment.has_value();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ClassRow& row = rows[i];
    StudentView s;
    s.row = &row;
    s.status = status_of(row);
    s.graded = results[i];
    try {
      s.score = score_student(s.graded, rubric, view.assignment);
    } catch (const std::runtime_error& e) {
      // The rubric leaves this class nothing to grade (nobody provides a weighted slot): every view
      // says so; the gradebook's export refuses with the same message.
      view.no_grades = e.what();
      s.score = Score{};
      s.score.max_points = rubric.points;
      s.score.headline = "no grade";
    }
    s.report_link = s.graded.report;
    if (s.status == "no submission")
      s.result = "NO SUBMISSION";
    else if (s.status == "does not compile")
      s.result = "DOES NOT COMPILE";
    else if (s.status == "not checked")
      s.result = "NOT CHECKED";
    else if (s.status == kGraderError)
      s.result = "GRADER ERROR";
    if (s.status != "checked") {
      view.students.push_back(std::move(s));
      continue;
    }
    const Language* language = language_named(row.report.value("language", "c++"));
    s.language = language ? language->name : "C++";                  // the language table's name for it
    if (row.report.contains("notebook")) s.language += " notebook";  // its code cells in that language
    for (const auto& v : row.report.value("verdicts", json::array())) {
      auto& c = s.areas[v.value("area", "?")];
      const std::string out = v.at("outcome").get<std::string>();
      if (out == "NOT PROVIDED") {
        ++(is_double_only(v, row.report) ? c.double_only : c.not_written);
        continue;
      }
      ++c.run;
      if (out == "PASS")
        ++c.passed;
      else
        ++c.bad;
    }
    // The assignment decides a PASS (one slot of twelve, right, read as PASS): every
    // check that ran passed, and every slot the rubric's assignment weights is provided, exercised
    // and right. Without an assignment in the rubric, the class's own union of slots is a guess at
    // one (docs/GRADEBOOK.md), and a PASS is every check passing; the grade still counts the slots.
    if (row.exit_code != 0) {
      s.result = row.report.value("verdict", std::string("FAIL"));
    } else if (!view.assignment_from_rubric) {
      s.result = "PASS";
    } else {
      bool complete = true;
      for (const auto& item : s.score.items) {
        if (item.kind == ScoreItem::Kind::Slot && item.state != "correct") complete = false;
        if (item.kind == ScoreItem::Kind::Claim && item.state == "none made")
          complete = false;  // claims asked, none made
      }
      s.result = complete ? "PASS" : "INCOMPLETE";
    }
    view.students.push_back(std::move(s));
  }
  view.mistakes = class_mistakes(view);
  return view;
}

std::vector<std::string> words_of(const StudentView& s) {
  std::vector<std::string> out;
  const ClassRow& row = *s.row;
  const std::string grade = s.score.headline.substr(0, s.score.headline.find(':'));  // "0.00 of 20"
  if (s.status == "no submission")
    return {"NO SUBMISSION, " + grade +
            ": the roster names this student, and the class folder holds nothing of theirs"};
  if (s.status == kGraderError && row.suspect)
    return {"GRADER ERROR, no grade: suspect: each of the " + std::to_string(row.earlier_faults.size() + 1) +
            " runs of this unchanged submission ended in the same machine fault, while classmates checked fine on "
            "this machine (its self-test passed); the lecturer decides, from the evidence below, and it is not "
            "checked again unless asked (--regrade " +
            row.name + ")"};
  if (s.status == kGraderError)
    return {
        "GRADER ERROR, no grade yet: the grading machine could not check this submission (not a problem of the "
        "code); the next run checks it again"};
  if (s.status != "checked") {
    out.push_back(s.result + ", " + grade);
    if (!s.graded.first_fix.empty())
      out.push_back((s.status == "does not compile" ? "first error: " : "why: ") + s.graded.first_fix);
    return out;
  }
  out.push_back(s.result + ", " + s.score.headline);
  for (const auto& n : s.score.notes) out.push_back(n);
  // What the assignment does not count: slots provided beyond it.
  std::set<std::string> outside(s.graded.provided.begin(), s.graded.provided.end());
  for (const auto& a : s.score.items)
    if (a.kind == ScoreItem::Kind::Slot) outside.erase(a.name);
  if (!outside.empty())
    out.push_back(std::to_string(outside.size()) + (outside.size() == 1 ? " slot" : " slots") +
                  " provided beyond the assignment (not graded)");
  std::vector<std::string> verified, failed;
  for (const auto& c : s.graded.claims)
    (c.status.rfind("verified", 0) == 0 ? verified : failed)
        .push_back(c.integrator + " " + c.claim + (c.status.rfind("verified", 0) == 0 ? "" : " (" + c.status + ")"));
  // The headline counts the claims when the rubric grades them; the failed ones are named here.
  const bool counted = s.score.headline.find("claim") != std::string::npos;
  if ((!counted && !verified.empty()) || !failed.empty()) {
    std::string claims = "claims: " + std::to_string(verified.size()) + " of " +
                         std::to_string(verified.size() + failed.size()) + " verified";
    if (!failed.empty()) {
      claims += ", failed: ";
      for (std::size_t i = 0; i < failed.size(); ++i) claims += (i ? "; " : "") + failed[i];
    }
    out.push_back(claims);
  }
  const json counts = row.report.value("counts", json::object());
  int problems = 0;
  for (const char* k : {"FAIL", "CRASH", "TIMEOUT", "ERROR"}) problems += counts.value(k, 0);
  if (problems > 0)
    out.push_back(std::to_string(problems) + (problems == 1 ? " check fails" : " checks fail") + " in all");
  const auto unchecked = row.report.value("unchecked", json::array());
  if (!unchecked.empty()) out.push_back(std::to_string(unchecked.size()) + " could not be checked");
  if (!s.graded.first_fix.empty()) out.push_back("first fix: " + s.graded.first_fix);
  return out;
}

}  // namespace gm::harness
