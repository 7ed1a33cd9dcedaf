// The console as a listener of a running check: each failure is printed the moment its
// check ends, led by what to fix first (the slot whose own definition check fails, or the
// integrator's false claim), and a progress line names the checks running and estimates what is
// left: in a terminal one line kept up to date on stderr, in a CI log a line every 30 seconds. The
// table, the summary and the claims still come at the end (console_report). With --quiet only the
// FIRST FIX lines and the false claims are streamed.
#pragma once

#include "harness/checking/check.hpp"
#include "harness/checking/first_fix.hpp"

#include <chrono>
#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace gm::harness {

class ConsoleStream : public CheckListener {
 public:
  // `subject` and `seed` name the run in the replay commands; `out` takes the failures, `err` the
  // progress (terminal: rewritten in place; otherwise every 30 s).
  ConsoleStream(std::string subject, const SubjectInfo& info, std::uint64_t seed, bool quiet, std::ostream& out,
                std::ostream& err, bool err_is_terminal);

  void scheduled(std::size_t total, std::size_t replayed) override;
  void progress(const CheckProgress& p) override;
  void finished(const std::vector<Verdict>& verdicts, bool replayed, const CheckProgress& p) override;
  void ended(const CheckResult& r) override;

  int failures_printed() const { return failures_; }

 private:
  void clear_progress();

  CheckResult stub_;  // subject, info and seed: what reproduce_command needs
  bool quiet_;
  std::ostream& out_;
  std::ostream& err_;
  bool terminal_;
  bool line_shown_ = false;
  std::chrono::steady_clock::time_point last_line_;
  FirstFixesSoFar first_fixes_;        // the slots named in a FIRST FIX line, decided by the check
  std::set<std::string> raises_seen_;  // integrator and message of each step raise already shown
  int failures_ = 0;
};

}  // namespace gm::harness
