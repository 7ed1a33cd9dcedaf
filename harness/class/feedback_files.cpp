#include "harness/class/feedback_files.hpp"

#include "harness/class/gradebook.hpp"
#include "harness/reports/html_page.hpp"
#include "harness/reports/report.hpp"

#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace gm::harness {

namespace fs = std::filesystem;

FeedbackName feedback_name(const std::string& name) {
  static const std::regex moodle(R"(^.+_[0-9]+_assignsubmission_file_?$)");
  static const std::regex canvas(R"(^([^_]+_(LATE_)?[0-9]+_[0-9]+_).*$)");
  std::smatch m;
  if (std::regex_match(name, moodle)) return {name + "/geomech-feedback.html", "Moodle"};
  if (std::regex_match(name, m, canvas)) return {m[1].str() + "geomech-feedback.html", "Canvas"};
  return {name + ".html", ""};
}

namespace {

std::string feedback_page(const StudentView& s) {
  std::ostringstream b;
  const std::string name = s.row->name;
  b << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>geomech: " << html_escape(name)
    << "</title>\n<style>body{font:15px/1.45 sans-serif;max-width:60em;margin:2em auto;padding:0 1em}"
       "code,pre{background:#f4f4f4}td,th{padding:.2em .6em;text-align:left}</style></head><body>\n";
  b << "<h1>" << html_escape(s.result) << ": " << html_escape(s.score.headline) << "</h1>\n<ul>\n";
  for (const auto& w : words_of(s)) b << "<li>" << html_escape(w) << "</li>\n";
  b << "</ul>\n";
  if (!s.score.items.empty() && !s.score.no_grade) {  // no grade (the grader's fault): nothing it rests on
    b << "<h2>What the grade rests on</h2>\n<table><tr><th>part</th><th>state</th><th>points</th><th>why</th></tr>\n";
    for (const auto& i : s.score.items)
      b << "<tr><td>" << html_escape(i.name) << "</td><td>" << html_escape(i.state) << "</td><td>"
        << format_points(i.points) << " of " << format_points(i.max_points) << "</td><td>" << html_escape(i.detail)
        << "</td></tr>\n";
    b << "</table>\n";
  }
  const std::string again = s.row->report.is_object() ? s.row->report.value("reproduce_prefix", std::string()) : "";
  if (!again.empty())
    b << "<p>Check your file again yourself: <code>" << html_escape(again) << "</code> (its report says every check, "
      << "with an input where it fails and the command that replays it).</p>\n";
  b << "</body></html>\n";
  return b.str();
}

}  // namespace

std::vector<std::string> write_feedback_files(const ClassView& view, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("--feedback-dir " + dir + ": " + ec.message());
  std::map<std::string, int> kinds;
  std::vector<std::string> others;
  for (const auto& s : view.students) {
    if (s.status == "no submission") continue;  // nothing handed in: nothing to attach feedback to
    const FeedbackName f = feedback_name(s.row->name);
    const fs::path path = fs::path(dir) / f.path;
    fs::create_directories(path.parent_path(), ec);
    write_file_atomically(path.string(), feedback_page(s));
    ++kinds[f.lms];
    if (f.lms.empty()) others.push_back(s.row->name);
  }
  std::vector<std::string> said;
  if (kinds.count("Moodle"))
    said.push_back(std::to_string(kinds["Moodle"]) +
                   " in folders named as Moodle's download names them: zip the "
                   "folder's content and use \"Upload multiple feedback files in a zip\"");
  if (kinds.count("Canvas"))
    said.push_back(std::to_string(kinds["Canvas"]) +
                   " named with Canvas's download prefix (user and submission ids): "
                   "zip them and use \"Re-upload submissions\"");
  if (!others.empty()) {
    std::string names;
    for (std::size_t i = 0; i < others.size() && i < 5; ++i) names += (i ? ", " : "") + others[i];
    said.push_back(std::to_string(others.size()) + " named after the implementation (" + names +
                   (others.size() > 5 ? ", ..." : "") +
                   "): no LMS gave these names; a class folder unzipped from Moodle's or Canvas's download has "
                   "names its bulk upload takes back");
  }
  return said;
}

}  // namespace gm::harness
