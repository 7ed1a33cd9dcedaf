// Integrators whose true behaviour is known by theory; see verdict_cases.hpp.
//   ./geomech check examples/integrators/verdict_cases.cpp --integrator backward_euler
#include "verdict_cases.hpp"

GEOMECH_STUDENT(cases::None, cases::BackwardEuler, cases::ExplicitEuler, cases::ExplicitEulerTwin, cases::AlwaysRaises,
                cases::RaisesBeyond, cases::RaisesBeyondDeclared, cases::WrongInsideDeclared, cases::WrongBelowRaise, cases::SinglePrecision, cases::FrameSlip, cases::LieRK4, cases::DampedSplitting,
                cases::StillBelow, cases::Capped, cases::Frozen, cases::RK4, cases::Clamped, cases::GuardedClamp,
                cases::RK4Casimir, cases::FloatBackwardEuler, cases::SmallAngleSnap, cases::FlippedDamping, cases::ShorterWayRound, cases::Midpoint);
