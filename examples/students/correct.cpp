// A correct implementation: every property it can be checked by passes.
#include "correct.hpp"

GEOMECH_STUDENT(course::RigidBody, course::Midpoint, course::Splitting, course::ClebschMidpoint);
