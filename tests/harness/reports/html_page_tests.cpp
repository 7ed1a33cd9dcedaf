// Reports as HTML pages: report.md as a page that loads nothing and runs nothing of the
// student's, its structure kept.
#include "harness/reports/html_page.hpp"

#include <gtest/gtest.h>

using namespace gm::harness;

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
  EXPECT_NE(h.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos) << h;
  EXPECT_NE(h.find("raise ValueError(&#39;```&#39;)\n&lt;b&gt;bold?&lt;/b&gt;"), std::string::npos) << h;
  // The structure is kept: the control that the page is not just escaped text.
  EXPECT_NE(h.find("<h2 id=\"what-to-fix\">What to fix</h2>"), std::string::npos) << h;
  EXPECT_NE(h.find("<strong>Python function <code>casimir</code> is wrong</strong>"), std::string::npos) << h;
  EXPECT_NE(h.find("<ul>\n<li>these fail too: <code>euler_3_8</code>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td><a href=\"#d-casimir\"><strong>FAIL</strong></a></td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td>a | b</td><td>line<br>two</td>"), std::string::npos) << h;
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
// is not an entity is still escaped.
TEST(HtmlPage, AnEntityOfTheMarkdownIsEscapedOnce) {
  const std::string h = markdown_to_html("| x |\n|---|\n| &lt;ad*_xi mu, eta&gt; & <b> |\n");
  EXPECT_NE(h.find("<td>&lt;ad*_xi mu, eta&gt; &amp; &lt;b&gt;</td>"), std::string::npos) << h;
  EXPECT_EQ(h.find("&amp;lt;"), std::string::npos) << h;
}
