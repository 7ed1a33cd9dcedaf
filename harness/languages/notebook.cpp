#include "harness/languages/notebook.hpp"

#include "harness/isolation/inert_text.hpp"
#include "harness/languages/rows.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>

namespace gm::harness {

namespace {

using nlohmann::json;

// What a JSON value is, in words, for a message ("a number", "a list").
std::string kind_of(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "true or false";
    case json::value_t::string:
      return "a text";
    case json::value_t::array:
      return "a list";
    case json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

// A cell's "source": a text, or a list of texts (its lines) joined.
std::string source_of(const json& cell, const std::string& where, const std::string& file) {
  if (!cell.contains("source"))
    throw NotebookError(file + ": " + where + ": it has no \"source\" (nbformat 4 gives every cell one)");
  const json& s = cell.at("source");
  if (s.is_string()) return s.get<std::string>();
  if (s.is_array()) {
    std::string out;
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (!s[k].is_string())
        throw NotebookError(file + ": " + where + ": line " + std::to_string(k + 1) + " of its \"source\" is " +
                            kind_of(s[k]) + "; nbformat 4 has a text there");
      out += s[k].get<std::string>();
    }
    return out;
  }
  throw NotebookError(file + ": " + where + ": its \"source\" is " + kind_of(s) +
                      "; nbformat 4 has a text or a list of lines there");
}

std::string text_at(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object.at(key).is_string()) return "";
  return object.at(key).get<std::string>();
}

bool tagged(const json& cell, const std::string& tag) {
  if (!cell.contains("metadata") || !cell.at("metadata").is_object()) return false;
  const json& m = cell.at("metadata");
  if (!m.contains("tags") || !m.at("tags").is_array()) return false;
  for (const auto& t : m.at("tags"))
    if (t.is_string() && t.get<std::string>() == tag) return true;
  return false;
}

// "cells 1, 3 and 6" / "cell 2".
std::string cells_in_words(const std::vector<int>& numbers) {
  std::string out = numbers.size() == 1 ? "cell " : "cells ";
  for (std::size_t i = 0; i < numbers.size(); ++i)
    out += (i == 0 ? "" : i + 1 == numbers.size() ? " and " : ", ") + std::to_string(numbers[i]);
  return out;
}

// The notebook's JSON, parsed, once it is seen to be an nbformat 4 notebook with a list of cells.
json parsed_notebook(const std::string& file, const std::string& text) {
  json nb;
  try {
    nb = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number past double's range (1e999)
    std::string why = e.what();
    if (const auto at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    throw NotebookError(file + " is not a notebook: its JSON does not parse (" + inert_text(bounded_text(why, 300)) +
                        ")");
  }
  if (!nb.is_object()) throw NotebookError(file + " is not a notebook: its JSON is " + kind_of(nb) + ", not an object");
  if (!nb.contains("nbformat"))
    throw NotebookError(file + " is not a notebook: it has no \"nbformat\" (the notebook format's version)");
  if (!nb.at("nbformat").is_number_integer())
    throw NotebookError(file + ": its \"nbformat\" is " + kind_of(nb.at("nbformat")) +
                        "; a notebook has a version number");
  if (const int major = nb.at("nbformat").get<int>(); major != 4)
    throw NotebookError(file + ": it is written in nbformat " + std::to_string(major) +
                        "; the suite reads nbformat 4, as Jupyter saves notebooks (open it in Jupyter and save it "
                        "again, or `jupyter nbconvert --to notebook` it)");
  if (!nb.contains("cells") || !nb.at("cells").is_array())
    throw NotebookError(file + ": its \"cells\" is " + (nb.contains("cells") ? kind_of(nb.at("cells")) : "missing") +
                        "; nbformat 4 has the list of cells there");
  return nb;
}

// Sets the notebook's kernel and the language its cells are in, from its metadata; a notebook whose
// kernel names no language the suite checks is refused.
void find_kernel(const json& metadata, const std::string& file, Notebook& out) {
  // The kernel: what its kernelspec says it runs, else the language_info its kernel wrote, else the
  // kernelspec's name.
  const json kernelspec = metadata.contains("kernelspec") ? metadata.at("kernelspec") : json();
  const json language_info = metadata.contains("language_info") ? metadata.at("language_info") : json();
  const std::vector<std::string> said{text_at(kernelspec, "language"), text_at(language_info, "name"),
                                      text_at(kernelspec, "name")};
  for (const auto& k : said)
    if (!k.empty() && !out.language) {
      out.kernel = k;
      out.language = language_of_kernel(k);
    }
  if (!out.language) {
    std::string named;
    for (const auto& k : said)
      if (!k.empty()) named += (named.empty() ? "" : ", ") + ("'" + inert_text(bounded_text(k, 80)) + "'");
    throw NotebookError(file + ": " +
                        (named.empty() ? std::string("its metadata names no kernel (no kernelspec, no language_info), "
                                                     "so which language its cells are in is not said; choose a kernel "
                                                     "in Jupyter (Kernel > Change Kernel) and save it")
                                       : "its kernel is " + named + "; the suite checks notebooks whose kernel is " +
                                             kernels_in_words()));
  }
}

}  // namespace

std::string CodeCell::label() const {
  return "cell " + std::to_string(number) +
         (execution_count >= 0 ? ", In [" + std::to_string(execution_count) + "]" : std::string());
}

std::string cell_magic(const std::string& source) {
  const std::size_t start = source.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || source.compare(start, 2, "%%") != 0) return "";
  std::size_t end = start + 2;
  while (end < source.size() && (std::isalnum(static_cast<unsigned char>(source[end])) || source[end] == '_')) ++end;
  if (end == start + 2) return "";  // "%% Section": a comment in Octave's cell mode, not a magic
  return source.substr(start, end - start);
}

