// The parts a student's translation units registered through GEOMECH_STUDENT (one per scalar),
// assembled into one subject, and the main() of the program that checks it.
#pragma once

#include "harness/check.hpp"

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
// slots that did not compile), as written by `geomech check` (see harness/build.hpp).
SubjectSet assemble(const std::string& name, harness::SubjectInfo& info, const nlohmann::json& build_notes);

// main() of a student check program: the check options plus --name, --source,
// --reproduce-prefix, --build-notes and --describe.
int student_main(int argc, char** argv);

}  // namespace gm::student
