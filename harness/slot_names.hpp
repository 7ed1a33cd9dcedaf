// Names students write instead of slot names (issue 13). Slot names are equation numbers
// (euler_3_8, hamiltonian_3_4); students write `energy`, `euler`, `casimir_function`. A function
// whose name is a known alias of a slot, or within a small edit distance of one, is reported with
// the slot it probably means, so that it is not silently left unchecked.
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

// The names of the functions a C++ source defines as static members or free functions (a
// lexical scan, good enough to give advice; never used to decide what is checked).
std::vector<std::string> cpp_function_names(const std::string& source);

// One line of advice per name that is not a slot but looks like one: "`energy` is not a slot
// name, so nothing checks it; did you mean `hamiltonian_3_4` ((3.4): h = Pi . I^-1 Pi / 2)?".
std::vector<std::string> slot_name_advice(const std::vector<std::string>& names);

// The students' index: concepts of the notes and the slot that implements each.
struct SlotConcept {
  const char* concept_name;
  const char* slot;
};
const std::vector<SlotConcept>& slot_concepts();

}  // namespace gm::harness