Notebook read_notebook(const std::string& file, const std::string& text) {
  const json nb = parsed_notebook(file, text);
  const json metadata = nb.contains("metadata") ? nb.at("metadata") : json::object();
  if (!metadata.is_object())
    throw NotebookError(file + ": its \"metadata\" is " + kind_of(metadata) + "; nbformat 4 has an object there");

  Notebook out;
  find_kernel(metadata, file, out);
  const Language& l = *out.language;
  std::vector<int> shown, skipped_tag;
  const json& cells = nb.at("cells");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    const std::string where = "cell " + std::to_string(number);
    const json& cell = cells[i];
    if (!cell.is_object()) throw NotebookError(file + ": " + where + " is " + kind_of(cell) + ", not a cell");
    if (!cell.contains("cell_type") || !cell.at("cell_type").is_string())
      throw NotebookError(file + ": " + where + ": its \"cell_type\" is " +
                          (cell.contains("cell_type") ? kind_of(cell.at("cell_type")) : "missing") +
                          "; nbformat 4 has code, markdown or raw there");
    const std::string type = cell.at("cell_type").get<std::string>();
    const std::string source = source_of(cell, where, file);
    if (type == "markdown" || type == "raw") {
      shown.push_back(number);
      continue;
    }
    if (type != "code")
      throw NotebookError(file + ": " + where + ": its \"cell_type\" is '" + inert_text(bounded_text(type, 80)) +
                          "'; nbformat 4 has code, markdown or raw there");
    CodeCell c;
    c.number = number;
    if (cell.contains("execution_count") && !cell.at("execution_count").is_null()) {
      const json& n = cell.at("execution_count");
      if (!n.is_number_integer() || n.get<long long>() < 0 || n.get<long long>() > 1000000000)
        throw NotebookError(file + ": " + where + ": its \"execution_count\" is " + kind_of(n) +
                            (n.is_number() ? " out of range" : "") + "; nbformat 4 has a whole number or null there");
      c.execution_count = n.get<int>();
    }
    if (tagged(cell, "skip-execution")) {
      skipped_tag.push_back(number);
      continue;
    }
    const CellCode code = l.cell_code ? l.cell_code(source) : CellCode{source, {}, {}};
    if (!code.whole_cell.empty()) {
      out.set_aside.push_back(c.label() + " (" + inert_text(bounded_text(code.whole_cell, 200)) + ")");
      continue;
    }
    for (const auto& [line, what] : code.skipped)
      out.set_aside.push_back(c.label() + ", line " + std::to_string(line) + " (" +
                              inert_text(bounded_text(what, 200)) + ")");
    c.code = code.code;
    out.cells.push_back(std::move(c));
  }
  if (!skipped_tag.empty())
    out.set_aside.insert(out.set_aside.begin(),
                         cells_in_words(skipped_tag) + " (tagged skip-execution: a cell that only shows something)");
  if (!shown.empty())
    out.set_aside.insert(out.set_aside.begin(), cells_in_words(shown) + " (Markdown or raw: shown, not run)");
  return out;
}

std::string cells_file_text(const Notebook& notebook, const std::string& file, const std::string& folder) {
  const std::string name = std::filesystem::path(file).filename().string();
  json cells = json::array();
  for (const auto& c : notebook.cells) cells.push_back({{"name", name + ", " + c.label()}, {"code", c.code}});
  const json j{{"format", "geomech-cells 1"}, {"notebook", name}, {"folder", folder}, {"cells", cells}};
  return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string set_aside_in_words(const Notebook& notebook, const std::string& file) {
  const std::string name = std::filesystem::path(file).filename().string();
  std::string out = name + ": its " + std::to_string(notebook.cells.size()) + " code cell" +
                    (notebook.cells.size() == 1 ? " is" : "s are") + " the implementation (" + notebook.language->name +
                    "), run in order";
  if (notebook.set_aside.empty()) return out;
  out += "; set aside: ";
  for (std::size_t i = 0; i < notebook.set_aside.size(); ++i) out += (i ? "; " : "") + notebook.set_aside[i];
  return out;
}

std::string where_defined(const std::vector<CodeCell>& cells, const Language& language, const std::string& name) {
  if (!language.code_only || !language.definitions) return "";
  std::string found;
  for (const auto& c : cells) {
    const std::string code = language.code_only(c.code);
    for (const auto& d : language.definitions(code))
      if (d.name == name) found = c.label() + ", line " + std::to_string(line_and_column(code, d.offset).first);
  }
  return found;
}

Language notebook_row() {
  Language notebook;
  notebook.id = "jupyter";
  notebook.name = "Jupyter notebook";
  notebook.extensions = {".ipynb"};
  notebook.route = Route::Notebook;  // its cells are served by the row its kernel names
  return notebook;
}

}  // namespace gm::harness
