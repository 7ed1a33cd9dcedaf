// A check is a stream of results (DESIGN.md "A check is a stream of results"): run_check
// tells its listeners as each (property, scalar, integrator) check starts and ends, in the order
// it schedules them, so that a failure reaches the student the moment its check ends rather than
// when the last one does. The console (harness/reports/console_stream.hpp) prints failures and a progress
// line as they come; the Markdown, JUnit and JSON writers still take the finished CheckResult.
#pragma once

#include "properties/runner.hpp"

#include <string>
#include <vector>

namespace gm::harness {

struct CheckResult;

struct CheckProgress {
  std::size_t done = 0;              // checks ended
  std::size_t total = 0;             // checks in the run (the pictures included)
  double elapsed = 0;                // seconds since the run started
  double left = -1;                  // estimated seconds still to go (< 0: not known yet)
  std::vector<std::string> running;  // the checks running now: "definition_hat_n [mp50]"
};

class CheckListener {
 public:
  virtual ~CheckListener() = default;
  // The run's schedule is made: `total` checks, of which `replayed` failed in the previous run
  // of this report and come first.
  virtual void scheduled(std::size_t /*total*/, std::size_t /*replayed*/) {}
  // A check started or ended: what runs now.
  virtual void progress(const CheckProgress& /*p*/) {}
  // One check ended with these verdicts (usually one; `replayed`: it failed last time).
  virtual void finished(const std::vector<Verdict>& /*verdicts*/, bool /*replayed*/, const CheckProgress& /*p*/) {}
  // Every check ended; the result is complete (sorted, accounted for).
  virtual void ended(const CheckResult& /*r*/) {}
};

}  // namespace gm::harness
