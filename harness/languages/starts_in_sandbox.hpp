// Whether a served language's interpreter starts inside the sandbox, as a check starts it: shown to
// the sandbox (its installation read-only, harness/isolation/sandboxed_interpreter.hpp) and started
// there with the row's start_probe (arguments that do nothing: Python `-c "import sys"`, Node a
// WebAssembly memory). A failure there is the grader's machine, never the code: a check behind the
// sandbox and the grader's machine check (harness/class/grader_machine.hpp) ask this first.
#pragma once

#include "harness/languages/language.hpp"

#include <string>

namespace gm::harness {

// "" when it starts (or cannot be tried: not installed, which each check says in its own words, or
// a row with no probe, whose first check tries it); else what fails, in words, with its fix.
std::string interpreter_start_problem(const Language& language);

}  // namespace gm::harness
