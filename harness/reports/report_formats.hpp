// The report formats of a check, registered once (report_formats.cpp): each with its name, the file
// it is in a report folder, the option that also writes it to a file of its own, and how it renders
// a finished check. The report folder (write_report_dir), the options of every command that checks
// (`geomech check`, a student's check program, check-trajectory) and the end of each check
// (finish_check) loop over this list, so a new format is one more entry here and its baseline
// (tests/harness/reports/baselines/). The console is not one of them: it listens to the check
// as it runs (console_stream.hpp) and prints its summary at the end.
#pragma once

#include "harness/checking/check.hpp"
#include "spec/catalogue.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gm::harness {

struct ReportFormat {
  std::string name;    // "JUnit XML": what the option's help and the messages call it
  std::string file;    // its file in a report folder: "junit.xml"
  std::string option;  // "--junit": also write it to this file
  std::function<std::string(const CheckResult&, const Catalogue*)> render;
};

// Markdown, HTML, JUnit XML, JSON, in the order a report folder lists them.
const std::vector<ReportFormat>& report_formats();

// "report.md, report.html, junit.xml, verdicts.json and figures/": the files of a report folder,
// for the help of --report.
std::string report_folder_files();

// The formats asked for by their own options: option ("--junit") -> the file to write.
using FormatFiles = std::map<std::string, std::string>;

// Adds each format's option to `app` (CLI11), filling `files`.
template <class App>
void add_format_options(App& app, FormatFiles& files) {
  for (const ReportFormat& f : report_formats())
    app.template add_option_function<std::string>(
        f.option, [&files, option = f.option](const std::string& path) { files[option] = path; },
        "also write the " + f.name + " to this file");
}

}  // namespace gm::harness
