// The grader's machine, checked once, first (../shared/DESIGN.md, "A cause is an experiment"): before a
// class run or an autograder checks any student, what untrusted mode needs is tried as the sandbox's
// user, on this machine: the sandbox starts, the compilers' cache is within its reach, the Python and
// Octave interpreters can be shown to it and Python starts inside it. A failure there is the
// grader's, said once with its fix; no student is checked, so none is graded for it.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace gm::harness {

struct GraderNeeds {
  bool untrusted = true;         // trusted runs in-process: nothing of the sandbox is needed
  std::string cache_dir;         // the compilers' cache (made if missing)
  std::set<std::string> served;  // the served languages (harness/languages/language.hpp) to be checked
};

// Each problem in words: what fails, where, and the fix. Empty: the machine can check.
std::vector<std::string> grader_machine_problems(const GraderNeeds& needs);

// The problems as one message, for a refusal ("the grader's machine cannot check submissions: ...").
std::string grader_machine_message(const std::vector<std::string>& problems);

}  // namespace gm::harness
