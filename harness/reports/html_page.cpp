#include "harness/reports/html_page.hpp"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm-extension_api.h>
#include <cmark-gfm.h>
#include <cmark-gfm/render.h>

#include <cctype>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace gm::harness {

namespace {

// An anchor or a relative path inside the report folder: the only link targets a page keeps. No
// scheme (no ':'), no absolute path, no "..", nothing percent-encoded: a path of the report's own files.
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

// A heading's id, from its words: "What to fix" -> "what-to-fix".
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

// The words of a node as a reader sees them (a heading's, an image's description).
std::string plain_text(cmark_node* node) {
  std::string out;
  cmark_iter* it = cmark_iter_new(node);
  for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
    cmark_node* n = cmark_iter_get_node(it);
    if (ev != CMARK_EVENT_ENTER) continue;
    const cmark_node_type type = cmark_node_get_type(n);
    if (type == CMARK_NODE_TEXT || type == CMARK_NODE_CODE) out += cmark_node_get_literal(n);
    if (type == CMARK_NODE_SOFTBREAK || type == CMARK_NODE_LINEBREAK) out += ' ';
  }
  cmark_iter_free(it);
  return out;
}

cmark_node* text_node(const std::string& text) {
  cmark_node* n = cmark_node_new(CMARK_NODE_TEXT);
  cmark_node_set_literal(n, text.c_str());
  return n;
}

// The HTML the page writes itself, not the Markdown: a line break, an anchor, a figure's <img>.
// Such a node is an HTML node marked with this extension, and only a node so marked is written as
// it is; the library's safe mode drops every other HTML node, so raw HTML from the Markdown never
// reaches the page. (A marked node rather than a custom one: a table cell may hold no custom node
// and no line break, but may hold HTML.) The renderer's buffer is the one the library's own
// extensions write to (cmark-gfm/render.h).
void write_page_html(cmark_syntax_extension*, cmark_html_renderer* renderer, cmark_node* node, cmark_event_type ev,
                     int) {
  if (ev != CMARK_EVENT_EXIT) cmark_strbuf_puts(renderer->html, cmark_node_get_literal(node));
}

cmark_syntax_extension* page_html() {
  static cmark_syntax_extension* const extension = [] {
    cmark_syntax_extension* e = cmark_syntax_extension_new("geomech-page-html");
    cmark_syntax_extension_set_html_render_func(e, write_page_html);
    return e;
  }();
  return extension;
}

void mark_as_page_html(cmark_node* n) {
  if (!cmark_node_set_syntax_extension(n, page_html())) throw std::logic_error("libcmark-gfm: cannot mark a node");
}

// A new node of the page's own HTML; every value in `html` escaped by the caller.
cmark_node* page_html_node(cmark_node_type type, const std::string& html) {
  cmark_node* n = cmark_node_new(type);
  cmark_node_set_literal(n, html.c_str());
  mark_as_page_html(n);
  return n;
}

void replace(cmark_node* old, cmark_node* with) {
  if (!cmark_node_replace(old, with)) {
    cmark_node_free(with);
    throw std::logic_error(std::string("libcmark-gfm: a ") + cmark_node_get_type_string(old) + " cannot become a " +
                           cmark_node_get_type_string(with));
  }
  cmark_node_free(old);
}

// The two forms of HTML the reports write themselves: `<br>` (md_inline's newline, inside a table
// cell or a list item) and a paragraph of just `<a id="..."></a>` (the anchor before a section,
// which report.md's links point to). Any other raw HTML is left to the library's safe mode.
bool is_line_break(cmark_node* n) { return std::string(cmark_node_get_literal(n)) == "<br>"; }

bool anchor_paragraph(cmark_node* p, std::string* id) {
  static const std::string open = "<a id=\"", close = "\">";
  cmark_node* a = cmark_node_first_child(p);
  cmark_node* b = a ? cmark_node_next(a) : nullptr;
  if (!b || cmark_node_next(b) || cmark_node_get_type(a) != CMARK_NODE_HTML_INLINE ||
      cmark_node_get_type(b) != CMARK_NODE_HTML_INLINE || std::string(cmark_node_get_literal(b)) != "</a>")
    return false;
  const std::string t = cmark_node_get_literal(a);
  if (t.rfind(open, 0) != 0 || t.size() < open.size() + close.size() ||
      t.compare(t.size() - close.size(), close.size(), close) != 0)
    return false;
  *id = t.substr(open.size(), t.size() - open.size() - close.size());
  return safe_target("#" + *id);
}

