// Failure messages that show a case's inputs by the names the notes use (I, Pi, O, h, ...)
// instead of RapidCheck's list of types. The inputs are formatted only when a check
// fails, so passing cases pay nothing.
#pragma once

#include "properties/support/show.hpp"

#include <rapidcheck.h>

#include <string>

namespace gm {

// "  Pi = [1/64, 0, 0]\n": one named input at full precision.
template <class X>
std::string named(const char* name, const X& x) {
  return std::string("    ") + name + " = " + show_value(x) + "\n";
}

// Runs `checks`; when one of them fails, appends the inputs `describe()` returns to the message.
template <class Describe, class Checks>
void showing_inputs(Describe&& describe, Checks&& checks) {
  try {
    checks();
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
