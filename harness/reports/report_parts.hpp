// What the report's formats share: the words and cells they all print the same way (the console
// summary, report.md, junit.xml and verdicts.json, each in a file of its own: report_console.cpp,
// report_markdown.cpp, report_junit.cpp, report_json.cpp). Rendering only: what a verdict is, which
// slot to fix first and what a claim came to are decided by the check (harness/checking/).
#pragma once

#include "harness/checking/check.hpp"
#include "spec/catalogue.hpp"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness::report_parts {

const Property* property_of(const Verdict& v);
std::string eps_text(double units);  // "3.2 eps"
// How the report names a slot to fix (harness::slot_named of the result's subject).
std::string slot_named(const CheckResult& r, const std::string& slot, const char* quote);
std::string file_safe(const std::string& s);                 // letters, digits, '-' and '_' only
std::string place_of(const Verdict& v, const Catalogue* c);  // the notes' place of its spec entry, or ""
// Rows of the result table: property (+ integrator) -> scalar -> verdict, in verdict order.
std::vector<std::pair<std::string, std::map<std::string, const Verdict*>>> table_rows(const CheckResult& r);
bool nothing_ran(const std::map<std::string, const Verdict*>& by_scalar);
// The table cell of a verdict: its decided word, with what a pass measured.
std::string verdict_cell(const Verdict& v, bool exact_column);
std::string summary_counts(const CheckResult& r);  // "12 PASS, 1 FAIL, ..."
std::string seconds_text(double s);                // "3.4 s"

// Groups the slots a subject lacks, with the properties that need them.
struct Missing {
  std::map<std::string, std::set<std::string>> by_reason;  // reason -> "property [scalar]" rows
};
Missing missing_of(const CheckResult& r);
// Why a NOT PROVIDED check did not run: "not written" or "double only".
std::string not_provided_kind(const CheckResult& r, const Verdict& v);

std::string md_cell(const std::string& s);  // a table cell or a list item: inert, on one line
std::string fence(const std::string& s);    // a code block that no text inside can close
// " (declared domain: |Omega| <= 1e+06, h >= 1e-09; nothing outside it is checked)", or empty.
std::string domain_words(const StepDomain& d);
std::string precision_words(const IntegratorInfo& integ);  // "computes in float (stated: ...); judged at ..."
// Whether the verdict is a check of a claim its integrator made.
bool judges_a_claim_made(const CheckResult& r, const Verdict& v);
std::string anchor_of(const Verdict& v);  // report.md's anchor of a verdict's section

}  // namespace gm::harness::report_parts
