// The prebuilt main() of a student check program: linked with the student's objects, the
// property library (libgeomech.a, whole archive) and the harness. Everything it does lives in
// harness/program/student_parts.cpp, so the same code is covered by the suite's own tests.
#include "harness/program/student_parts.hpp"

int main(int argc, char** argv) { return gm::student::student_main(argc, argv); }
