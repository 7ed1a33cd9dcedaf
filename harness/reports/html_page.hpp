// Reports as HTML pages that need nothing but themselves: the Markdown the reports write,
// turned into HTML, and a page around it. A page loads nothing (its Content-Security-Policy allows
// no network at all), its figures are inline (data: URIs), and every text is escaped: raw HTML in the
// Markdown is shown as text, but for the two forms the reports write themselves (`<br>` in a table
// cell, `<a id="..."></a>` before a heading). Links go only to anchors and to relative paths inside
// the report folder; anything else is shown as text.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace gm::harness {

// & < > " ' as entities.
std::string html_escape(std::string_view text);

// RFC 4648 base64, for data: URIs.
std::string base64(std::string_view bytes);

struct MarkdownHtml {
  // An image's source (the Markdown's path, e.g. "figures/x.svg") -> what its <img src> gets (a data:
  // URI), or "" to show the image's text instead.
  std::function<std::string(const std::string& path)> image;
  // Links to "X.md" go to "X.html" (the HTML pages sit beside the Markdown ones).
  bool md_links_to_html = true;
};

// The HTML of the Markdown the reports write: headings, paragraphs, lists (nested by two spaces),
// pipe tables, fenced code, **bold**, `code`, links and images.
std::string markdown_to_html(const std::string& markdown, const MarkdownHtml& options = {});

// A whole page: <!DOCTYPE html>, the title, the suite's style, `body`, and `script` (inline; may be
// empty). Its policy allows inline style and script and data: images, nothing else.
std::string html_page(const std::string& title, const std::string& body, const std::string& script = "");

}  // namespace gm::harness
