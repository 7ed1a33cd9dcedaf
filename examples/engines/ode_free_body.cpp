// geomech: pkg ode
//
// The Open Dynamics Engine's free rigid body (Debian's libode-dev 0.16.2), stepped by dWorldStep and
// by dWorldQuickStep, with ODE's gyroscopic term on (its default) and off: four integrators, each in
// the state ODE keeps, a unit quaternion (w, x, y, z) and the angular velocity in the world frame
// (dBodyGetQuaternion, dBodyGetAngularVel). The suite converts; this file converts nothing.
//
//   ./geomech check examples/engines/ode_free_body.cpp                 (the comment line above links ODE)
//   ./geomech check examples/engines/ode_free_body.cpp --untrusted
//
// What ODE's own documentation says about these steps (ODE 0.16.2, the comments of its public header
// /usr/include/ode/objects.h, which libode-dev installs), and the claims made here from it:
//
// - dWorldStep: "This uses a "big matrix" method ... this is currently the most accurate method."
// - dWorldQuickStep: "This uses an iterative method ... For large systems this is a lot faster than
//   dWorldStep(), but it is less accurate."
// - dBodySetGyroscopicMode: "Disabling the gyroscopic term of a body usually improves stability."
//   dBodyGetGyroscopicMode: "nonzero if gyroscopic term computation is enabled (default)".
// - dBodySetFiniteRotationMode: mode 0, the default, "An ``infinitesimal'' orientation update is
//   used. This is fast to compute, but it can occasionally cause inaccuracies for bodies that are
//   rotating at high speed".
// - dWorldStep, dWorldQuickStep: "@param stepsize The number of seconds that the simulation has to
//   advance." (ODE stops the program for a step that is not > 0: "stepsize must be > 0"; a backward
//   step is refused here with that reason.)
//
// None of these is an order, a conservation law, a symmetry or a structure the suite can verify: "most
// accurate" and "less accurate" compare the two steppers without a measure, and "improves stability"
// is about joints and contacts, not a free body. So nothing is claimed: the suite characterises each
// integrator (what holds, what does not, the measured order), and the README's researcher section
// says what it finds. The precision is stated: ODE is built in double here (ode/precision.h defines
// dDOUBLE, and dGetConfiguration() names "ODE_double_precision"), so the steps run in double only.
#include <geomech/student.hpp>

#include <ode/ode.h>

#include <stdexcept>
#include <string>

namespace ode_free_body {

using gm::EngineState;
using V3 = gm::Vec3<double>;

// One world with one body, made once per process (each check runs in a process of its own). The file
// is compiled once per scalar and linked together: its functions are inline.
struct World {
  dWorldID world;
  dBodyID body;
  World() {
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, 0);
    body = dBodyCreate(world);
  }
};

inline World& the_world() {
  static World w;
  return w;
}

enum class Stepper { Step, QuickStep };

// One step of ODE from (q, omega) for the principal moments I (unit mass at the origin, no force).
inline EngineState<double> ode_step(const V3& I, const EngineState<double>& x, double h, Stepper how, bool gyroscopic) {
  if (!(h > 0))
    throw std::domain_error("ODE steps forward only: dWorldStep and dWorldQuickStep stop the program for a "
                            "stepsize that is not > 0 (\"stepsize must be > 0\")");
  World& w = the_world();
  dMass m;
  dMassSetParameters(&m, 1, 0, 0, 0, I(0), I(1), I(2), 0, 0, 0);
  dBodySetMass(w.body, &m);
  dBodySetGyroscopicMode(w.body, gyroscopic ? 1 : 0);
  dBodySetPosition(w.body, 0, 0, 0);
  dBodySetLinearVel(w.body, 0, 0, 0);
  const dQuaternion q = {x.q(0), x.q(1), x.q(2), x.q(3)};  // ODE's order: (w, x, y, z)
  dBodySetQuaternion(w.body, q);
  dBodySetAngularVel(w.body, x.omega(0), x.omega(1), x.omega(2));
  const int ok = how == Stepper::Step ? dWorldStep(w.world, h) : dWorldQuickStep(w.world, h);
  if (!ok) throw std::runtime_error("ODE could not allocate the memory for a step");
  EngineState<double> y = x;
  const dReal* r = dBodyGetQuaternion(w.body);
  const dReal* a = dBodyGetAngularVel(w.body);
  y.q << r[0], r[1], r[2], r[3];
  y.omega << a[0], a[1], a[2];
  return y;
}

constexpr const char* kPrecisionReason =
    "ODE is built in double here: ode/precision.h defines dDOUBLE and dGetConfiguration() names "
    "ODE_double_precision; its steps compute in dReal = double whatever they are given";

#define ODE_INTEGRATOR(Type, label, stepper, gyro)                                                          \
  struct Type {                                                                                            \
    static constexpr const char* name = label;                                                             \
    static constexpr const char* state = "quaternion_wxyz omega";                                         \
    static constexpr const char* precision = "double";                                                     \
    static constexpr const char* precision_reason = kPrecisionReason;                                      \
    static EngineState<double> rigid_body_step(const V3& I, const EngineState<double>& x, const double& h) { \
      return ode_step(I, x, h, stepper, gyro);                                                             \
    }                                                                                                      \
  };

ODE_INTEGRATOR(WorldStep, "dWorldStep", Stepper::Step, true)
ODE_INTEGRATOR(WorldStepNoGyro, "dWorldStep_gyroscopic_off", Stepper::Step, false)
ODE_INTEGRATOR(QuickStep, "dWorldQuickStep", Stepper::QuickStep, true)
ODE_INTEGRATOR(QuickStepNoGyro, "dWorldQuickStep_gyroscopic_off", Stepper::QuickStep, false)
#undef ODE_INTEGRATOR

struct Engine {
  static constexpr const char* description = "the Open Dynamics Engine's free rigid body (dWorldStep, dWorldQuickStep)";
};

}  // namespace ode_free_body

GEOMECH_STUDENT(ode_free_body::Engine, ode_free_body::WorldStep, ode_free_body::WorldStepNoGyro, ode_free_body::QuickStep,
                ode_free_body::QuickStepNoGyro);
