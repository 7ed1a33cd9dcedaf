// The languages a submission may be written in: one row each. A row is the whole of what the suite
// knows of a language: its files, how a submission in it becomes a subject (compiled with the suite,
// or started as a server behind the slot protocol, docs/PROTOCOL.md), the interpreter it runs in,
// how its values and functions are written in reports, how its source is read for advice, how its
// slots are listed (`geomech slots --<id>`), and the notebook kernels whose cells are its code.
// Everything that asks "which language is this, and what does that change" (the tool, the check,
// the reports, class mode, the autograders, the grader's machine check) reads a row; nothing else
// names a language (ctest layout.language_ids holds that). Adding a language is a row (a file of
// this room and its line in languages.cpp) and its server (docs/DEVELOPING.md, "Adding a language").
#pragma once

#include "harness/isolation/sandboxed_interpreter.hpp"
#include "properties/support/value_style.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gm::harness {

// How a submission becomes a subject.
enum class Route {
  Compiled,  // compiled with the suite into a check program (trusted) or a protocol server (untrusted)
  Served,    // started in its interpreter as a protocol server
  Notebook,  // a Jupyter notebook: its code cells, in the language its kernel names, served by that row
};

// A function a source defines, where its name begins (a byte offset into the text read).
struct Definition {
  std::size_t offset = 0;
  std::string name;
};

// A notebook cell's code as its kernel runs it: the lines of the kernel's own syntax (an IPython line
// magic, a shell escape) replaced so that the rest keeps its line numbers, and those lines said.
struct CellCode {
  std::string code;
  std::vector<std::pair<int, std::string>> skipped;  // (line from 1, what it is: "a shell escape (!pip ...)")
  std::string whole_cell;  // not empty: the whole cell is not code, and why ("a cell magic (%%time), ...")
};

struct Language {
  std::string id;                       // the protocol's name for it ("c++", "python", "octave")
  std::string name;                     // as reports write it ("C++")
  std::vector<std::string> extensions;  // a file of the language (".cpp", ".cc")
  Route route = Route::Compiled;
  // In a student's folder, the one file that is the implementation holds this text (a C++ file that
  // registers a student); empty: the language's one file there is it.
  std::string marker;
  bool folder_of_files = false;  // a folder of such files is one implementation (Octave function files)
  bool files_beside = false;     // the files beside it belong to it (a C++ file's headers)

  // ---- How reports speak of it.
  // What a slot is called in it, before the slot's name and its file ("Python function `casimir` in
  // mine.py"); empty: "slot `casimir`", the suite's own word.
  std::string function_noun;
  std::string version_label;  // before the interpreter's version in the report ("Python" in "(Python 3.11.2)")
  // Said when an implementation provides nothing in a scalar its language cannot compute in
  // (" (Octave code is checked in double only)"); empty: nothing to add.
  std::string scalars_note;
  ValueStyle values;  // how values and their types are written (properties/support/value_style.hpp)
  // When --timeout is not given, a check of an implementation in it gets this many times the default
  // timeout: an interpreter computes 50-digit flows tens of times slower than compiled code, and one
  // case of a long flow can take longer than the 60 s a check gets (3 for Python; 6 for Octave, whose
  // calls cost about 5 times Python's). The case budget is not scaled.
  double timeout_factor = 1;
  // An integrator step that computes in double only, given 50-digit numbers, raises this error
  // ("TypeError"), and the report adds the hint after it (how to say so). Empty: no hint.
  std::string double_only_error, double_only_hint;

  // ---- Reading its source. Lexical scans, for advice and for ordering first fixes, never for a
  // verdict. `function_names`: the functions a file defines where a slot may be (top level), for the
  // did-you-mean of a misspelt slot. `code_only`: the text with comments and string literals blanked
  // (same length), `definitions`: where each function of such a text begins (methods too), for which
  // slot calls which (harness/checking/source_calls.hpp). Null: these hints are missing.
  std::vector<std::string> (*function_names)(const std::string& source) = nullptr;
  std::string (*code_only)(const std::string& source) = nullptr;
  std::vector<Definition> (*definitions)(const std::string& code) = nullptr;

  // ---- `geomech slots --<id>` (the suite's own language: `geomech slots`): a heading, the fence of
  // its code block ("python"; empty: no block), the comment that starts a line of prose in it, each
  // slot's signature in the language, and the integrators' interface as code (after the prose every
  // language shares, harness/remote/slot_conventions.hpp). Null `signature`: no listing.
  std::string slots_heading;
  std::string slots_fence;
  std::string comment;
  std::string (*signature)(const std::string& slot, const std::string& cpp_signature) = nullptr;
  std::string (*integrator_interface)() = nullptr;

