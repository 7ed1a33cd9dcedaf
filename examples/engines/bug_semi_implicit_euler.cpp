// semi_implicit_euler.cpp with one conversion wrong inside each integrator's step (as
// bug_semi_implicit_euler.py): world -> body with R for R^T (world_omega_transpose_slip), the body's
// Omega applied on the world's side of q (body_Omega_on_world_side), pi rebuilt with the attitude
// before the turn (matrix_pi_stale_attitude). Each is a FALSE CLAIM of order 1 whose explanation
// speaks in its declared form.
//   ./geomech check examples/engines/bug_semi_implicit_euler.cpp -p integrator_order --scalar double
#define ENGINE_SLIP 1
#include "semi_implicit_euler.hpp"

GEOMECH_STUDENT(engines::NoSlots, engines::WorldOmega, engines::BodyOmegaXYZW, engines::MatrixSpatialMomentum);
