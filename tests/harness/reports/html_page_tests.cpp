// Reports as HTML pages: report.md as a page that loads nothing and runs nothing of the
// student's, its structure kept (rendered by libcmark-gfm in its safe mode).
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/html_page.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace gm::harness;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(HtmlPage, ReportMarkdownBecomesEscapedHtmlWithItsStructure) {
  const std::string md =
      "# geomech report: <img src=x onerror=alert(1)>\n\n"
      "Source: `a<b>.py`\n\n"
      "## What to fix\n\n"
      "- **Python function `casimir` is wrong**: fails in [double](#d-casimir): x \\| y <script>alert(1)</script>\n"
      "  - these fail too: `euler_3_8`\n\n"
      "| property | double |\n|---|---|\n| `p` | [**FAIL**](#d-casimir) |\n| a \\| b | line<br>two |\n\n"
      "<a id=\"d-casimir\"></a>\n### FAIL: casimir\n\n"
      "````\nraise ValueError('```')\n<b>bold?</b>\n````\n\n"
      "[evil](javascript:alert(1)) [far](https://example.org/x) [mine](alice/report.md) [fig](figures/a.svg)\n\n"
      "![figures/a.svg](figures/a.svg)\n\n![missing](figures/none.svg)\n";
  MarkdownHtml o;
  o.image = [](const std::string& p) {
    return p == "figures/a.svg" ? "data:image/svg+xml;base64," + base64("<svg/>") : "";
  };
  const std::string h = markdown_to_html(md, o);
  // Nothing from the text is live.
  EXPECT_EQ(h.find("<script"), std::string::npos) << h;
  EXPECT_EQ(h.find("<img src=x"), std::string::npos) << h;
  EXPECT_EQ(h.find("<b>"), std::string::npos) << h;
  EXPECT_EQ(h.find("href=\"javascript"), std::string::npos) << h;
  EXPECT_EQ(h.find("href=\"https"), std::string::npos) << h;  // no network, not even a link out
  // Raw HTML is dropped (the text between the tags is text); in a code block it is code, escaped.
  EXPECT_NE(h.find("x | y <!-- raw HTML omitted -->alert(1)<!-- raw HTML omitted -->"), std::string::npos) << h;
  EXPECT_NE(h.find("raise ValueError('```')\n&lt;b&gt;bold?&lt;/b&gt;"), std::string::npos) << h;
  // The structure is kept: the control that the page is not just escaped text.
  EXPECT_NE(h.find("<h2 id=\"what-to-fix\">What to fix</h2>"), std::string::npos) << h;
  EXPECT_NE(h.find("<strong>Python function <code>casimir</code> is wrong</strong>"), std::string::npos) << h;
  EXPECT_NE(h.find("<ul>\n<li>these fail too: <code>euler_3_8</code>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td><a href=\"#d-casimir\"><strong>FAIL</strong></a></td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td>a | b</td>\n<td>line<br>two</td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<a id=\"d-casimir\"></a>"), std::string::npos) << h;
  EXPECT_NE(h.find("<a href=\"alice/report.html\">mine</a>"), std::string::npos) << h;
  EXPECT_NE(h.find("<img src=\"data:image/svg+xml;base64,PHN2Zy8+\" alt=\"figures/a.svg\">"), std::string::npos) << h;
  EXPECT_NE(h.find("<em>[figure: figures/none.svg]</em>"), std::string::npos) << h;
  const std::string page = html_page("t <x>", h);
  EXPECT_NE(page.find("Content-Security-Policy\" content=\"default-src 'none'; img-src data:"), std::string::npos);
  EXPECT_NE(page.find("<title>t &lt;x&gt;</title>"), std::string::npos);
  EXPECT_EQ(base64("Ma"), "TWE=");
  EXPECT_EQ(base64("Man"), "TWFu");
  EXPECT_EQ(base64("M"), "TQ==");
}

// Escaped once: report.md writes "<" as "&lt;" (md_inline), which the page shows as "<",
// not as "&lt;" ("&amp;lt;ad*_xi mu, eta&amp;gt;" in 22 cells of one report). The control: text that
// is not an entity is still escaped, and a tag is dropped.
TEST(HtmlPage, AnEntityOfTheMarkdownIsEscapedOnce) {
  const std::string h = markdown_to_html("| x |\n|---|\n| &lt;ad*_xi mu, eta&gt; & x < y <b> |\n");
  EXPECT_NE(h.find("<td>&lt;ad*_xi mu, eta&gt; &amp; x &lt; y <!-- raw HTML omitted --></td>"), std::string::npos) << h;
  EXPECT_EQ(h.find("&amp;lt;"), std::string::npos) << h;
}

