#include "harness/class/class_console.hpp"

#include "harness/isolation/inert_text.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace gm::harness {

namespace {

// The interruption's text, for the signal handler: two buffers, the one to print named by an
// atomic index, so that a handler never reads a text being written.
constexpr std::size_t kCap = 16384;
char g_text[2][kCap];
std::size_t g_length[2] = {0, 0};
std::atomic<int> g_current{-1};
pid_t g_owner = 0;  // the class run; its forked checks inherit the handler and stay quiet
struct sigaction g_previous_int, g_previous_term;

extern "C" void on_interrupt(int sig) {
  if (::getpid() == g_owner) {
    const int k = g_current.load();
    if (k >= 0) {
      const ssize_t ignored = ::write(2, g_text[k], g_length[k]);
      (void)ignored;
    }
  }
  // Then as before: the signal's default, which ends the run (its checks die with it).
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

std::string duration_text(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return buf;
}

}  // namespace

ClassConsole::ClassConsole(std::size_t total, std::size_t done)
    : total_(total), done_(done), terminal_(::isatty(2) != 0), last_drawn_(Clock::now()), last_logged_(Clock::now()) {
  g_owner = ::getpid();
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, &g_previous_int);
  ::sigaction(SIGTERM, &sa, &g_previous_term);
}

ClassConsole::~ClassConsole() {
  clear_line();
  ::sigaction(SIGINT, &g_previous_int, nullptr);
  ::sigaction(SIGTERM, &g_previous_term, nullptr);
  g_current.store(-1);
}

void ClassConsole::on_interrupt_say(const std::string& text) {
  const int next = g_current.load() == 0 ? 1 : 0;
  const std::size_t n = std::min(text.size(), kCap);
  std::memcpy(g_text[next], text.data(), n);
  g_length[next] = n;
  g_current.store(next);
}

void ClassConsole::clear_line() {
  if (terminal_ && line_shown_) std::cerr << "\r\033[K" << std::flush;
  line_shown_ = false;
}

void ClassConsole::started(const std::string& name) { running_[name] = Clock::now(); }

void ClassConsole::finished(const std::string& name, const std::string& result, const std::string& grade,
                            double seconds) {
  running_.erase(name);
  ++done_;
  clear_line();
  std::cerr << "  [" << done_ << "/" << total_ << "] " << inert_text(name) << ": " << result
            << (grade.empty() ? "" : ", " + grade) << ", " << duration_text(seconds) << "\n"
            << std::flush;
  last_drawn_ = Clock::now() - std::chrono::seconds(1);  // the progress line again at once
}

void ClassConsole::tick() {
  const auto now = Clock::now();
  if (running_.empty()) return;
  if (terminal_ ? now - last_drawn_ < std::chrono::seconds(1) : now - last_logged_ < std::chrono::seconds(30)) return;
  std::ostringstream line;
  line << "  checking ";
  bool first = true;
  for (const auto& [name, since] : running_) {
    line << (first ? "" : ", ") << inert_text(name) << " ("
         << duration_text(std::chrono::duration<double>(now - since).count()) << ")";
    first = false;
  }
  line << "; " << done_ << " of " << total_ << " done";
  std::string text = line.str();
  if (terminal_) {
    constexpr std::size_t width = 118;
    if (text.size() > width) text = text.substr(0, width - 1) + "~";
    std::cerr << "\r\033[K" << text << std::flush;
    line_shown_ = true;
    last_drawn_ = now;
  } else {
    std::cerr << text << "\n" << std::flush;
    last_logged_ = now;
  }
}

}  // namespace gm::harness
