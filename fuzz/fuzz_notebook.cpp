// libFuzzer target: the notebook reader of `geomech check FILE.ipynb` (harness/languages/notebook.hpp),
// with the language table whose rows set a cell's kernel syntax aside. Any input must either be read or
// raise NotebookError; a notebook that is read must be consistent: its cells numbered from 1 upwards,
// each cell's code as many lines as its source had (a line set aside keeps its place), and its cells
// file JSON that parses back with the same cells.
#include "harness/languages/notebook.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

// Link seams: the rows name these (the sandbox's view of an interpreter, the servers' scripts); the
// reader never calls them.
namespace gm {
std::string suite_data_path(const std::string& relative) { return relative; }
namespace harness {
SandboxedInterpreter python_for_sandbox(const std::string&, const std::string&) { return {}; }
SandboxedInterpreter installation_for_sandbox(const std::string&, const std::string&, const std::string&) { return {}; }
}  // namespace harness
}  // namespace gm

namespace {

void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_notebook: accepted a notebook that %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gm::harness;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Notebook nb = read_notebook("fuzz.ipynb", text);
    require(nb.language != nullptr, "has no language");
    int last = 0;
    for (const auto& c : nb.cells) {
      require(c.number > last, "numbers its cells out of order");
      last = c.number;
      require(c.label().rfind("cell " + std::to_string(c.number), 0) == 0, "labels a cell by another number");
      (void)where_defined(nb.cells, *nb.language, "hat");
    }
    const auto cells = nlohmann::json::parse(cells_file_text(nb, "fuzz.ipynb", ""));
    require(cells.at("cells").size() == nb.cells.size(), "writes another number of cells");
    (void)set_aside_in_words(nb, "fuzz.ipynb");
  } catch (const NotebookError&) {
    // refused, with what is wrong
  }
  return 0;
}
