#include "harness/reports/html_page.hpp"

#include <cctype>
#include <sstream>
#include <vector>

namespace gm::harness {

namespace {

bool is_punct(char c) { return std::ispunct(static_cast<unsigned char>(c)) != 0; }

// An anchor or a relative path inside the report folder: the only link targets a page keeps.
bool safe_target(const std::string& t) {
  if (t.empty()) return false;
  if (t[0] == '#') {
    for (std::size_t i = 1; i < t.size(); ++i)
      if (!std::isalnum(static_cast<unsigned char>(t[i])) && t[i] != '-' && t[i] != '_' && t[i] != '.') return false;
    return t.size() > 1;
  }
  if (t[0] == '/' || t[0] == '.' || t.find("..") != std::string::npos) return false;
  for (char c : t)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' && c != '/' && c != '#')
      return false;
  return true;
}

std::string link_target(std::string t, const MarkdownHtml& o) {
  const auto hash = t.find('#');
  std::string path = t.substr(0, hash), frag = hash == std::string::npos ? "" : t.substr(hash);
  if (o.md_links_to_html && path.size() > 3 && path.compare(path.size() - 3, 3, ".md") == 0)
    path = path.substr(0, path.size() - 3) + ".html";
  return path + frag;
}

// The closing `)` of a link or image target starting at `at` (after the `(`), or npos.
std::size_t target_end(const std::string& s, std::size_t at) {
  for (std::size_t i = at; i < s.size(); ++i) {
    if (s[i] == ')') return i;
    if (s[i] == ' ' || s[i] == '\n') return std::string::npos;
  }
  return std::string::npos;
}

// The `]` closing a bracket opened before `at`, skipping escapes and code spans, or npos.
std::size_t bracket_end(const std::string& s, std::size_t at) {
  int depth = 1;
  for (std::size_t i = at; i < s.size(); ++i) {
    if (s[i] == '\\') {
      ++i;
    } else if (s[i] == '[') {
      ++depth;
    } else if (s[i] == ']' && --depth == 0) {
      return i;
    }
  }
  return std::string::npos;
}

std::string inline_html(const std::string& s, const MarkdownHtml& o, bool in_link = false) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\\' && i + 1 < s.size() && is_punct(s[i + 1])) {
      out += html_escape(std::string(1, s[++i]));
      continue;
    }
    if (c == '`') {
      std::size_t n = 0;
      while (i + n < s.size() && s[i + n] == '`') ++n;
      const std::string fence(n, '`');
      std::size_t close = s.find(fence, i + n);
      while (close != std::string::npos && close + n < s.size() && s[close + n] == '`')
        close = s.find(fence, close + n + 1);
      if (close == std::string::npos) {
        out += fence;
        i += n - 1;
        continue;
      }
      std::string code = s.substr(i + n, close - i - n);
      if (code.size() >= 2 && code.front() == ' ' && code.back() == ' ') code = code.substr(1, code.size() - 2);
      out += "<code>" + html_escape(code) + "</code>";
      i = close + n - 1;
      continue;
    }
    if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      const std::size_t close = s.find("**", i + 2);
      if (close != std::string::npos && close > i + 2) {
        out += "<strong>" + inline_html(s.substr(i + 2, close - i - 2), o, in_link) + "</strong>";
        i = close + 1;
        continue;
      }
    }
    const bool image = c == '!' && i + 1 < s.size() && s[i + 1] == '[';
    if ((c == '[' || image) && !in_link) {
      const std::size_t open = image ? i + 1 : i;
      const std::size_t close = bracket_end(s, open + 1);
      if (close != std::string::npos && close + 1 < s.size() && s[close + 1] == '(') {
        const std::size_t end = target_end(s, close + 2);
        if (end != std::string::npos) {
          const std::string text = s.substr(open + 1, close - open - 1), target = s.substr(close + 2, end - close - 2);
          if (image) {
            const std::string src = o.image && safe_target(target) ? o.image(target) : "";
            out += src.empty() ? "<em>[figure: " + html_escape(target) + "]</em>"
                               : "<img src=\"" + html_escape(src) + "\" alt=\"" + html_escape(text) + "\">";
          } else if (safe_target(target)) {
            out += "<a href=\"" + html_escape(link_target(target, o)) + "\">" + inline_html(text, o, true) + "</a>";
          } else {
            out += inline_html(text, o, true) + " (" + html_escape(target) + ")";
          }
          i = end;
          continue;
        }
      }
    }
    if (c == '<' && s.compare(i, 4, "<br>") == 0) {
      out += "<br>";
      i += 3;
      continue;
    }
    // An entity the Markdown already spells (md_inline writes < as &lt;) is one character, not
    // text to escape again ("&amp;lt;" showed "&lt;ad*_xi mu, eta&gt;" in report.html).
    if (c == '&') {
      bool entity = false;
      for (const char* e : {"&lt;", "&gt;", "&amp;", "&quot;", "&#39;"})
        if (s.compare(i, std::char_traits<char>::length(e), e) == 0) {
          out += e;
          i += std::char_traits<char>::length(e) - 1;
          entity = true;
          break;
        }
      if (entity) continue;
    }
    out += html_escape(std::string(1, c));
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// The cells of a table row, split at unescaped pipes outside code spans.
std::vector<std::string> table_cells(const std::string& line) {
  std::string s = trim(line);
  if (!s.empty() && s.front() == '|') s.erase(0, 1);
  if (!s.empty() && s.back() == '|' && (s.size() < 2 || s[s.size() - 2] != '\\')) s.pop_back();
  std::vector<std::string> cells;
  std::string cur;
  bool code = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      cur += s[i];
      cur += s[++i];
    } else if (s[i] == '`') {
      code = !code;
      cur += s[i];
    } else if (s[i] == '|' && !code) {
      cells.push_back(trim(cur));
      cur.clear();
    } else {
      cur += s[i];
    }
  }
  cells.push_back(trim(cur));
  return cells;
}

