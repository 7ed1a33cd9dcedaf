// Text that came from the code under test (an exception's message, its output, a description) as it
// may be shown: whatever a submission prints or raises reaches the console and the
// reports as inert text. Invalid UTF-8 becomes U+FFFD, and control characters other than newline
// and tab are made visible as \xNN (an escape sequence such as "\x1b[2K\r\x1b[32mPASS" would
// otherwise erase a line of a terminal showing report.md and print a false PASS in its place).
#pragma once

#include <cstddef>
#include <string>

namespace gm::harness {

std::string inert_text(const std::string& text);

// At most `cap` bytes of `text` (a submission may raise a message of any size): its
// beginning and its end, with the cut said in between ("[... 20971040 bytes cut: ...]"). Cut on
// UTF-8 boundaries. The caps the harness uses:
inline constexpr std::size_t kMessageCap = 8192;            // one message, traceback, compiler output
inline constexpr std::size_t kReportTextBudget = 2u << 20;  // all of a report's messages together
std::string bounded_text(const std::string& text, std::size_t cap = kMessageCap);

// Text from a submission inside a line of Markdown (a table cell, a list item, a heading): inert,
// on one line (newlines shown as <br>), with what Markdown or HTML would act on escaped: no raw
// HTML (<img onerror=...>: &lt;), no entity, no link or image ("](" escaped), no table cell closed
// early (\|). Backticks and emphasis characters are left as they are: a code span or emphasis
// changes no more than the look of the text (and the harness's own advice uses code spans).
std::string md_inline(const std::string& text);

// A relative path as a Markdown link target: every byte but letters, digits and "-._~/" percent-
// encoded (a name with a space or a parenthesis would end the link early).
std::string md_link_target(const std::string& path);

// Text from a submission as a Markdown code block: inert, fenced by more backticks than any run
// inside (a fence of three would be closed by the text's own, and what follows would be live).
std::string md_fenced(const std::string& text);

}  // namespace gm::harness
