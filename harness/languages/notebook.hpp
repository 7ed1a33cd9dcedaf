// A Jupyter notebook as a submission. Read as the documented JSON format of nbformat 4 (through
// nlohmann-json, never by matching its text): its kernel (metadata.kernelspec, else
// metadata.language_info) names the language of its code cells, and those cells, in order, are the
// implementation, served by that language's server from a cells file the harness writes
// (docs/PROTOCOL.md, "Notebooks").
//
// What is set aside, and said: Markdown and raw cells (shown by Jupyter, never run), code cells
// tagged skip-execution (the tag Jupyter's nbclient skips, for a cell that only shows something), a
// cell magic (%%time on a cell's first line) and, line by line, the kernel's own syntax (an IPython
// line magic or shell escape: Language::cell_code). A cell's saved outputs are not read.
//
// A cell is named by its place in the notebook, counting every cell (Markdown too) from 1 at the
// top, and by the execution count Jupyter shows beside it when the notebook was saved with one:
// "cell 4, In [3]". Every message that names a line of a notebook names the cell and the line in it.
#pragma once

#include "harness/languages/language.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace gm::harness {

struct CodeCell {
  int number = 0;             // its place in the notebook, from 1, every cell counted
  int execution_count = -1;   // as saved (In [3]); -1: none (never run, or its outputs cleared)
  std::string code;           // as it runs (CellCode::code of its language)
  std::string label() const;  // "cell 4, In [3]", or "cell 4"
};

struct Notebook {
  const Language* language = nullptr;  // the row whose code the cells are
  std::string kernel;                  // as the notebook names it ("python3")
  std::vector<CodeCell> cells;         // the code cells that run, in order
  std::vector<std::string> set_aside;  // what does not run, in words: "cell 2 (Markdown: shown, not run)"
};

// A file that is not a notebook the suite can check: what() names the file and what is wrong in it
// ("week3.ipynb: cell 5: its \"source\" is a number; nbformat 4 has a text or a list of lines there").
struct NotebookError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The notebook in `text`, read from `file` (named in messages as given). Throws NotebookError.
Notebook read_notebook(const std::string& file, const std::string& text);

// The cells file its language's server reads (docs/PROTOCOL.md, "Notebooks"): the notebook's name,
// the folder its imports are found in ("" for none: in the sandbox), and each code cell as
// {"name": "week3.ipynb, cell 4, In [3]", "code": ...}, the name standing for a file name in the
// server's tracebacks.
std::string cells_file_text(const Notebook& notebook, const std::string& file, const std::string& folder);

// What is set aside, as one line for the top of the report: "week3.ipynb: its 6 code cells are the
// implementation, run in order; set aside: ...".
std::string set_aside_in_words(const Notebook& notebook, const std::string& file);

// "%%time" when the first line of a cell is a cell magic (%% and a name, in IPython's and in
// metakernel's syntax alike); "" otherwise.
std::string cell_magic(const std::string& source);

// Where the function `name` is defined in a notebook's cells, by the last cell that defines it (a later
// cell redefines it): "cell 4, In [3], line 2"; "" when no cell does, or the language has no reader.
std::string where_defined(const std::vector<CodeCell>& cells, const Language& language, const std::string& name);

}  // namespace gm::harness
