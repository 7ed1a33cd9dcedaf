// The languages a submission may be written in, and how each is started: the interpreters a
// .py or .m file runs in and the command that serves it over the slot protocol (docs/PROTOCOL.md).
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

// How to start the server for an implementation file, from its extension (.py, .m, or a folder of
// .m files); empty when the extension is not one of these. `why` says what is missing.
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

}  // namespace gm::harness
