// Names students write instead of slot names. Slot names are equation numbers
// (euler_3_8, hamiltonian_3_4); students write `energy`, `euler`, `casimir_function`. A function
// whose name is a known alias of a slot, or within a small edit distance of one, is reported with
// the slot it probably means, so that it is not silently left unchecked.
#pragma once

#include <string>
#include <vector>

namespace gm::harness {

// The claim an unknown claim key probably means ("symmetry" -> "symmetric"), or "" when none is
// close; `known` lists the claim names.
std::string closest_claim(const std::string& key, const std::vector<std::string>& known);

// One line of advice per name that is not a slot but looks like one (the names a file defines, as its
// language's row reads them, harness/languages/language.hpp): "`energy` is not a slot
// name, so nothing checks it; did you mean `hamiltonian_3_4` ((3.4): h = Pi . I^-1 Pi / 2)?".
std::vector<std::string> slot_name_advice(const std::vector<std::string>& names);

// The slot names, in the slot table's order, and the integrators' claim names ("order", then the
// yes/no claims of core/subject.hpp), for readers of names written by hand (a rubric).
std::vector<std::string> slot_name_list();
std::vector<std::string> claim_name_list();

// " (did you mean \"casimir\"?)" for the names of `known` closest to `name` (edit distance at most a
// third of the name, or the same name in another case), or "" when none is close.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& known);

// The students' index: concepts of the notes and the slot that implements each.
struct SlotConcept {
  const char* concept_name;
  const char* slot;
};
const std::vector<SlotConcept>& slot_concepts();

}  // namespace gm::harness
