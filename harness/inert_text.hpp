// Text that came from the code under test (an exception's message, its output, a description) as it
// may be shown (issue 34): whatever a submission prints or raises reaches the console and the
// reports as inert text. Invalid UTF-8 becomes U+FFFD, and control characters other than newline
// and tab are made visible as \xNN (an escape sequence such as "\x1b[2K\r\x1b[32mPASS" would
// otherwise erase a line of a terminal showing report.md and print a false PASS in its place).
#pragma once

#include <string>

namespace gm::harness {

std::string inert_text(const std::string& text);

}  // namespace gm::harness