// Raw HTML in the Markdown, in a block or inline, is dropped: nothing of it reaches the page, not
// as a tag and not as an attribute. The control, in the same text: the two forms the reports write
// themselves, a line break and an anchor, are kept; an anchor or a line break with anything more
// in it is raw HTML like any other.
TEST(HtmlPage, RawHtmlInTheMarkdownIsDropped) {
  const std::string md =
      "<script>alert(1)</script>\n\n"
      "<iframe src=\"https://example.org\"></iframe>\n\n"
      "<a id=\"x\" onclick=\"alert(1)\"></a>\n\n"
      "<a id=\"kept\"></a>\n"
      "## Section\n\n"
      "a <img src=x onerror=alert(2)> b <a href=\"https://example.org\">c</a> d<br onmouseover=alert(3)>e\n\n"
      "| cell |\n|---|\n| one<br>two <style>body{}</style> |\n";
  const std::string h = markdown_to_html(md);
  for (const char* live : {"<script", "<iframe", "<img", "<style", "onerror", "onclick", "onmouseover", "href"})
    EXPECT_EQ(h.find(live), std::string::npos) << live << " in\n" << h;
  EXPECT_EQ(count(h, "<!-- raw HTML omitted -->"), 10u) << h;
  EXPECT_NE(h.find("<a id=\"kept\"></a>\n<h2 id=\"section\">Section</h2>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td>one<br>two <!-- raw HTML omitted -->body{}<!-- raw HTML omitted --></td>"), std::string::npos)
      << h;
}

// A submission's text reaches report.md through md_inline: on the page it is the text it was,
// escaped once, nothing of it live (no tag, no link, no image), its newlines as line breaks.
TEST(HtmlPage, SubmissionTextStaysInert) {
  const std::string text =
      "<script>alert(1)</script> & [x](javascript:alert(1)) ![y](https://example.org/y.png) <https://example.org>\n"
      "a | b";
  const std::string h =
      markdown_to_html("| message |\n|---|\n| " + md_inline(text) + " |\n\n- " + md_inline(text) + "\n");
  const std::string shown =
      "&lt;script&gt;alert(1)&lt;/script&gt; &amp; [x](javascript:alert(1)) ![y](https://example.org/y.png) "
      "&lt;https://example.org&gt;<br>a | b";
  EXPECT_EQ(count(h, shown), 2u) << h;
  EXPECT_NE(h.find("<td>" + shown + "</td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<li>" + shown + "</li>"), std::string::npos) << h;
  for (const char* live : {"<script", "<a ", "<img", "href", "src="})
    EXPECT_EQ(h.find(live), std::string::npos) << live << " in\n" << h;
}

// Links to the report's own files and anchors are kept, "X.md" pointing to its HTML twin "X.html".
TEST(HtmlPage, LinksInsideTheReportFolderAreKept) {
  const std::string h = markdown_to_html(
      "[fig](figures/a.svg) [data](figures/work-precision.csv) [twin](other.md) [section](other.md#d-x) "
      "[here](#d-casimir) [page](alice/report.html) [ref][r]\n\n[r]: bob/report.md\n");
  for (const char* kept :
       {"<a href=\"figures/a.svg\">fig</a>", "<a href=\"figures/work-precision.csv\">data</a>",
        "<a href=\"other.html\">twin</a>", "<a href=\"other.html#d-x\">section</a>", "<a href=\"#d-casimir\">here</a>",
        "<a href=\"alice/report.html\">page</a>", "<a href=\"bob/report.html\">ref</a>"})
    EXPECT_NE(h.find(kept), std::string::npos) << kept << " not in\n" << h;
  EXPECT_EQ(count(h, "href="), 7u) << h;
  MarkdownHtml as_is;
  as_is.md_links_to_html = false;
  EXPECT_NE(markdown_to_html("[twin](other.md)", as_is).find("<a href=\"other.md\">twin</a>"), std::string::npos);
}

