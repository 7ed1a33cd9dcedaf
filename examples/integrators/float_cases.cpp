// Integrators computed in float, whose verdicts at float's precision theory knows; see float_cases.hpp.
//   ./geomech check examples/integrators/float_cases.cpp --integrator float_rk4
#include "float_cases.hpp"

GEOMECH_STUDENT(float_cases::None, float_cases::FloatExplicitEuler, float_cases::FloatMidpoint,
                float_cases::FloatMidpointUnstated, float_cases::FloatSplitting, float_cases::FloatRK4,
                float_cases::FloatRoundsUp, float_cases::FloatNoGyroscopic, float_cases::FloatRotationSkip);
