// Which slots each slot of a submission calls, read from its source: when a slot's own
// check fails and it calls another slot whose own check fails too, the callee is the first fix
// (`manakov_2_34` is right and fails only through the `manakov_Omega` it calls). A lexical scan with
// the reader of the submission's language (Language::code_only and definitions: the bodies of the
// functions named after slots; a folder of a folder_of_files language holds one function per file);
// it orders the first fixes and says who calls whom, it never decides a verdict. The file is opened
// without following a link, only if it is a regular file, and read up to 4 MiB; anything else reads
// as no calls, and so does a language without a reader.
#pragma once

#include "harness/languages/language.hpp"
#include "harness/languages/notebook.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace gm::harness {

// slot -> the other slots its body names in a call; `source` a file, or a folder of the language's
// function files; a notebook's code cells when `cells` holds them (each cell read on its own: a
// function's body ends with its cell).
std::map<std::string, std::set<std::string>> slot_calls(const std::string& source, const Language& language,
                                                        const std::vector<CodeCell>& cells = {});

// The same, from source text already read (one file).
std::map<std::string, std::set<std::string>> slot_calls_in_text(const std::string& text, const Language& language);

}  // namespace gm::harness
