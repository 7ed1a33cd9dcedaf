// The parts a student's translation units registered through GEOMECH_STUDENT (one per scalar),
// assembled into one subject.
#pragma once

#include "harness/checking/check.hpp"

#include <geomech/student.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace gm::student {

struct Registered {
  std::shared_ptr<const Subject<double>> d;
  std::shared_ptr<const Subject<Real50>> mp;
  std::shared_ptr<const Subject<Rational>> q;
  std::optional<PartInfo> d_info, mp_info, q_info;
};

const Registered& registered();

// The subject and what is known about it. `build_notes` is what the build found (scalars or
// slots that did not compile), as written by `geomech check` (see harness/program/build.hpp).
// What the build found (scalars and slots that did not compile, the compiler's warnings) into info.
void apply_build_notes(harness::SubjectInfo& info, const nlohmann::json& build_notes);

SubjectSet assemble(const std::string& name, harness::SubjectInfo& info, const nlohmann::json& build_notes);

}  // namespace gm::student
