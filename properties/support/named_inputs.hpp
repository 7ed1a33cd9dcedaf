// Failure messages that show a case's inputs by the names the notes use (I, Pi, O, h, ...)
// instead of RapidCheck's list of types. The inputs are formatted only when a check
// fails, so passing cases pay nothing.
#pragma once

#include "properties/support/claims.hpp"
#include "properties/support/show.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace gm {

// "  Pi = [1/64, 0, 0]\n": one named input at full precision.
template <class X>
std::string named(const char* name, const X& x) {
  return std::string("    ") + name + " = " + show_value(x) + "\n";
}

// The inputs `describe()` returns, on one line: "I = [..], Pi = [..], h = 1/8".
inline std::string inputs_on_one_line(const std::string& lines) {
  std::string out, line;
  for (std::size_t i = 0; i <= lines.size(); ++i) {
    if (i == lines.size() || lines[i] == '\n') {
      const std::size_t first = line.find_first_not_of(' ');
      if (first != std::string::npos) out += (out.empty() ? "" : ", ") + line.substr(first);
      line.clear();
    } else {
      line += lines[i];
    }
  }
  return out;
}

// Runs `checks`; when one of them fails, appends the inputs `describe()` returns to the message.
// A finding on a claim nobody made that does not hold passes its case, and carries the case's
// inputs in its evidence instead ("does not hold ...; at I = [..], Pi = [..]"): its counterexample.
template <class Describe, class Checks>
void showing_inputs(Describe&& describe, Checks&& checks) {
  std::vector<std::pair<std::string, std::string>> before;
  for (const auto& f : recorded_claims()) before.emplace_back(f.claim, f.evidence);
  try {
    checks();
    for (auto& f : recorded_claims()) {
      if (f.claimed || f.holds) continue;
      if (std::find(before.begin(), before.end(), std::make_pair(f.claim, f.evidence)) != before.end()) continue;
      f.evidence += "; at " + inputs_on_one_line(describe());
    }
  } catch (rc::detail::CaseResult& r) {
    r.description += "\n  inputs, by the notes' names:\n" + describe();
    if (!r.description.empty() && r.description.back() == '\n') r.description.pop_back();
    throw;
  }
}

}  // namespace gm

namespace gm {

// When a failing slot's output is exactly what the notes print in a place recorded as
// an erratum (spec/catalogue.json), the failure says so and names the entry, so a student who
// followed the notes is not left to wonder. `matches_printed()` is evaluated only on failure.
template <class Matches, class Checks>
void recognising_erratum(Matches&& matches_printed, const char* entry, const char* printed, Checks&& checks) {
  try {
    checks();
  } catch (rc::detail::CaseResult& r) {
    bool matches = false;
    try {
      matches = matches_printed();
    } catch (...) {}
    if (matches)
      r.description = std::string("your result is the formula as printed in the notes, ") + printed +
                      ", which is an erratum: see spec/CATALOGUE.md, entry " + entry +
                      " (what holds instead is below)\n" + r.description;
    throw;
  }
}

}  // namespace gm
