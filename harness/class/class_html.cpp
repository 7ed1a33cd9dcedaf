#include "harness/class/class_html.hpp"

#include <algorithm>

#include "harness/reports/html_page.hpp"
#include "harness/reports/report.hpp"

#include <cctype>
#include <sstream>

namespace gm::harness {

namespace {

std::string key_of(const std::string& area) {
  std::string k;
  for (char c : area) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      k += c;
    else if (!k.empty() && k.back() != '-')
      k += '-';
  }
  while (!k.empty() && k.back() == '-') k.pop_back();
  return k;
}

// Results sort worst first by default reading order: what needs a look.
int result_rank(const std::string& r) {
  if (r == "NO SUBMISSION") return 0;
  if (r == "NOT CHECKED" || r == "GRADER ERROR") return 1;
  if (r == "DOES NOT COMPILE") return 2;
  if (r == "PASS") return 6;
  if (r == "INCOMPLETE") return 5;
  return 3;  // FAIL, NOTHING CHECKED
}

std::string number(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

// Sorts a table by a column's data-sort values (numbers as numbers); #sort=KEY or #sort=-KEY on load.
const char* kSortScript = R"JS(
(function () {
  var table = document.getElementById('class-table');
  if (!table) return;
  var heads = table.tHead.rows[0].cells;
  function sortBy(col, dir) {
    var body = table.tBodies[0];
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = a.cells[col].getAttribute('data-sort'), y = b.cells[col].getAttribute('data-sort');
      var nx = parseFloat(x), ny = parseFloat(y);
      var c = (!isNaN(nx) && !isNaN(ny)) ? nx - ny : x.localeCompare(y);
      if (c === 0) c = a.cells[0].getAttribute('data-sort').localeCompare(b.cells[0].getAttribute('data-sort'));
      return dir * c;
    });
    for (var i = 0; i < rows.length; ++i) body.appendChild(rows[i]);
    for (var j = 0; j < heads.length; ++j) heads[j].removeAttribute('aria-sort');
    heads[col].setAttribute('aria-sort', dir > 0 ? 'ascending' : 'descending');
  }
  Array.prototype.forEach.call(heads, function (th, col) {
    th.className = 'sortable';
    th.addEventListener('click', function () {
      sortBy(col, th.getAttribute('aria-sort') === 'ascending' ? -1 : 1);
    });
  });
  var m = /^#sort=(-?)([a-z0-9-]+)$/.exec(window.location.hash);
  if (m) {
    for (var k = 0; k < heads.length; ++k)
      if (heads[k].getAttribute('data-key') === m[2]) sortBy(k, m[1] === '-' ? -1 : 1);
  }
})();
)JS";

}  // namespace

std::vector<std::string> class_table_columns() {
  std::vector<std::string> c{"name", "result", "grade"};
  for (const auto& a : area_names()) c.push_back(key_of(a));
  c.push_back("first-fix");
  return c;
}

namespace {

// The class table: a row per student, its result, grade, area cells and first fix, each cell
// with the value it sorts by.
void write_class_table_html(std::ostream& b, const ClassView& view, const std::vector<std::string>& areas) {
  b << "<table id=\"class-table\">\n<thead><tr><th data-key=\"name\">implementation</th>"
       "<th data-key=\"result\">result</th><th data-key=\"grade\">grade</th>";
  for (const auto& a : areas) b << "<th data-key=\"" << key_of(a) << "\">" << html_escape(a) << "</th>";
  b << "<th data-key=\"first-fix\">first fix</th></tr></thead>\n<tbody>\n";
  for (const auto& s : view.students) {
    const std::string name = s.row->name;
    b << "<tr id=\"row-" << html_escape(key_of(name)) << "\"><td data-sort=\"" << html_escape(name) << "\">";
    if (!s.report_link.empty())
      b << "<a href=\"" << html_escape(name) << "/report.html\">" << html_escape(name) << "</a>";
    else
      b << html_escape(name);
    b << "</td><td data-sort=\"" << result_rank(s.result) << "\" class=\""
      << (s.result == "PASS"         ? "PASS"
          : s.result == "INCOMPLETE" ? "INCOMPLETE"
                                     : "FAIL")
      << "\">" << html_escape(s.result) << "</td>";
    if (s.score.no_grade)  // the grader's fault, or not checked yet: no grade, as in the gradebook
      b << "<td data-sort=\"-1\">-</td>";
    else
      b << "<td data-sort=\"" << number(s.score.points) << "\">" << format_points(s.score.points) << "</td>";
    for (const auto& a : areas) {
      auto it = s.areas.find(a);
      const AreaCell c = it == s.areas.end() ? AreaCell{} : it->second;
      const double frac = c.run > 0 ? static_cast<double>(c.passed) / c.run : -1;
      b << "<td data-sort=\"" << number(frac) << "\"" << (c.bad > 0 ? " class=\"bad\"" : "") << ">"
        << html_escape(cell_text(c)) << "</td>";
    }
    b << "<td data-sort=\"" << html_escape(s.graded.first_fix) << "\">" << html_escape(s.graded.first_fix)
      << "</td></tr>\n";
  }
  b << "</tbody>\n</table>\n";
}

// The section of what the class got wrong, when it got anything wrong.
void write_class_mistakes_html(std::ostream& b, const ClassView& view) {
  if (view.mistakes.empty()) return;
  // What the class got wrong: a bar per slot or claim, the share of the students checked who got
  // it wrong (an inline SVG: the page stays self-contained), then the table with who and the fix.
  const int bar_h = 22, label_w = 260, bar_w = 360;
  const int height = bar_h * static_cast<int>(view.mistakes.size()) + 10;
  b << "<h2 id=\"wrong\">What the class got wrong</h2>\n<svg role=\"img\" aria-label=\"students who got each wrong\" "
       "width=\""
    << label_w + bar_w + 90 << "\" height=\"" << height << "\" style=\"font: 13px sans-serif\">\n";
  for (std::size_t i = 0; i < view.mistakes.size(); ++i) {
    const ClassMistake& m = view.mistakes[i];
    const int y = static_cast<int>(i) * bar_h + 5;
    const int w = m.checked > 0 ? bar_w * m.students / m.checked : 0;
    b << "<text x=\"" << label_w - 6 << "\" y=\"" << y + 15 << "\" text-anchor=\"end\">"
      << html_escape(m.kind + " " + m.what) << "</text><rect x=\"" << label_w << "\" y=\"" << y + 3 << "\" width=\""
      << std::max(w, 1) << "\" height=\"" << bar_h - 6 << "\" fill=\"#c0392b\"/><text x=\""
      << label_w + std::max(w, 1) + 6 << "\" y=\"" << y + 15 << "\">" << m.students << " of " << m.checked
      << "</text>\n";
  }
  b << "</svg>\n<table id=\"wrong-table\">\n<thead><tr><th>wrong</th><th>students</th><th>who</th><th>the most "
       "common "
       "first fix</th></tr></thead>\n<tbody>\n";
  for (const auto& m : view.mistakes) {
    std::string who;
    for (std::size_t i = 0; i < m.who.size(); ++i) who += (i ? ", " : "") + m.who[i];
    b << "<tr><td>" << html_escape(m.kind) << " <code>" << html_escape(m.what) << "</code></td><td>" << m.students
      << " of " << m.checked << "</td><td>" << html_escape(who) << "</td><td>"
      << (m.common_fix.empty() ? std::string("-")
                               : "(" + std::to_string(m.common_fix_students) + " of " + std::to_string(m.students) +
                                     ") " + html_escape(m.common_fix))
      << "</td></tr>\n";
  }
  b << "</tbody>\n</table>\n";
}

}  // namespace

