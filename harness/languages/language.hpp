// The languages a submission may be written in: one row each, with its file extensions, how it is
// checked (compiled with the suite, or started as a server behind the slot protocol,
// docs/PROTOCOL.md), the interpreter it runs in and the command that serves it. Everything that asks
// "which language is this file, and how is it run" (the tool, class mode, the autograders, the
// grader's machine check) reads this table; adding a language is a row here and its server
// (docs/DEVELOPING.md, "Adding a language").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gm::harness {

// How a submission becomes a subject.
enum class Route {
  Compiled,  // compiled with the suite into a check program (trusted) or a protocol server (untrusted)
  Served,    // started in its interpreter as a protocol server
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
  // Served languages: the variable that names the interpreter, the interpreter found on this machine,
  // the arguments that start it to no effect (tried inside the sandbox by the grader's machine check;
  // empty: not tried), and the command that serves `file` over the protocol.
  std::string interpreter_variable;
  std::string system_interpreter;  // the system's, named in a fix ("/usr/bin/python3")
  std::string (*interpreter)() = nullptr;
  std::vector<std::string> start_probe;
  std::vector<std::string> (*server)(const std::string& file) = nullptr;
};

// Every language, in the order messages list them.
const std::vector<Language>& languages();

// The language of a file extension (".py"), or nullptr.
const Language* language_of_extension(std::string_view extension);

// The language of a path: by its extension, or a folder of a folder_of_files language's files; nullptr
// when it is neither.
const Language* language_of(const std::string& path);

// The language named by its id ("python"), or nullptr.
const Language* language_named(std::string_view id);

// The extensions in words, for messages: ".cpp, .cc, .py or .m"; and ", nor a folder of .m files"
// (the folder_of_files languages), to follow "not a ... file".
std::string extensions_in_words();
std::string folder_in_words();

// How to start the server for a served file (a .py, a .m, or a folder of .m files); empty when
// the file is of no served language. `language` receives its id, `why` what is missing.
std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why);

// The Octave server with Octave's interpreter linked in (student/octave/octave_server.cpp), beside
// this program when liboctave-dev was installed at build time; empty when it is not there, or when
// $GEOMECH_OCTAVE_SERVER=script or $GEOMECH_OCTAVE (an octave-cli to run) asks for the script
// server. Both answer alike; the linked one costs a half to a quarter of the time per call.
std::string octave_server_program();

// The interpreters a .py or .m file runs in: $GEOMECH_PYTHON, else the python3 first on
// PATH (a venv or pyenv works), else /usr/bin/python3; $GEOMECH_OCTAVE, else octave-cli from PATH.
// Absolute paths where found.
std::string python_interpreter();
std::string octave_interpreter();

// A program as PATH finds it (absolute), or "" when it is not there; a name with a '/' as given.
std::string on_path(const std::string& program);

}  // namespace gm::harness