// An absolute URL (with a scheme, protocol-relative, or an absolute path) is not a link on the page:
// its text stays, with the target as text. The control: a relative link beside them is kept.
TEST(HtmlPage, AbsoluteLinksAreUnlinked) {
  const std::string h = markdown_to_html(
      "[far](https://example.org/x) [plain](http://example.org) [proto](//example.org/x) [root](/etc/passwd) "
      "[file](file:///etc/passwd) [mail](mailto:a@example.org) <https://example.org/auto> [ref][r] "
      "[mine](figures/a.svg)\n\n[r]: https://example.org/ref\n");
  EXPECT_EQ(count(h, "href="), 1u) << h;
  EXPECT_NE(h.find("<a href=\"figures/a.svg\">mine</a>"), std::string::npos) << h;
  for (const char* inert : {"far (https://example.org/x)", "plain (http://example.org)", "proto (//example.org/x)",
                            "root (/etc/passwd)", "file (file:///etc/passwd)", "mail (mailto:a@example.org)",
                            "https://example.org/auto (https://example.org/auto)", "ref (https://example.org/ref)"})
    EXPECT_NE(h.find(inert), std::string::npos) << inert << " not in\n" << h;
}

// javascript: and its disguises (upper case, an entity, vbscript:, data:) are unlinked the same
// way: shown as text, never in an attribute. The control: an anchor link beside them is kept.
TEST(HtmlPage, ScriptLinksAreUnlinked) {
  const std::string h = markdown_to_html(
      "[a](javascript:alert(1)) [b](JaVaScRiPt:alert(2)) [c](&#106;avascript:alert(3)) [d](vbscript:msgbox) "
      "[e](data:text/html,<b>x</b>) [f](<javascript:alert(4)>) [ok](#d-x)\n");
  EXPECT_EQ(count(h, "href="), 1u) << h;
  EXPECT_NE(h.find("<a href=\"#d-x\">ok</a>"), std::string::npos) << h;
  for (const char* inert : {"a (javascript:alert(1))", "b (JaVaScRiPt:alert(2))", "c (javascript:alert(3))",
                            "d (vbscript:msgbox)", "f (javascript:alert(4))"})
    EXPECT_NE(h.find(inert), std::string::npos) << inert << " not in\n" << h;
  EXPECT_EQ(h.find("<b>"), std::string::npos) << h;
}

// A relative link that leaves the report folder ("..", anywhere in the path, or hidden behind
// percent-encoding or "./") is unlinked. The control: a path into a subfolder of it is kept.
TEST(HtmlPage, LinksOutOfTheReportFolderAreUnlinked) {
  const std::string h = markdown_to_html(
      "[up](../bob/report.md) [deep](figures/../../secret.md) [enc](%2e%2e/secret.md) [dot](./../x.md) "
      "[in](figures/a.svg)\n");
  EXPECT_EQ(count(h, "href="), 1u) << h;
  EXPECT_NE(h.find("<a href=\"figures/a.svg\">in</a>"), std::string::npos) << h;
  for (const char* inert :
       {"up (../bob/report.md)", "deep (figures/../../secret.md)", "enc (%2e%2e/secret.md)", "dot (./../x.md)"})
    EXPECT_NE(h.find(inert), std::string::npos) << inert << " not in\n" << h;
}

// A figure comes from the report's own files, inline: an image from anywhere else is not loaded
// (nor asked for), its path shown in words. The control: the report's figure is inline.
TEST(HtmlPage, FiguresComeOnlyFromTheReportFolder) {
  std::set<std::string> asked;
  MarkdownHtml o;
  o.image = [&](const std::string& p) {
    asked.insert(p);
    return "data:image/svg+xml;base64," + base64("<svg/>");
  };
  const std::string h = markdown_to_html(
      "![a](figures/a.svg) ![b](https://example.org/b.png) ![c](../c.svg) ![d](javascript:alert(1)) "
      "![e](data:image/png;base64,AAAA)\n",
      o);
  EXPECT_EQ(asked, std::set<std::string>{"figures/a.svg"});
  EXPECT_EQ(count(h, "<img "), 1u) << h;
  EXPECT_NE(h.find("<img src=\"data:image/svg+xml;base64,PHN2Zy8+\" alt=\"a\">"), std::string::npos) << h;
  for (const char* inert : {"<em>[figure: https://example.org/b.png]</em>", "<em>[figure: ../c.svg]</em>",
                            "<em>[figure: javascript:alert(1)]</em>", "<em>[figure: data:image/png;base64,AAAA]</em>"})
    EXPECT_NE(h.find(inert), std::string::npos) << inert << " not in\n" << h;
}
