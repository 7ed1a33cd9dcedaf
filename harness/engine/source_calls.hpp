// Which slots each slot of a submission calls, read from its source: when a slot's own
// check fails and it calls another slot whose own check fails too, the callee is the first fix
// (`manakov_2_34` is right and fails only through the `manakov_Omega` it calls). A lexical scan of
// Python (`def` bodies), Octave (a file of functions, or a folder with one function per file) and
// C++ (the bodies of the functions named after slots); it orders the first fixes and says who calls
// whom, it never decides a verdict. The file is opened without following a link, only if it is a
// regular file, and read up to 4 MiB; anything else reads as no calls.
#pragma once

#include <map>
#include <set>
#include <string>

namespace gm::harness {

// slot -> the other slots its body names in a call. `language` is "python", "octave" or "c++"
// (anything else: "c++"); `source` a file, or for Octave a folder of .m files.
std::map<std::string, std::set<std::string>> slot_calls(const std::string& source, const std::string& language);

// The same, from source text already read (one file).
std::map<std::string, std::set<std::string>> slot_calls_in_text(const std::string& text, const std::string& language);

}  // namespace gm::harness
