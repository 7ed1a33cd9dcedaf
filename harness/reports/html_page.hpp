// Reports as HTML pages that need nothing but themselves: the Markdown the reports write, rendered
// by libcmark-gfm (CommonMark with GitHub's tables) in its safe mode, and a page around it. A page
// loads nothing (its Content-Security-Policy allows no network at all), its figures are inline
// (data: URIs), and every text is escaped once. Raw HTML in the Markdown is dropped, but for the two
// forms the reports write themselves (`<br>` in a table cell or list item, a paragraph of
// `<a id="..."></a>` before a heading). Links go only to anchors and to relative paths inside the
// report folder; any other link is unlinked, its text kept and its target shown as text.
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

// The HTML of CommonMark with GitHub's pipe tables: each top-level heading with an id from its words
// ("## What to fix" -> <h2 id="what-to-fix">), links and images as above.
std::string markdown_to_html(const std::string& markdown, const MarkdownHtml& options = {});

// A whole page: <!DOCTYPE html>, the title, the suite's style, `body`, and `script` (inline; may be
// empty). Its policy allows inline style and script and data: images, nothing else.
std::string html_page(const std::string& title, const std::string& body, const std::string& script = "");

}  // namespace gm::harness
