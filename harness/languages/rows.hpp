// The rows of the language table, each built by its own file of this room (cpp.cpp, python.cpp,
// octave.cpp, javascript.cpp, notebook.cpp); languages.cpp lists them in the order messages name them.
#pragma once

#include "harness/languages/language.hpp"

#include <string>

namespace gm::harness {

Language cpp_row();
Language python_row();
Language octave_row();
Language javascript_row();
Language notebook_row();

// A text of a language with C's comments (C++, JavaScript) with its comments (// and /* */) and
// string literals blanked, same length, lines kept: `quotes` the characters that open a literal
// ("\"'", and JavaScript's backquote too), `multiline` the one whose literal may cross lines ('`'; 0:
// none). For the rows' code_only.
std::string c_like_code_only(const std::string& text, const std::string& quotes, char multiline);

// The Octave server with Octave's interpreter linked in (student/octave/octave_server.cpp), beside
// this program when liboctave-dev was installed at build time; empty when it is not there, or when
// $GEOMECH_OCTAVE_SERVER=script or $GEOMECH_OCTAVE (an octave-cli to run) asks for the script
// server. Both answer alike; the linked one costs a half to a quarter of the time per call.
std::string octave_server_program();

}  // namespace gm::harness