  // ---- Running it (served languages): the variable that names the interpreter, the interpreter
  // found on this machine, the arguments that start it to no effect (tried inside the sandbox by the
  // grader's machine check; empty: not tried), what of its installation the sandbox must show
  // (harness/isolation/sandboxed_interpreter.hpp), whether `geomech self-test` tries it unless told
  // not to (--no-<id>; otherwise only when asked, --<id>), and the command that serves `file` over
  // the protocol (the file its last argument, the server's own script or program the one before).
  std::string interpreter_variable;
  std::string system_interpreter;  // the system's, named in a fix ("/usr/bin/python3")
  std::string (*interpreter)() = nullptr;
  std::vector<std::string> start_probe;
  SandboxedInterpreter (*for_sandbox)(const std::string& interpreter) = nullptr;
  bool self_test_by_default = false;
  std::vector<std::string> (*server)(const std::string& file) = nullptr;
  // The packages a file names for its interpreter's package manager (JavaScript: `// geomech: npm
  // NAME` lines; null: none), and the folder its interpreter finds them in ("node_modules"). Behind
  // the sandbox, a named package is found in a folder the grader trusts (GEOMECH_LIBRARY_ROOTS:
  // ROOT/<package_folder>/NAME) and shown read-only at /<package_folder>/NAME, where the interpreter
  // looks from the submission's folder.
  std::vector<std::string> (*named_packages)(const std::string& source) = nullptr;
  std::string package_folder;

  // ---- Notebooks (harness/languages/notebook.hpp): the kernels whose cells are code of this
  // language (a notebook's kernelspec language, language_info name or kernelspec name, compared
  // without case), and how a cell's lines of the kernel's own syntax are set aside. The server
  // serves a notebook's cells file (a .json file, docs/PROTOCOL.md, "Notebooks") like a source file.
  std::vector<std::string> kernels;
  CellCode (*cell_code)(const std::string& source) = nullptr;
};

// Every language, in the order messages list them; the first is the suite's own (C++).
const std::vector<Language>& languages();

// The suite's own language: the reference, the built-in subjects and a C++ file checked in process.
const Language& suite_language();

// The language of a file extension (".py"), or nullptr.
const Language* language_of_extension(std::string_view extension);

// The language of a path: by its extension, or a folder of a folder_of_files language's files; nullptr
// when it is neither.
const Language* language_of(const std::string& path);

// The language named by its id ("python"), or nullptr.
const Language* language_named(std::string_view id);

// The language whose code a notebook kernel runs (`kernel` as the notebook names it, any case), or nullptr.
const Language* language_of_kernel(std::string_view kernel);

// The extensions in words, for messages: ".cpp, .cc, .py, .m, .mjs, .js or .ipynb"; and ", nor a folder of .m
// files" (the folder_of_files languages), to follow "not a ... file".
std::string extensions_in_words();
std::string folder_in_words();

// The kernels notebooks may have, in words: "Python (python, python3) or Octave (octave)".
std::string kernels_in_words();

// How to start the server for a served file (a .py, a .m, or a folder of .m files); empty when
// the file is of no served language. `language` receives its id, `why` what is missing.
std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why);

// The files a served file names as its own, beside it in its folder: one `<comment>geomech: beside
// NAME` line each, in the row's comment syntax ("# geomech: beside node_server.mjs"). A wrapper's own
// files (a Node server a Python file starts, a module a JavaScript file imports) are part of it:
// behind the sandbox they are shown with it, read as a stranger's files are (never through a link).
// NAME is a plain file name (letters, digits, . _ -, not first a .); a line naming anything else (a
// path, "..") throws std::invalid_argument with its line, as the code's own mistake.
std::vector<std::string> beside_files(const Language& language, const std::string& source);

// A program as PATH finds it (absolute), or "" when it is not there; a name with a '/' as given.
std::string on_path(const std::string& program);

// A row's interpreter: the one its variable names ($GEOMECH_PYTHON; a bare name as PATH finds it),
// else `program` first on PATH (a venv's, nvm's), else `fallback` (the system's, or the bare name).
std::string interpreter_named(const char* variable, const std::string& program, const std::string& fallback);

// Line and column (from 1) of a byte offset into a text.
std::pair<int, int> line_and_column(const std::string& text, std::size_t offset);

// A slot's parameters as its C++ signature in the slot table writes them ("Mat3<T>(const Vec3<T>& v)"):
// (the parameter's whole text, its name) each, "const Vec3<T>& v" and "v"; and its result type
// ("Mat3<T>"). For the rows' signature printers.
std::vector<std::pair<std::string, std::string>> slot_parameters(const std::string& cpp_signature);
std::string slot_result_type(const std::string& cpp_signature);

}  // namespace gm::harness
