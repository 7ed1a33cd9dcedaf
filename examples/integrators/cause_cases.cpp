// Integrators with one known defect each, whose cause an experiment confirms or none can; see
// cause_cases.hpp.
//   ./geomech check examples/integrators/cause_cases.cpp --integrator speed_cap
#include "cause_cases.hpp"

GEOMECH_STUDENT(cause_cases::None, cause_cases::SmallAngleSeries, cause_cases::IgnoresNegative, cause_cases::SpeedCap,
                cause_cases::RaisesSlowWrongElsewhere, cause_cases::NoGyroscopic);
