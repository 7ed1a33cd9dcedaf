// What a class run says on the console while it runs ("nothing for 6.5 minutes after the
// banner"): a line for each student as their check ends (verdict, grade, time), a progress line
// naming who is being checked and for how long (redrawn in place on a terminal, a line every 30 s
// in a log), and, on Ctrl-C (SIGINT) or SIGTERM, what was kept and the command that resumes.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <string>

namespace gm::harness {

class ClassConsole {
 public:
  // `total` implementations in this run, `done` of them already finished (resumed or refused).
  ClassConsole(std::size_t total, std::size_t done);
  ~ClassConsole();
  ClassConsole(const ClassConsole&) = delete;
  ClassConsole& operator=(const ClassConsole&) = delete;

  void started(const std::string& name);
  // "  [3/7] bob: FAIL, 8.00 of 20, 12.3 s"
  void finished(const std::string& name, const std::string& result, const std::string& grade, double seconds);
  // The progress line, when it is due (call often).
  void tick();
  // What an interruption prints from now on: the results kept and the command that resumes.
  void on_interrupt_say(const std::string& text);

 private:
  using Clock = std::chrono::steady_clock;
  void clear_line();
  std::size_t total_, done_;
  std::map<std::string, Clock::time_point> running_;
  bool terminal_;
  bool line_shown_ = false;
  Clock::time_point last_drawn_, last_logged_;
};

}  // namespace gm::harness
