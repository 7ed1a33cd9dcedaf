#include "harness/checking/source_calls.hpp"

#include "core/subject.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
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

// Where each slot is defined: (offset, slot), sorted.
std::vector<std::pair<std::size_t, std::string>> definitions(const std::string& code, const Language& language) {
  std::vector<std::pair<std::size_t, std::string>> out;
  for (const auto& d : language.definitions(code))
    if (is_slot_name(d.name)) out.emplace_back(d.offset, d.name);
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

std::map<std::string, std::set<std::string>> slot_calls_in_text(const std::string& text, const Language& language) {
  std::map<std::string, std::set<std::string>> out;
  if (!language.code_only || !language.definitions) return out;
  const std::string code = language.code_only(text);
  const auto defs = definitions(code, language);
  for (std::size_t i = 0; i < defs.size(); ++i) {
    const std::size_t from = defs[i].first + defs[i].second.size();
    const std::size_t to = i + 1 < defs.size() ? defs[i + 1].first : code.size();
    for (const auto& c : calls_in(code.substr(from, to - from), defs[i].second)) out[defs[i].second].insert(c);
  }
  return out;
}

std::map<std::string, std::set<std::string>> slot_calls(const std::string& source, const Language& language,
                                                        const std::vector<CodeCell>& cells) {
  if (!cells.empty()) {
    std::map<std::string, std::set<std::string>> out;
    for (const auto& c : cells)
      for (const auto& [slot, callees] : slot_calls_in_text(c.code, language)) out[slot] = callees;  // the last wins
    return out;
  }
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(source, ec))) {
    // A folder of function files: each NAME<ext> holds the function NAME (and maybe subfunctions).
    std::map<std::string, std::set<std::string>> out;
    if (!language.folder_of_files || !language.code_only || language.extensions.empty()) return out;
    for (const auto& e : fs::directory_iterator(source, ec)) {
      if (e.path().extension() != language.extensions.front() || !e.is_regular_file(ec) || e.is_symlink(ec)) continue;
      const std::string name = e.path().stem().string();
      if (!is_slot_name(name)) continue;
      const std::string code = language.code_only(read_regular(e.path()));
      for (const auto& c : calls_in(code, name)) out[name].insert(c);
    }
    return out;
  }
  return slot_calls_in_text(read_regular(source), language);
}

}  // namespace gm::harness
