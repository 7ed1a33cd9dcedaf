// junit.xml: the JUnit report of a check, for CI (report.hpp, junit_report).
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/reports/html_page.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"
#include "harness/reports/svg.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gm::harness {

using namespace report_parts;
using nlohmann::json;

std::string junit_report(const CheckResult& r) {
  int failures = 0, errors = 0, skipped = 0;
  for (const auto& v : r.verdicts) {
    if (v.outcome == Outcome::Fail) ++failures;
    if (v.outcome == Outcome::Crash || v.outcome == Outcome::Timeout || v.outcome == Outcome::Error) ++errors;
    if (v.outcome == Outcome::NotProvided || v.outcome == Outcome::NotCharacterised) ++skipped;
  }
  skipped += static_cast<int>(r.left_to_thorough.size());
  const std::size_t tests = r.verdicts.size() + r.left_to_thorough.size();
  char time_buf[32];
  std::snprintf(time_buf, sizeof time_buf, "%.3f", r.seconds);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << "<testsuites name=\"geomech\" tests=\"" << tests << "\" failures=\"" << failures << "\" errors=\"" << errors
    << "\" skipped=\"" << skipped << "\" time=\"" << time_buf << "\">\n";
  x << "  <testsuite name=\"geomech." << xml_escape(r.subject) << "\" tests=\"" << tests << "\" failures=\"" << failures
    << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\"" << time_buf << "\">\n";
  x << "    <properties><property name=\"seed\" value=\"" << r.seed << "\"/></properties>\n";
  for (const auto& v : r.verdicts) {
    char t[32];
    std::snprintf(t, sizeof t, "%.3f", v.seconds);
    x << "    <testcase classname=\"" << xml_escape(r.subject + "." + v.scalar) << "\" name=\""
      << xml_escape(row_name(v)) << "\" time=\"" << t << "\">\n";
    std::string body = v.title + "\nspec entry: " + v.spec + "\n" + v.message;
    if (!inputs_in_message(v))
      for (const auto& [type, value] : v.counterexample) body += "\n" + type + " = " + value;
    if (is_problem(v.outcome)) body += "\nreproduce: " + reproduce_command(r, v);
    switch (v.outcome) {
      case Outcome::Fail:
        x << "      <failure type=\"FAIL\" message=\"" << xml_escape(first_line(v.message)) << "\">" << xml_escape(body)
          << "</failure>\n";
        break;
      case Outcome::Crash:
      case Outcome::Timeout:
      case Outcome::Error:
        if (!v.machine_fault.empty())  // the machine's: said as such, with its fix
          x << "      <error type=\"" << kMachineErrorWord << "\" message=\"" << xml_escape(first_line(v.machine_fault))
            << "\">" << xml_escape(body) << "</error>\n";
        else
          x << "      <error type=\"" << outcome_name(v.outcome) << "\" message=\"" << xml_escape(first_line(v.message))
            << "\">" << xml_escape(body) << "</error>\n";
        break;
      case Outcome::NotProvided:
        x << "      <skipped message=\"NOT PROVIDED: " << xml_escape(v.message) << "\"/>\n";
        break;
      case Outcome::NotCharacterised:
        x << "      <skipped message=\"NOT CHARACTERISED: " << xml_escape(first_line(v.message)) << "\"/>\n";
        break;
      case Outcome::Pass:
        break;
    }
    // The verdict's word ("holds (not claimed)", "does not hold (not claimed)", ...), as
    // every other view shows it.
    if (!v.integrator.empty() && !v.word.empty())
      x << "      <properties><property name=\"verdict\" value=\"" << xml_escape(v.word) << "\"/></properties>\n";
    x << "    </testcase>\n";
  }
  for (const auto& c : r.left_to_thorough)
    x << "    <testcase classname=\"" << xml_escape(r.subject + ".mp50") << "\" name=\"" << xml_escape(c)
      << "\" time=\"0.000\">\n      <skipped message=\"LEFT TO --thorough: " << xml_escape(r.thorough_only_note)
      << "\"/>\n    </testcase>\n";
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

}  // namespace gm::harness
