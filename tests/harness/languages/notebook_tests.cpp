// harness/languages/notebook: a notebook read as nbformat 4's JSON, its kernel naming the row, its
// cells named by place and execution count, the kernel's own syntax set aside line by line (and
// only at a statement's start: the controls keep what merely looks like it), a malformed one named.
#include "harness/languages/notebook.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace gm::harness {
namespace {

using nlohmann::json;

json code(const std::string& source, json count = nullptr) {
  return {{"cell_type", "code"},
          {"metadata", json::object()},
          {"outputs", json::array()},
          {"execution_count", count},
          {"source", source}};
}

std::string notebook(const std::vector<json>& list, const std::string& kernel = "python") {
  json cells = json::array();
  for (const auto& c : list) cells.push_back(c);
  return json{{"nbformat", 4},
              {"nbformat_minor", 5},
              {"metadata", {{"kernelspec", {{"name", kernel + "3"}, {"language", kernel}, {"display_name", kernel}}}}},
              {"cells", cells}}
      .dump();
}

TEST(Notebook, TheKernelNamesTheRowAndCellsAreNamedAsTheNotebookShowsThem) {
  const json md = {{"cell_type", "markdown"}, {"metadata", json::object()}, {"source", {"# Week 3\n", "text"}}};
  const Notebook nb = read_notebook("w.ipynb", notebook({md, code("def hat(v):\n    return v\n", 3), code("x = 1")}));
  ASSERT_EQ(nb.language, language_named("python"));
  ASSERT_EQ(nb.cells.size(), 2u);
  EXPECT_EQ(nb.cells[0].label(), "cell 2, In [3]");
  EXPECT_EQ(nb.cells[1].label(), "cell 3");  // never run: no count
  EXPECT_EQ(where_defined(nb.cells, *nb.language, "hat"), "cell 2, In [3], line 1");
  EXPECT_EQ(where_defined(nb.cells, *nb.language, "vee"), "");
  EXPECT_EQ(set_aside_in_words(nb, "/x/w.ipynb"),
            "w.ipynb: its 2 code cells are the implementation (Python), run in order; set aside: cell 1 (Markdown or "
            "raw: shown, not run)");
  // The source as a list of lines is joined; language_info names the kernel when kernelspec does not.
  const json octave = {{"nbformat", 4},
                       {"nbformat_minor", 4},
                       {"metadata", {{"language_info", {{"name", "Octave"}}}}},
                       {"cells", json::array({code(std::string("function m = hat(v)\n  m = v;\nend"))})}};
  EXPECT_EQ(read_notebook("o.ipynb", octave.dump()).language, language_named("octave"));
}

TEST(Notebook, IPythonsOwnSyntaxIsSetAsideAtAStatementsStartOnly) {
  const std::string cell =
      "import numpy\n"
      "!pip install mpmath\n"
      "for k in range(3):\n"
      "    %time f(k)\n"
      "files = !ls\n"
      "x = (1\n"
      "     % 2)\n"
      "s = \"\"\"\n"
      "%not a magic in a string\n"
      "\"\"\"\n"
      "y = 3 % 2";
  const Notebook nb = read_notebook("w.ipynb", notebook({code(cell, 1)}));
  ASSERT_EQ(nb.cells.size(), 1u);
  EXPECT_EQ(nb.cells[0].code,
            "import numpy\npass\nfor k in range(3):\n    pass\npass\nx = (1\n     % 2)\ns = \"\"\"\n%not a magic in a "
            "string\n\"\"\"\ny = 3 % 2");
  ASSERT_EQ(nb.set_aside.size(), 3u);
  EXPECT_EQ(nb.set_aside[0], "cell 1, In [1], line 2 (a shell escape (!pip install mpmath))");
  EXPECT_EQ(nb.set_aside[1], "cell 1, In [1], line 4 (a line magic (%time f(k)))");
  EXPECT_EQ(nb.set_aside[2], "cell 1, In [1], line 5 (a shell escape (files = !ls))");
  // A cell magic sets the whole cell aside; a cell tagged skip-execution is not run; "%% Title" is
  // no magic (Octave's cell-mode comment).
  json tagged = code("plot(x)", 4);
  tagged["metadata"] = {{"tags", {"skip-execution"}}};
  const Notebook two = read_notebook("w.ipynb", notebook({code("%%time\nf()", 2), tagged}));
  EXPECT_TRUE(two.cells.empty());
  EXPECT_EQ(two.set_aside,
            (std::vector<std::string>{"cell 2 (tagged skip-execution: a cell that only shows something)",
                                      "cell 1, In [2] (a cell magic (%%time), run by IPython, not Python)"}));
  EXPECT_EQ(cell_magic("%% Title\nx = 1"), "");
  EXPECT_EQ(cell_magic("\n%%writefile a.py\nx"), "%%writefile");
}

TEST(Notebook, TheOctaveKernelsShellEscapeIsSetAside) {
  const Notebook nb =
      read_notebook("o.ipynb", notebook({code("%plot inline\n!ls\nx = [1, ...\n  !2];\ny = ~x", 1)}, "octave"));
  ASSERT_EQ(nb.cells.size(), 1u);
  EXPECT_EQ(nb.cells[0].code, "%plot inline\n\nx = [1, ...\n  !2];\ny = ~x");  // a magic line is a comment already
  EXPECT_EQ(nb.set_aside, (std::vector<std::string>{"cell 1, In [1], line 2 (a shell escape (!ls))"}));
}

// What is wrong is named; the control: the same notebook whole reads.
TEST(Notebook, AMalformedNotebookIsNamedWithWhatIsWrong) {
  auto error = [](const std::string& text) {
    try {
      read_notebook("w.ipynb", text);
    } catch (const NotebookError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(error(notebook({code("x = 1")})), "read");
  EXPECT_EQ(error("[1, 2]"), "w.ipynb is not a notebook: its JSON is a list, not an object");
  EXPECT_NE(error("{\"cells\": [").find("w.ipynb is not a notebook: its JSON does not parse (parse error at line 1"),
            std::string::npos);
  // A number past double's range is nlohmann's out_of_range, not its parse_error: still a refusal (the
  // fuzzer found it uncaught, std::terminate).
  EXPECT_EQ(error("{\"cells\": [], \"nbformat\": 8e530}"),
            "w.ipynb is not a notebook: its JSON does not parse (number overflow parsing '8e530')");
  json bad = json::parse(notebook({code("x = 1")}));
  bad["cells"][0]["source"] = {"x = 1\n", 2};
  EXPECT_EQ(error(bad.dump()), "w.ipynb: cell 1: line 2 of its \"source\" is a number; nbformat 4 has a text there");
  bad = json::parse(notebook({code("x = 1")}));
  bad["cells"][0]["cell_type"] = "python";
  EXPECT_EQ(error(bad.dump()),
            "w.ipynb: cell 1: its \"cell_type\" is 'python'; nbformat 4 has code, markdown or raw there");
  bad = json::parse(notebook({code("x = 1")}));
  bad["cells"][0]["execution_count"] = -2;
  EXPECT_EQ(error(bad.dump()),
            "w.ipynb: cell 1: its \"execution_count\" is a number out of range; nbformat 4 has a whole number or null "
            "there");
  EXPECT_NE(error(notebook({code("x = 1")}, "ir"))
                .find("its kernel is 'ir', 'ir3'; the suite checks notebooks whose "
                      "kernel is Python (python, python3) or Octave (octave)"),
            std::string::npos);
}

}  // namespace
}  // namespace gm::harness
