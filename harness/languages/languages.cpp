// The language table: its rows, in the order messages list them, and what finds a row.
#include "harness/languages/language.hpp"

#include "harness/languages/rows.hpp"

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <stdexcept>

namespace gm::harness {

namespace fs = std::filesystem;

const std::vector<Language>& languages() {
  // A new language: its row's file in this room and its line here (docs/DEVELOPING.md, "Adding a language").
  static const std::vector<Language> table{cpp_row(), python_row(), octave_row(), javascript_row(), notebook_row()};
  return table;
}

const Language& suite_language() { return languages().front(); }

const Language* language_of_extension(std::string_view extension) {
  for (const auto& l : languages())
    for (const auto& e : l.extensions)
      if (e == extension) return &l;
  return nullptr;
}

const Language* language_of(const std::string& path) {
  const fs::path p(path);
  if (const Language* l = language_of_extension(p.extension().string())) return l;
  std::error_code ec;
  if (fs::is_directory(p, ec) && !fs::is_empty(p, ec))
    for (const auto& l : languages())
      if (l.folder_of_files) return &l;
  return nullptr;
}

std::vector<std::string> beside_files(const Language& language, const std::string& source) {
  std::string comment = language.comment;
  while (!comment.empty() && comment.back() == ' ') comment.pop_back();
  if (comment.empty()) return {};
  static const std::regex plain(R"(^[A-Za-z0-9_-][A-Za-z0-9._-]*$)");
  const std::string key = "geomech: beside";
  std::set<std::string> names;
  std::size_t start = 0;
  for (int line = 1; start <= source.size(); ++line) {
    const std::size_t end = std::min(source.find('\n', start), source.size());
    std::string text = source.substr(start, end - start);
    start = end + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text.compare(first, comment.size(), comment) != 0) continue;
    std::size_t at = text.find_first_not_of(" \t", first + comment.size());
    if (at == std::string::npos || text.compare(at, key.size(), key) != 0) continue;
    at += key.size();
    const std::size_t name_at = text.find_first_not_of(" \t", at);
    if (name_at == at || name_at == std::string::npos) continue;  // "geomech: besides", or nothing named
    std::string name = text.substr(name_at);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    if (name.size() > 255 || !std::regex_match(name, plain))
      throw std::invalid_argument("line " + std::to_string(line) + ": `geomech: beside " + name +
                                  "` names no file beside this one: a file of this folder is named by its name "
                                  "alone (letters, digits, . _ -), never a path");
    names.insert(name);
  }
  return {names.begin(), names.end()};
}

std::string interpreter_named(const char* variable, const std::string& program, const std::string& fallback) {
  if (const char* named = std::getenv(variable); named && *named) {
    const std::string found = on_path(named);
    return found.empty() ? named : found;
  }
  const std::string found = on_path(program);
  return found.empty() ? fallback : found;
}

std::string c_like_code_only(const std::string& text, const std::string& quotes, char multiline) {
  std::string out = text;
  auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (text.compare(i, 2, "//") == 0) {
      const std::size_t end = std::min(text.find('\n', i), text.size());
      blank(i, end);
      i = end;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      blank(i, end == std::string::npos ? text.size() : end + 2);
      i = end == std::string::npos ? text.size() : end + 2;
    } else if (quotes.find(c) != std::string::npos) {
      std::size_t k = i + 1;
      while (k < text.size() && text[k] != c && (c == multiline || text[k] != '\n')) k += text[k] == '\\' ? 2 : 1;
      blank(i + 1, k);
      i = k + 1;
    } else {
      ++i;
    }
  }
  return out;
}

const Language* language_named(std::string_view id) {
  for (const auto& l : languages())
    if (l.id == id) return &l;
  return nullptr;
}

const Language* language_of_kernel(std::string_view kernel) {
  auto lower = [](std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  const std::string k = lower(kernel);
  for (const auto& l : languages())
    for (const auto& name : l.kernels)
      if (lower(name) == k) return &l;
  return nullptr;
}

namespace {

std::string in_words(const std::vector<std::string>& all, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < all.size(); ++i) out += (i == 0 ? "" : i + 1 == all.size() ? last : ", ") + all[i];
  return out;
}

}  // namespace

std::string extensions_in_words() {
  std::vector<std::string> all;
  for (const auto& l : languages()) all.insert(all.end(), l.extensions.begin(), l.extensions.end());
  return in_words(all, " or ");
}

std::string folder_in_words() {
  std::string out;
  for (const auto& l : languages())
    if (l.folder_of_files) out += ", nor a folder of " + l.extensions.front() + " files";
  return out;
}

std::string kernels_in_words() {
  std::vector<std::string> rows;
  for (const auto& l : languages())
    if (!l.kernels.empty()) rows.push_back(l.name + " (" + in_words(l.kernels, ", ") + ")");
  return in_words(rows, " or ");
}

std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why) {
  const Language* l = language_of(file);
  if (l && l->route == Route::Served) {
    if (language) *language = l->id;
    return l->server(file);
  }
  if (why) {
    std::vector<std::string> served;
    for (const auto& s : languages())
      if (s.route == Route::Served) served.insert(served.end(), s.extensions.begin(), s.extensions.end());
    *why = "not a " + in_words(served, " or ") + " file" + folder_in_words();
  }
  return {};
}

std::string on_path(const std::string& program) {
  if (program.find('/') != std::string::npos) return program;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t from = 0;
  for (;;) {
    const std::size_t colon = dirs.find(':', from);
    const std::string dir = dirs.substr(from, colon == std::string::npos ? std::string::npos : colon - from);
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return fs::absolute(candidate).string();
    if (colon == std::string::npos) break;
    from = colon + 1;
  }
  return "";
}

std::pair<int, int> line_and_column(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  return {line, column};
}

std::vector<std::pair<std::string, std::string>> slot_parameters(const std::string& sig) {
  const auto open = sig.find('(');
  const std::string args = sig.substr(open + 1, sig.rfind(')') - open - 1);
  std::vector<std::string> parts;
  std::size_t depth = 0, start = 0;
  for (std::size_t i = 0; i <= args.size(); ++i) {
    if (i == args.size() || (args[i] == ',' && depth == 0)) {
      parts.push_back(args.substr(start, i - start));
      start = i + 1;
    } else if (args[i] == '<') {
      ++depth;
    } else if (args[i] == '>') {
      --depth;
    }
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (auto q : parts) {
    while (!q.empty() && q.back() == ' ') q.pop_back();
    const auto sp = q.find_last_of(" &");
    out.emplace_back(q, q.substr(sp + 1));
  }
  return out;
}

std::string slot_result_type(const std::string& sig) { return sig.substr(0, sig.find('(')); }

}  // namespace gm::harness
