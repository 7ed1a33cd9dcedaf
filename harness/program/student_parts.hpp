// The main() of the program that checks a student's implementation (the parts it registered are
// assembled by harness/program/student_registry.hpp).
#pragma once

#include "harness/program/student_registry.hpp"

namespace gm::student {

// main() of a student check program: the check options plus --name, --source,
// --reproduce-prefix, --build-notes and --describe.
int student_main(int argc, char** argv);

}  // namespace gm::student