// A link to a file of the report (or an anchor) is kept, "X.md" pointing to "X.html"; any other
// is unlinked: its text stays, followed by its target as text ("far (https://example.org/x)").
void keep_or_unlink(cmark_node* link, const MarkdownHtml& o) {
  const std::string url = cmark_node_get_url(link);
  if (safe_target(url)) {
    cmark_node_set_url(link, link_target(url, o).c_str());
    return;
  }
  while (cmark_node* child = cmark_node_first_child(link))
    if (!cmark_node_insert_before(link, child)) throw std::logic_error("libcmark-gfm: cannot unlink a link's text");
  replace(link, text_node(" (" + url + ")"));
}

// A figure of the report, inline as a data: URI (the page loads nothing), or its path in words.
// The <img> is the page's own: the library's safe mode blanks every data: URI but png, gif, jpeg
// and webp ones, and the figures are SVG.
void inline_figure(cmark_node* image, const MarkdownHtml& o) {
  const std::string url = cmark_node_get_url(image);
  const std::string src = o.image && safe_target(url) ? o.image(url) : "";
  if (src.empty()) {
    cmark_node* em = cmark_node_new(CMARK_NODE_EMPH);
    cmark_node_append_child(em, text_node("[figure: " + url + "]"));
    replace(image, em);
  } else {
    replace(image, page_html_node(CMARK_NODE_HTML_INLINE, "<img src=\"" + html_escape(src) + "\" alt=\"" +
                                                              html_escape(plain_text(image)) + "\">"));
  }
}

struct ParserFree {
  void operator()(cmark_parser* p) const { cmark_parser_free(p); }
};
struct NodeFree {
  void operator()(cmark_node* n) const { cmark_node_free(n); }
};
struct CharFree {
  void operator()(char* s) const { std::free(s); }
};

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
  static std::once_flag registered;
  std::call_once(registered, cmark_gfm_core_extensions_ensure_registered);
  // Safe mode: CMARK_OPT_UNSAFE is never set, so the library writes raw HTML as
  // "<!-- raw HTML omitted -->" and blanks javascript:, vbscript:, file: and data: links. (In
  // 0.29 that is the default; CMARK_OPT_SAFE is kept for its name and does nothing.) Invalid UTF-8
  // becomes U+FFFD.
  const int options = CMARK_OPT_SAFE | CMARK_OPT_VALIDATE_UTF8;
  std::unique_ptr<cmark_parser, ParserFree> parser(cmark_parser_new(options));
  cmark_syntax_extension* table = cmark_find_syntax_extension("table");
  if (!parser || !table || !cmark_parser_attach_syntax_extension(parser.get(), table))
    throw std::runtime_error("libcmark-gfm: cannot start a parser with GitHub's tables");
  cmark_parser_feed(parser.get(), md.data(), md.size());
  std::unique_ptr<cmark_node, NodeFree> doc(cmark_parser_finish(parser.get()));

  // The nodes to change, innermost first (the reverse of document order), so that a node is changed
  // before anything holding it is replaced and freed.
  std::vector<cmark_node*> nodes;
  cmark_iter* it = cmark_iter_new(doc.get());
  for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;)
    if (ev == CMARK_EVENT_ENTER) nodes.push_back(cmark_iter_get_node(it));
  cmark_iter_free(it);
  for (auto n = nodes.rbegin(); n != nodes.rend(); ++n) {
    std::string id;
    switch (cmark_node_get_type(*n)) {
      case CMARK_NODE_HTML_INLINE:
        if (is_line_break(*n)) mark_as_page_html(*n);
        break;
      case CMARK_NODE_PARAGRAPH:
        if (anchor_paragraph(*n, &id))
          replace(*n, page_html_node(CMARK_NODE_HTML_BLOCK, "<a id=\"" + html_escape(id) + "\"></a>\n"));
        break;
      case CMARK_NODE_LINK:
        keep_or_unlink(*n, o);
        break;
      case CMARK_NODE_IMAGE:
        inline_figure(*n, o);
        break;
      default:
        break;
    }
  }

  // Block by block, so that each top-level heading gets the id its words give it ("## What to fix"
  // -> <h2 id="what-to-fix">): the library writes none, and its <hN> is the first thing it writes.
  std::string html;
  cmark_llist* extensions = cmark_parser_get_syntax_extensions(parser.get());
  for (cmark_node* block = cmark_node_first_child(doc.get()); block; block = cmark_node_next(block)) {
    const std::unique_ptr<char, CharFree> rendered(cmark_render_html(block, options, extensions));
    std::string part = rendered.get();
    if (cmark_node_get_type(block) == CMARK_NODE_HEADING)
      if (const std::string id = slug(plain_text(block)); !id.empty() && part.rfind("<h", 0) == 0)
        part.insert(3, " id=\"" + id + "\"");
    html += part;
  }
  return html;
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