bool is_table_rule(const std::string& line) {
  const std::string t = trim(line);
  if (t.empty() || t[0] != '|') return false;
  for (char c : t)
    if (c != '|' && c != '-' && c != ':' && c != ' ') return false;
  return t.find("---") != std::string::npos;
}

bool anchor_line(const std::string& line, std::string* id) {
  static const std::string open = "<a id=\"", close = "\"></a>";
  const std::string t = trim(line);
  if (t.rfind(open, 0) != 0 || t.size() < open.size() + close.size() ||
      t.compare(t.size() - close.size(), close.size(), close) != 0)
    return false;
  const std::string x = t.substr(open.size(), t.size() - open.size() - close.size());
  if (!safe_target("#" + x)) return false;
  *id = x;
  return true;
}

std::string slug(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if ((c == ' ' || c == '-' || c == '_') && !out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i < bytes.size()) {
    const unsigned a = static_cast<unsigned char>(bytes[i]);
    const unsigned b = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned v = (a << 16) | (b << 8);
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string markdown_to_html(const std::string& md, const MarkdownHtml& o) {
  std::vector<std::string> lines;
  {
    std::istringstream in(md);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  std::ostringstream html;
  std::vector<std::string> paragraph;
  auto flush_paragraph = [&] {
    if (paragraph.empty()) return;
    std::string text;
    for (const auto& l : paragraph) text += (text.empty() ? "" : "\n") + l;
    html << "<p>" << inline_html(text, o) << "</p>\n";
    paragraph.clear();
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::string t = trim(line);
    std::string id;
    // Fenced code: as long a fence closes it.
    if (t.rfind("```", 0) == 0 || t.rfind("~~~", 0) == 0) {
      flush_paragraph();
      const char f = t[0];
      std::size_t n = 0;
      while (n < t.size() && t[n] == f) ++n;
      std::string code;
      std::size_t j = i + 1;
      for (; j < lines.size(); ++j) {
        const std::string u = trim(lines[j]);
        if (u.size() >= n && u.find_first_not_of(f) == std::string::npos) break;
        code += lines[j] + "\n";
      }
      html << "<pre><code>" << html_escape(code) << "</code></pre>\n";
      i = j;
      continue;
    }
    if (t.empty()) {
      flush_paragraph();
      continue;
    }
    if (anchor_line(line, &id)) {
      flush_paragraph();
      html << "<a id=\"" << html_escape(id) << "\"></a>\n";
      continue;
    }
    if (t[0] == '#') {
      std::size_t level = 0;
      while (level < t.size() && t[level] == '#') ++level;
      if (level <= 6 && level < t.size() && t[level] == ' ') {
        flush_paragraph();
        const std::string text = trim(t.substr(level + 1));
        html << "<h" << level << " id=\"" << slug(text) << "\">" << inline_html(text, o) << "</h" << level << ">\n";
        continue;
      }
    }
    if (t[0] == '|' && i + 1 < lines.size() && is_table_rule(lines[i + 1])) {
      flush_paragraph();
      html << "<table>\n<thead><tr>";
      for (const auto& c : table_cells(line)) html << "<th>" << inline_html(c, o) << "</th>";
      html << "</tr></thead>\n<tbody>\n";
      std::size_t j = i + 2;
      for (; j < lines.size() && !trim(lines[j]).empty() && trim(lines[j])[0] == '|'; ++j) {
        html << "<tr>";
        for (const auto& c : table_cells(lines[j])) html << "<td>" << inline_html(c, o) << "</td>";
        html << "</tr>\n";
      }
      html << "</tbody>\n</table>\n";
      i = j - 1;
      continue;
    }
    if (t.rfind("- ", 0) == 0 || t.rfind("* ", 0) == 0) {
      flush_paragraph();
      // A list: items by their indent (two spaces a level); a line without a marker continues the item.
      int depth = 0;
      std::size_t j = i;
      bool open_item = false;
      for (; j < lines.size(); ++j) {
        const std::string& l = lines[j];
        const std::string u = trim(l);
        if (u.empty()) break;
        const bool item = u.rfind("- ", 0) == 0 || u.rfind("* ", 0) == 0;
        if (!item) {
          if (!open_item) break;
          html << "\n" << inline_html(u, o);
          continue;
        }
        const int level = static_cast<int>(l.find_first_not_of(' ') / 2) + 1;
        if (level > depth) {
          for (; depth < level; ++depth) html << "\n<ul>\n<li>";
        } else {
          html << "</li>\n";
          for (; depth > level; --depth) html << "</ul>\n</li>\n";
          html << "<li>";
        }
        html << inline_html(u.substr(2), o);
        open_item = true;
      }
      for (; depth > 0; --depth) html << "</li>\n</ul>\n";
      i = j - 1;
      continue;
    }
    paragraph.push_back(t);
  }
  flush_paragraph();
  return html.str();
}

std::string html_page(const std::string& title, const std::string& body, const std::string& script) {
  std::ostringstream p;
  p << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    // Nothing from the network, ever: no fetch, no font, no frame; inline style and script and
    // data: images only.
    << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
       "style-src 'unsafe-inline'; script-src 'unsafe-inline'; base-uri 'none'; form-action 'none'\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>" << html_escape(title) << "</title>\n<style>\n"
    << "body{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:75em;padding:0 "
       "1em;line-height:1.45;color:#222}\n"
       "table{border-collapse:collapse;margin:1em 0;font-size:.92em}\n"
       "th,td{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top}\n"
       "th{background:#f2f2f2}\nth.sortable{cursor:pointer}\nth.sortable:after{content:' \\2195';color:#888}\n"
       "code,pre{font-family:ui-monospace,monospace;font-size:.9em}\n"
       "pre{background:#f6f6f6;padding:.6em;overflow-x:auto;white-space:pre-wrap}\n"
       "img{max-width:100%;height:auto;border:1px solid #ddd;margin:.5em 0}\n"
       ".PASS{color:#176b2c;font-weight:bold}.FAIL,.bad{color:#a11;font-weight:bold}\n"
       ".INCOMPLETE,.partial{color:#8a5a00;font-weight:bold}\n"
       ".note{color:#555}\n"
    << "</style>\n</head>\n<body>\n"
    << body;
  if (!script.empty()) p << "<script>\n" << script << "\n</script>\n";
  p << "</body>\n</html>\n";
  return p.str();
}

}  // namespace gm::harness
