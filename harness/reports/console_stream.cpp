#include "harness/reports/console_stream.hpp"

#include "harness/reports/report.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace gm::harness {

namespace {

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 10 ? "%.1f s" : "%.0f s", s);
  return buf;
}

std::string check_name(const Verdict& v) {
  return v.property + "  [" + v.scalar + (v.integrator.empty() ? "" : ", " + v.integrator) + "]";
}

// At most `n` lines of a message, each indented.
std::string head_lines(const std::string& message, int n) {
  std::istringstream lines(message);
  std::string line, out;
  int k = 0;
  while (std::getline(lines, line)) {
    if (k == n) {
      out += "  | ...  (the whole message is in the report)\n";
      break;
    }
    out += "  | " + line + "\n";
    ++k;
  }
  return out;
}

}  // namespace

ConsoleStream::ConsoleStream(std::string subject, const SubjectInfo& info, std::uint64_t seed, bool quiet,
                             std::ostream& out, std::ostream& err, bool err_is_terminal)
    : quiet_(quiet),
      out_(out),
      err_(err),
      terminal_(err_is_terminal),
      last_line_(std::chrono::steady_clock::now()),
      first_fixes_(info) {
  stub_.subject = std::move(subject);
  stub_.info = info;
  stub_.seed = seed;
}

void ConsoleStream::clear_progress() {
  if (terminal_ && line_shown_) {
    err_ << "\r\033[K" << std::flush;
    line_shown_ = false;
  }
}

void ConsoleStream::scheduled(std::size_t total, std::size_t replayed) {
  if (replayed > 0)
    out_ << "geomech: " << replayed << " check" << (replayed == 1 ? "" : "s")
         << " that failed in the previous run of this report come first\n"
         << std::flush;
  if (!quiet_ && !terminal_) err_ << "geomech: " << total << " checks scheduled\n" << std::flush;
}

void ConsoleStream::progress(const CheckProgress& p) {
  if (quiet_) return;
  std::ostringstream line;
  line << "geomech: " << p.done << "/" << p.total << " checks done";
  if (failures_ > 0) line << ", " << failures_ << " failing";
  if (!p.running.empty()) {
    line << "; running ";
    for (std::size_t i = 0; i < p.running.size(); ++i) line << (i ? ", " : "") << p.running[i];
  }
  if (p.left >= 0 && p.done < p.total) line << "; about " << seconds_text(p.left) << " left";
  std::string text = line.str();
  if (terminal_) {
    constexpr std::size_t width = 118;  // one terminal line, whatever was running
    if (text.size() > width) text = text.substr(0, width - 1) + "~";
    err_ << "\r\033[K" << text << std::flush;
    line_shown_ = true;
  } else if (std::chrono::steady_clock::now() - last_line_ > std::chrono::seconds(30) && p.done < p.total) {
    err_ << text << "\n" << std::flush;
    last_line_ = std::chrono::steady_clock::now();
  }
}

void ConsoleStream::finished(const std::vector<Verdict>& verdicts, bool replayed, const CheckProgress& p) {
  std::ostringstream text;
  for (const auto& v : verdicts) {
    if (replayed && !is_problem(v.outcome))
      text << "fixed: " << check_name(v) << " failed in the previous run and "
           << (v.outcome == Outcome::Pass ? std::string("passes") : "is " + std::string(outcome_name(v.outcome)))
           << " now\n";
    if (!is_problem(v.outcome)) continue;
    ++failures_;
    if (replayed) text << "still failing (as in the previous run): " << check_name(v) << "\n";
    // One finding per cause: a step that raises says so once, in full; the other checks it
    // kept from running say only that.
    if (!v.step_raised.empty() && !raises_seen_.insert(v.integrator + '\n' + v.step_raised).second) {
      if (!quiet_) text << outcome_name(v.outcome) << "  " << check_name(v) << ": your step raised, as above\n";
      continue;
    }
    // The machine's or the set-up's fault names no slot: it says what went wrong and its fix.
    if (!v.machine_fault.empty()) {
      text << "\nERROR (the machine's, not the code's)  " << check_name(v) << "  (" << seconds_text(p.elapsed)
           << " into the check)\n  " << v.machine_fault << "\n";
      continue;
    }
    // What to fix first: a slot's own definition check names the slot; an integrator's false claim
    // names the claim and what was measured.
    // (decided by the check as the verdicts arrive: harness/checking/first_fix.hpp)
    std::string lead;
    if (const auto named = first_fixes_.on_problem(v)) {
      const std::string& slot = named->slot;
      lead = named->callee.empty()
                 ? "FIRST FIX: " + slot_named(stub_.info, slot, "'") + " is wrong: its own check " + v.property +
                       " fails in " + v.scalar + ": " + first_line(v.message)
                 : "THEN:      " + slot_named(stub_.info, slot, "'") + " fails its own check " + v.property + " in " +
                       v.scalar + ", and it calls '" + named->callee + "', which is wrong: fix that first";
    }
    if (!v.step_raised.empty()) {
      lead += std::string(lead.empty() ? "" : "\n") + "YOUR STEP RAISES: integrator '" + v.integrator + "' raised at " +
              v.step_raised_where + ": " + first_line(v.step_raised) +
              " (the claims whose checks it stops are NOT VERIFIED; the rest NOT CHARACTERISED)";
      // A step written for floats, given 50-digit numbers (an mpf to numpy or math): its precision says so.
      const Language& l = *stub_.info.language;
      if (v.scalar == "mp50" && !l.double_only_error.empty() &&
          v.step_raised.find(l.double_only_error) != std::string::npos)
        lead += "\n  " + l.double_only_hint;
    }
    for (const auto& c : v.claims)
      if (c.claimed && !c.holds && v.step_raised.empty())
        lead += std::string(lead.empty() ? "" : "\n") + "FALSE CLAIM: integrator '" + v.integrator + "' claims " +
                c.claim + ": " + c.evidence;
    if (quiet_) {
      if (!lead.empty()) text << lead << "\n";
      continue;
    }
    text << "\n"
         << outcome_name(v.outcome) << "  " << check_name(v) << "  (" << seconds_text(p.elapsed)
         << " into the check)\n";
    if (!lead.empty()) text << lead << "\n";
    text << head_lines(v.message, 12);
    text << "  reproduce: " << reproduce_command(stub_, v) << "\n";
  }
  if (text.str().empty()) return;
  clear_progress();
  out_ << text.str() << std::flush;
}

void ConsoleStream::ended(const CheckResult&) { clear_progress(); }

}  // namespace gm::harness
