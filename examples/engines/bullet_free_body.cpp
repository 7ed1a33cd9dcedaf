// geomech: pkg bullet
//
// The Bullet Physics SDK's free rigid body (Debian's libbullet-dev 3.24), stepped by
// btDiscreteDynamicsWorld::stepSimulation with each of Bullet's gyroscopic settings: the implicit
// body-frame term (Bullet's default), the explicit term (clamped by the body's maximum gyroscopic
// force), and none. Each integrator is in the state Bullet keeps: a unit quaternion (x, y, z, w)
// (btQuaternion's order) and the angular velocity in the world frame (getAngularVelocity). The suite
// converts; this file converts nothing.
//
//   ./geomech check examples/engines/bullet_free_body.cpp               (the comment line above links Bullet)
//   ./geomech check examples/engines/bullet_free_body.cpp --untrusted
//
// What Bullet's own headers say about these steps (Bullet 3.24, /usr/include/bullet, which
// libbullet-dev installs), and the claims made here from it:
//
// - btRigidBody.h, btRigidBodyFlags: "BT_ENABLE_GYROPSCOPIC_FORCE flags is enabled by default in
//   Bullet 2.83 and onwards. and it BT_ENABLE_GYROPSCOPIC_FORCE becomes equivalent to
//   BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY"; "See Demos/GyroscopicDemo and
//   computeGyroscopicImpulseImplicit".
// - btTransformUtil.h, integrateTransform: "Exponential map" (the attitude turned by the angular
//   velocity over the step), "limit the angular motion" (at most pi/4 per step,
//   ANGULAR_MOTION_THRESHOLD), "use Taylor's expansions of sync function" below an angular speed of
//   0.001.
// - btDiscreteDynamicsWorld.h: stepSimulation(timeStep, maxSubSteps = 1, fixedTimeStep = 1/60);
//   with maxSubSteps = 0, as here, one step of timeStep itself.
//
// None of these is an order, a conservation law, a symmetry or a structure the suite can verify, so
// nothing is claimed: the suite characterises each integrator. The precision is stated: Debian builds
// Bullet in single precision (btScalar is float: BT_USE_DOUBLE_PRECISION is not defined, checked
// below at compile time), so every step computes in float whatever it is given, and is judged at
// float's round-off.
#include <geomech/student.hpp>

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <stdexcept>
#include <type_traits>

namespace bullet_free_body {

static_assert(std::is_same_v<btScalar, float>, "this file describes Bullet's float build (btScalar = float)");

using gm::EngineState;
using V3 = gm::Vec3<double>;

// One world holding one body, made once per process (each check runs in a process of its own), with
// no gravity and no collision: a free body. Deactivation ("sleeping") is disabled, as a simulation
// of a free body needs: Bullet stops a body whose speed stays below a threshold for two seconds.
struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btDefaultMotionState motion;
  btSphereShape shape{btScalar(0.5)};  // a body without a shape is never stepped (addRigidBody skips it)
  std::unique_ptr<btRigidBody> body;
  World() {
    world.setGravity(btVector3(0, 0, 0));
    btRigidBody::btRigidBodyConstructionInfo info(1, &motion, &shape, btVector3(1, 1, 1));
    body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(body.get());
  }
  ~World() { world.removeRigidBody(body.get()); }
};

inline World& the_world() {
  static World w;
  return w;
}

// One step of Bullet from (q, omega) for the principal moments I (unit mass, no force), with the
// rigid body's flags (its gyroscopic setting).
inline EngineState<double> bullet_step(const V3& I, const EngineState<double>& x, double h, int flags) {
  World& w = the_world();
  btRigidBody& b = *w.body;
  b.setFlags(flags);
  b.setMassProps(1, btVector3(btScalar(I(0)), btScalar(I(1)), btScalar(I(2))));
  const btQuaternion q(btScalar(x.q(0)), btScalar(x.q(1)), btScalar(x.q(2)), btScalar(x.q(3)));  // (x, y, z, w)
  btTransform t;
  t.setIdentity();
  t.setRotation(q);
  b.setCenterOfMassTransform(t);  // also rotates the inertia into the world frame
  b.setLinearVelocity(btVector3(0, 0, 0));
  b.setAngularVelocity(btVector3(btScalar(x.omega(0)), btScalar(x.omega(1)), btScalar(x.omega(2))));
  b.clearForces();
  w.world.stepSimulation(btScalar(h), 0);
  EngineState<double> y = x;
  const btQuaternion r = b.getCenterOfMassTransform().getRotation();
  const btVector3& a = b.getAngularVelocity();
  y.q << r.x(), r.y(), r.z(), r.w();
  y.omega << a.x(), a.y(), a.z();
  return y;
}

constexpr const char* kPrecisionReason =
    "Bullet is built in single precision in Debian: btScalar is float (BT_USE_DOUBLE_PRECISION is not defined, a "
    "static_assert of this file checks it), so its steps compute in float whatever they are given";

#define BULLET_INTEGRATOR(Type, label, flags)                                                                \
  struct Type {                                                                                              \
    static constexpr const char* name = label;                                                               \
    static constexpr const char* state = "quaternion_xyzw omega";                                           \
    static constexpr const char* precision = "float";                                                        \
    static constexpr const char* precision_reason = kPrecisionReason;                                        \
    static EngineState<double> rigid_body_step(const V3& I, const EngineState<double>& x, const double& h) { \
      return bullet_step(I, x, h, flags);                                                                    \
    }                                                                                                        \
  };

BULLET_INTEGRATOR(ImplicitBody, "stepSimulation", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY)
BULLET_INTEGRATOR(Explicit, "stepSimulation_gyroscopic_explicit", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT)
BULLET_INTEGRATOR(NoGyroscopic, "stepSimulation_gyroscopic_off", 0)
#undef BULLET_INTEGRATOR

struct Engine {
  static constexpr const char* description =
      "the Bullet Physics SDK's free rigid body (btDiscreteDynamicsWorld::stepSimulation), in float";
};

}  // namespace bullet_free_body

GEOMECH_STUDENT(bullet_free_body::Engine, bullet_free_body::ImplicitBody, bullet_free_body::Explicit,
                bullet_free_body::NoGyroscopic);