std::string class_summary_html(const ClassView& view, const ClassPage& page) {
  const auto& areas = area_names();
  std::ostringstream b;
  b << "<h1>geomech class report: " << html_escape(page.class_name) << "</h1>\n";
  const std::size_t done = view.students.size();
  if (!page.pending.empty()) {
    b << "<p class=\"partial\" id=\"in-progress\">In progress: " << done << " of " << done + page.pending.size()
      << " implementations checked. Not yet checked (a run started again resumes with them): ";
    for (std::size_t i = 0; i < page.pending.size(); ++i) b << (i ? ", " : "") << html_escape(page.pending[i]);
    b << ".";
    if (page.grades_withheld) b << " The gradebook is not written until every implementation is checked.";
    b << "</p>\n";
  }
  b << "<p class=\"note\">" << done << " implementations. Grades: " << html_escape(page.rubric_source) << ", "
    << view.assignment.size() << " slots in the assignment"
    << (view.assignment_from_rubric ? "" : " (every slot a student of the class provides)")
    << ". Each area cell: checks passed / checks run (bad: FAIL, CRASH, TIMEOUT or ERROR); n/w: checks of slots "
       "not written; d/o: checks in 50 digits or rationals the code or its language cannot run (double only). "
       "Click a heading to sort.</p>\n";
  write_class_table_html(b, view, areas);
  write_class_mistakes_html(b, view);
  b << "<h2 id=\"in-words\">Each student in words</h2>\n<ul>\n";
  for (const auto& s : view.students) {
    b << "<li id=\"words-" << html_escape(key_of(s.row->name)) << "\"><strong>" << html_escape(s.row->name)
      << "</strong>";
    if (!s.language.empty()) b << " (" << s.language << ")";
    b << ": ";
    const auto words = words_of(s);
    for (std::size_t i = 0; i < words.size(); ++i) b << (i ? "; " : "") << html_escape(words[i]);
    b << ".";
    if (!s.report_link.empty()) b << " <a href=\"" << html_escape(s.row->name) << "/report.html\">report</a>";
    b << "</li>\n";
  }
  b << "</ul>\n";
  for (const auto& s : view.students) {
    if (s.status == "does not compile") {
      b << "<h2>" << html_escape(s.row->name) << ": does not compile</h2>\n<pre>" << html_escape(s.row->build_message)
        << "</pre>\n";
    } else if (s.status == "not checked") {
      b << "<h2>" << html_escape(s.row->name) << ": not checked</h2>\n<pre>" << html_escape(s.row->problem)
        << "</pre>\n";
    } else if (s.status == kGraderError && s.row->suspect) {
      b << "<h2>" << html_escape(s.row->name) << ": the same machine fault in each of "
        << s.row->earlier_faults.size() + 1
        << " runs, while classmates checked fine: suspect (no grade; the lecturer decides)</h2>\n";
      for (const auto& f : s.row->earlier_faults) b << "<pre>" << html_escape(f) << "</pre>\n";
      b << "<pre>" << html_escape(grader_fault_of(*s.row)) << "</pre>\n";
    } else if (s.status == kGraderError) {
      b << "<h2>" << html_escape(s.row->name) << ": the grader's machine failed its check (no grade)</h2>\n<pre>"
        << html_escape(grader_fault_of(*s.row)) << "</pre>\n";
    }
  }
  return html_page("geomech class report: " + page.class_name, b.str(), kSortScript);
}

}  // namespace gm::harness
