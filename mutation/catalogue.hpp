// The mutants `geomech mutants` runs: the generic operators of mutation/operators.hpp applied to
// every slot of GM_SUBJECT_SLOTS and to every integrator step of the reference, plus every
// hand-written negative control of tests/mutants (class "handwritten").
#pragma once

#include "core/subject.hpp"
#include "properties/registry.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gm::mutation {

struct MutantDef {
  std::string name;      // stable: "euler_3_8:negate_result", "rk4:rigid_body_step:drop_attitude"
  std::string slot;      // the slot mutated ("rigid_body_step"/"manakov_step" for integrators; "" for handwritten)
  std::string op;        // operator name ("negate_result", ...; "handwritten")
  std::string op_class;  // operator class ("result_sign", "factor", ..., "handwritten")
  std::string description;
  std::string integrator;  // integrator mutants: the integrator's name
  StepKind step = StepKind::None;
  // The reference with this one mistake.
  std::function<SubjectSet(const SubjectSet&)> full;
  // Only the mutated slot (or only the mutated integrator) provided; empty for handwritten mutants.
  std::function<SubjectSet(const SubjectSet&)> alone;
};

// Every mutant, generated from `base` (the reference subject): slots in declaration order,
// then integrators, then the hand-written ones.
std::vector<MutantDef> all_mutants(const SubjectSet& base);

}  // namespace gm::mutation
