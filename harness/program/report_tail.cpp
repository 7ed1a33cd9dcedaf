#include "harness/program/report_tail.hpp"

#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"

#include <iostream>

namespace gm::harness {

int finish_check(const CheckResult& r, const Catalogue* catalogue, const ReportTail& tail) {
  if (tail.quiet) {
    std::cout << r.subject << ": " << r.verdict_word() << " (" << report_parts::summary_counts(r) << ")"
              << (r.left_to_thorough.empty()
                      ? ""
                      : "; " + std::to_string(r.left_to_thorough.size()) + " costly 50-digit runs left to --thorough")
              << "\n";
    for (const auto& u : r.unchecked) std::cout << "UNCHECKED: " << u << "\n";  // why it is not a pass
  } else {
    std::cout << console_report(r, catalogue);
  }
  int status = r.exit_code();
  try {
    if (!tail.report_dir.empty()) {
      write_report_dir(r, tail.report_dir, catalogue);
      std::cout << "report: " << tail.report_dir << "/report.md (JUnit: " << tail.report_dir << "/junit.xml)\n";
    }
    for (const ReportFormat& f : report_formats())
      if (const auto to = tail.also.find(f.option); to != tail.also.end() && !to->second.empty())
        write_file_atomically(to->second, f.render(r, catalogue));
  } catch (const std::exception& e) {
    std::cerr << "geomech: " << e.what() << "\n";
    status = 2;
  }
  return status;
}

}  // namespace gm::harness
