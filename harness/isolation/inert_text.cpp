#include "harness/isolation/inert_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace gm::harness {

namespace {

// The length of the valid UTF-8 sequence starting at s[i] (1..4), or 0 when it is not one.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(i + k) >> 6) != 0x2) return 0;
  // Overlong forms, surrogates (U+D800..U+DFFF) and code points above U+10FFFF are not valid UTF-8.
  if (n == 2 && c < 0xC2) return 0;
  if (n == 3) {
    const unsigned cp = ((c & 0x0Fu) << 12) | ((b(i + 1) & 0x3Fu) << 6) | (b(i + 2) & 0x3Fu);
    if (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  }
  if (n == 4) {
    const unsigned cp =
        ((c & 0x07u) << 18) | ((b(i + 1) & 0x3Fu) << 12) | ((b(i + 2) & 0x3Fu) << 6) | (b(i + 3) & 0x3Fu);
    if (cp < 0x10000 || cp > 0x10FFFF) return 0;
  }
  return n;
}

}  // namespace

std::string inert_text(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD, the replacement character
      ++i;
      continue;
    }
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const bool c1 = n == 2 && c == 0xC2 && static_cast<unsigned char>(s[i + 1]) < 0xA0;  // U+0080..U+009F
    if ((n == 1 && ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F)) || c1) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", n == 1 ? c : static_cast<unsigned char>(s[i + 1]));
      out += buf;
    } else {
      out.append(s, i, n);
    }
    i += n;
  }
  return out;
}

std::string bounded_text(const std::string& text, std::size_t cap) {
  if (text.size() <= cap) return text;
  // Back to the start of a UTF-8 sequence (a continuation byte is 10xxxxxx).
  auto boundary = [&](std::size_t at) {
    while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) >> 6) == 0x2) --at;
    return at;
  };
  const std::size_t head = boundary(cap * 3 / 4);
  const std::size_t tail = boundary(text.size() - cap / 4);
  return text.substr(0, head) + "\n[... " + std::to_string(tail - head) +
         " bytes cut: a message from the code under test is shown up to " + std::to_string(cap) +
         " bytes, its beginning and its end ...]\n" + text.substr(tail);
}

std::string md_inline(const std::string& text) {
  const std::string s = inert_text(text);
  std::string out;
  out.reserve(s.size() + 16);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    switch (c) {
      case '<':
        out += "&lt;";
        break;  // no raw HTML, no autolink
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;  // no entity spelled by the text
      case '\n':
        out += "<br>";
        break;
      case '\t':
        out += ' ';
        break;
      case '|':
        out += "\\|";
        break;   // no table cell closed early
      case ']':  // no link or image: "[text](url)" needs "]("
        out += i + 1 < s.size() && s[i + 1] == '(' ? "\\]" : "]";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string md_link_target(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) != 0 || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      out += buf;
    }
  }
  return out;
}

std::string md_fenced(const std::string& text) {
  const std::string s = inert_text(text);
  std::size_t longest = 0, run = 0;
  for (char c : s) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string f(std::max<std::size_t>(3, longest + 1), '`');
  return f + "\n" + s + (s.empty() || s.back() == '\n' ? "" : "\n") + f + "\n";
}

}  // namespace gm::harness
