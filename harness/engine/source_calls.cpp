#include "harness/engine/source_calls.hpp"

#include "core/subject.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxBytes = 4u << 20;

// A regular file's bytes, never through a link and never more than kMaxBytes; "" otherwise.
std::string read_regular(const fs::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return "";
  struct stat st {};
  std::string out;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    char buf[65536];
    for (ssize_t n; out.size() < kMaxBytes && (n = ::read(fd, buf, sizeof buf)) > 0;)
      out.append(buf, static_cast<std::size_t>(n));
    if (out.size() > kMaxBytes) out.resize(kMaxBytes);
  }
  ::close(fd);
  return out;
}

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Comments and string literals blanked (same length), so that neither a comment naming a slot nor a
// string counts as a call.
std::string code_only(const std::string& text, const std::string& language) {
  std::string out = text;
  const bool python = language == "python", octave = language == "octave";
  std::size_t i = 0;
  auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  while (i < text.size()) {
    const char c = text[i];
    if ((python && c == '#') || (octave && (c == '%' || c == '#')) ||
        (!python && !octave && text.compare(i, 2, "//") == 0)) {
      const std::size_t end = text.find('\n', i);
      blank(i, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end;
    } else if (!python && !octave && text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      blank(i, end == std::string::npos ? text.size() : end + 2);
      i = end == std::string::npos ? text.size() : end + 2;
    } else if (python && (text.compare(i, 3, "\"\"\"") == 0 || text.compare(i, 3, "'''") == 0)) {
      const std::size_t end = text.find(text.substr(i, 3), i + 3);
      blank(i + 3, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end + 3;
    } else if (c == '"' || (c == '\'' && !octave)) {
      // (In Octave a ' is also the transpose: only "..." strings are blanked there.)
      std::size_t k = i + 1;
      while (k < text.size() && text[k] != c && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
      blank(i + 1, k);
      i = k + 1;
    } else {
      ++i;
    }
  }
  return out;
}

// Where each slot is defined: (offset, slot), sorted.
std::vector<std::pair<std::size_t, std::string>> definitions(const std::string& code, const std::string& language) {
  std::vector<std::pair<std::size_t, std::string>> out;
  std::regex def;
  if (language == "python")
    def = std::regex(R"((^|\n)[ \t]*def[ \t]+([A-Za-z_]\w*)[ \t]*\()");
  else if (language == "octave")
    def = std::regex(R"((^|\n)[ \t]*function[ \t]+(?:[^\n=]*=[ \t]*)?([A-Za-z_]\w*)[ \t]*[\(\n;])");
  else
    def = std::regex(R"((^|[\s>*&])([A-Za-z_]\w*)[ \t]*\([^;{}]*\)[^;{}]*\{)");
  for (auto it = std::sregex_iterator(code.begin(), code.end(), def); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[2].str();
    if (is_slot_name(name)) out.emplace_back(static_cast<std::size_t>(it->position(2)), name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The slots `body` calls (a slot name followed by `(`, or `<...>(` in C++), but `self`.
std::set<std::string> calls_in(const std::string& body, const std::string& self) {
  std::set<std::string> out;
  for (const auto& s : subject_slots()) {
    const std::string name = s.name;
    if (name == self) continue;
    for (std::size_t at = body.find(name); at != std::string::npos; at = body.find(name, at + 1)) {
      if (at > 0 && (is_word(body[at - 1]) || body[at - 1] == '.')) continue;  // a longer name, or x.name
      std::size_t k = at + name.size();
      if (k < body.size() && is_word(body[k])) continue;
      while (k < body.size() && (body[k] == ' ' || body[k] == '\t')) ++k;
      if (k < body.size() && body[k] == '<') {  // C++: name<T>(
        const std::size_t close = body.find('>', k);
        if (close == std::string::npos) continue;
        k = close + 1;
      }
      if (k < body.size() && body[k] == '(') {
        out.insert(name);
        break;
      }
    }
  }
  return out;
}

}  // namespace

std::map<std::string, std::set<std::string>> slot_calls_in_text(const std::string& text, const std::string& language) {
  const std::string code = code_only(text, language);
  const auto defs = definitions(code, language);
  std::map<std::string, std::set<std::string>> out;
  for (std::size_t i = 0; i < defs.size(); ++i) {
    const std::size_t from = defs[i].first + defs[i].second.size();
    const std::size_t to = i + 1 < defs.size() ? defs[i + 1].first : code.size();
    for (const auto& c : calls_in(code.substr(from, to - from), defs[i].second)) out[defs[i].second].insert(c);
  }
  return out;
}

std::map<std::string, std::set<std::string>> slot_calls(const std::string& source, const std::string& language) {
  std::error_code ec;
  const std::string lang = language == "python" || language == "octave" ? language : "c++";
  if (fs::is_directory(fs::symlink_status(source, ec))) {
    // An Octave folder: each NAME.m holds the function NAME (and maybe subfunctions).
    std::map<std::string, std::set<std::string>> out;
    for (const auto& e : fs::directory_iterator(source, ec)) {
      if (e.path().extension() != ".m" || !e.is_regular_file(ec) || e.is_symlink(ec)) continue;
      const std::string name = e.path().stem().string();
      if (!is_slot_name(name)) continue;
      const std::string code = code_only(read_regular(e.path()), "octave");
      for (const auto& c : calls_in(code, name)) out[name].insert(c);
    }
    return out;
  }
  return slot_calls_in_text(read_regular(source), lang);
}

}  // namespace gm::harness
