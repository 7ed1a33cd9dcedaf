// Negative controls: deliberately wrong variants of the reference subject. Each property names
// the mutants that must make it fail; tests/property_tests.cpp shows that they do.
//
//   GM_MUTANT(name, "what is wrong, in a student's words", [](auto& s) {
//     using T = gm::scalar_of<decltype(s)>;
//     s.hat = [](const gm::Vec3<T>& v) -> gm::Mat3<T> { ... };
//   });
//
// The patch is applied to the reference subject in every scalar (double, Real50, Rational).
// A mutant that changes claims rather than slots uses GM_MUTANT_SET, which edits the SubjectSet.
#pragma once

#include "core/subject.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace gm {

template <class S>
using scalar_of = typename std::decay_t<S>::Scalar;

struct Mutant {
  std::string name;
  std::string description;
  std::function<SubjectSet(const SubjectSet&)> make;
};

const std::vector<Mutant>& mutants();
const Mutant* find_mutant(std::string_view name);
void register_mutant(Mutant m);

// A mistake that only exists in some scalars: a computation done in double is exact in double,
// so its negative control can only fail in mp50 and exact. Listed with GM_MUTANT_WRONG_ONLY_IN;
// everywhere else the mutant is right by construction (an equivalent mutant there).
void mutant_wrong_only_in(const std::string& name, std::vector<ScalarKind> kinds);
// Whether the mutant is wrong in scalar k (true unless restricted).
bool mutant_wrong_in(const std::string& name, ScalarKind k);
struct MutantScalarsRegistrar {
  MutantScalarsRegistrar(const char* name, std::vector<ScalarKind> kinds) {
    mutant_wrong_only_in(name, std::move(kinds));
  }
};

struct MutantRegistrar {
  template <class Patch>
  MutantRegistrar(const char* name, const char* description, Patch patch) {
    register_mutant(Mutant{name, description, [name, description, patch](const SubjectSet& base) {
                             return mutate(base, name, description, patch);
                           }});
  }
};

struct MutantSetRegistrar {
  MutantSetRegistrar(const char* name, const char* description, std::function<void(SubjectSet&)> edit) {
    register_mutant(Mutant{name, description, [name, description, edit](const SubjectSet& base) {
                             SubjectSet s = base;
                             s.name = name;
                             s.description = description;
                             edit(s);
                             return s;
                           }});
  }
};

}  // namespace gm

// Already defined only when tests/unity/compiles_alone.py parses a file alone (parse_only.hpp).
#ifndef GM_MUTANT
#define GM_MUTANT(name, description, ...) \
  static const ::gm::MutantRegistrar gm_mutant_##name { #name, description, __VA_ARGS__ }
#define GM_MUTANT_WRONG_ONLY_IN(name, ...)                             \
  static const ::gm::MutantScalarsRegistrar gm_mutant_scalars_##name { \
#name, { __VA_ARGS__ }                                             \
  }
#define GM_MUTANT_SET(name, description, ...) \
  static const ::gm::MutantSetRegistrar gm_mutant_set_##name { #name, description, __VA_ARGS__ }
#endif
