#include "harness/reports/report_formats.hpp"

#include "harness/reports/html_page.hpp"
#include "harness/reports/report.hpp"

#include <nlohmann/json.hpp>

namespace gm::harness {

namespace {

// report.md as a page: its figures inline (data: URLs), so that the page is one file.
std::string html_report(const CheckResult& r, const Catalogue* c) {
  const auto figures = report_figures(r);
  MarkdownHtml to_html;
  to_html.image = [&](const std::string& path) {
    for (const auto& f : figures)
      if (f.file == path) return "data:image/svg+xml;base64," + base64(f.svg);
    return std::string();
  };
  return html_page("geomech report: " + r.subject, markdown_to_html(markdown_report(r, c), to_html));
}

std::string json_text(const CheckResult& r, const Catalogue* c) {
  return json_report(r, c).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace

const std::vector<ReportFormat>& report_formats() {
  static const std::vector<ReportFormat> formats = {
      {"Markdown report", "report.md", "--markdown", markdown_report},
      {"HTML report", "report.html", "--html", html_report},
      {"JUnit XML", "junit.xml", "--junit", [](const CheckResult& r, const Catalogue*) { return junit_report(r); }},
      {"verdicts as JSON", "verdicts.json", "--json", json_text},
  };
  return formats;
}

std::string report_folder_files() {
  std::string list;
  for (const ReportFormat& f : report_formats()) list += f.file + ", ";
  return list.substr(0, list.size() - 2) + " and figures/";
}

}  // namespace gm::harness
