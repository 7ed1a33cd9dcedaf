#include "harness/class/grader_machine.hpp"

#include "harness/isolation/sandbox.hpp"
#include "harness/languages/language.hpp"
#include "harness/languages/starts_in_sandbox.hpp"
#include "harness/remote/remote_subject.hpp"

#include <unistd.h>
#include <filesystem>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

std::string who() { return sandbox_uid() == 65534 ? "nobody" : "this user"; }

// The cache: the sandboxed compiler writes there, so every folder on the way must let the sandbox's
// user pass.
void try_cache(const std::string& cache_dir, std::vector<std::string>& problems) {
  std::error_code ec;
  const fs::path dir = fs::absolute(cache_dir, ec);
  fs::create_directories(dir, ec);
  if (ec) {
    problems.push_back("the compilers' cache " + dir.string() + " cannot be made: " + ec.message() +
                       ". Fix: --cache-dir DIR, a folder this user can write");
    return;
  }
  const std::string blocked = sandbox_cannot_reach(dir.string());
  if (blocked.empty()) return;
  problems.push_back("the compilers' cache " + dir.string() + " is out of the sandbox's reach: its user (" + who() +
                     ") cannot pass " + blocked +
                     " (a folder only its owner may enter, as mktemp -d makes). Fix: `chmod o+x " + blocked +
                     "`, or --cache-dir DIR in a folder every user may pass");
}

}  // namespace

std::vector<std::string> grader_machine_problems(const GraderNeeds& needs) {
  std::vector<std::string> problems;
  if (!needs.untrusted) return problems;
  if (const std::string why = sandbox_unavailable(); !why.empty()) {
    problems.push_back(why);
    return problems;  // nothing else can be tried inside it
  }
  if (!needs.cache_dir.empty()) try_cache(needs.cache_dir, problems);
  for (const auto& l : languages())
    if (l.route == Route::Served && needs.served.count(l.id))
      if (const std::string p = interpreter_start_problem(l); !p.empty()) problems.push_back(p);
  return problems;
}

std::string grader_machine_message(const std::vector<std::string>& problems) {
  std::string m = "the grader's machine cannot check submissions (nothing was checked, nobody was graded):";
  for (const auto& p : problems) m += "\n  - " + p;
  return m;
}

}  // namespace gm::harness
