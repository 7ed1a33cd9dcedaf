// The suite's findings on the Bullet Physics SDK (examples/engines/bullet_free_body.cpp), each
// confirmed by this test's own computation, written here without the suite: Bullet called directly
// (btDiscreteDynamicsWorld::stepSimulation on one free body, as the wrapper steps it), a reference
// solution of the free rigid body by classical RK4 in double on Euler's equations (2.2) and the
// quaternion's kinematics, and the invariants computed from Bullet's own state (its quaternion and
// world-frame angular velocity).
//
//   bullet_confirm REPORT_DIR/verdicts.json
//
// Bullet computes in float here (Debian's build), so a quantity holds when its largest change over
// 64 steps of h = 1/8 stays below 32 x 64 float eps (2.4e-4: float round-off, accumulated at most
// linearly); a first-order method's drift is about 1e-2. For each integrator (the gyroscopic term
// implicit in the body frame, Bullet's default; explicit; off) the findings of the suite's claims
// table for unit_quaternion, energy, casimir and noether must agree with this test's, and the order
// this test measures (the log-log slope of the error at t = 1 for h = 1/4 ... 1/16, where Bullet's
// first-order error stands far above float's round-off) must agree with the suite's within 0.2.
// Then three findings of Bullet's own code that the suite reports, measured here:
//   - a step of |h| below FLT_EPSILON does nothing (stepSimulation's btFuzzyZero(timeStep));
//   - the explicit gyroscopic term is clamped at the solver's maximum gyroscopic force (100);
//   - with the gyroscopic term off the body's world angular velocity never changes.
// Exit status 0 when every finding agrees, 1 otherwise (each disagreement printed).
#include <btBulletDynamicsCommon.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using V3 = std::array<double, 3>;
using Q = std::array<double, 4>;  // (w, x, y, z) here; Bullet's btQuaternion is (x, y, z, w)

struct State {
  Q q;
  V3 omega;  // world frame
};

const V3 kI = {1.25, 0.75, 0.5};  // principal moments

Q mul(const Q& a, const Q& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
V3 to_body(const Q& q, const V3& v) {
  const Q r = mul(mul({q[0], -q[1], -q[2], -q[3]}, {0, v[0], v[1], v[2]}), q);
  return {r[1], r[2], r[3]};
}
V3 to_world(const Q& q, const V3& v) {
  const Q r = mul(mul(q, {0, v[0], v[1], v[2]}), {q[0], -q[1], -q[2], -q[3]});
  return {r[1], r[2], r[3]};
}

struct Bullet {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btDefaultMotionState motion;
  btSphereShape shape{btScalar(0.5)};  // a body without a shape is never stepped (addRigidBody skips it)
  std::unique_ptr<btRigidBody> body;
  Bullet() {
    world.setGravity(btVector3(0, 0, 0));
    btRigidBody::btRigidBodyConstructionInfo info(1, &motion, &shape, btVector3(1, 1, 1));
    body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(body.get());
  }
  ~Bullet() { world.removeRigidBody(body.get()); }
  State step(const State& x, double h, int flags) {
    body->setFlags(flags);
    body->setMassProps(1, btVector3(btScalar(kI[0]), btScalar(kI[1]), btScalar(kI[2])));
    btTransform t;
    t.setIdentity();
    t.setRotation(btQuaternion(btScalar(x.q[1]), btScalar(x.q[2]), btScalar(x.q[3]), btScalar(x.q[0])));
    body->setCenterOfMassTransform(t);
    body->setLinearVelocity(btVector3(0, 0, 0));
    body->setAngularVelocity(btVector3(btScalar(x.omega[0]), btScalar(x.omega[1]), btScalar(x.omega[2])));
    body->clearForces();
    world.stepSimulation(btScalar(h), 0);
    const btQuaternion r = body->getCenterOfMassTransform().getRotation();
    const btVector3& a = body->getAngularVelocity();
    return {{r.w(), r.x(), r.y(), r.z()}, {a.x(), a.y(), a.z()}};
  }
};

// The free rigid body's field on (q, Omega): dOmega/dt = I^-1 ((I Omega) x Omega) (2.2),
// dq/dt = q (0, Omega) / 2.
struct Body {
  Q q;
  V3 W;
};
Body field(const Body& b) {
  const V3 L = {kI[0] * b.W[0], kI[1] * b.W[1], kI[2] * b.W[2]};
  const V3 c = {L[1] * b.W[2] - L[2] * b.W[1], L[2] * b.W[0] - L[0] * b.W[2], L[0] * b.W[1] - L[1] * b.W[0]};
  const Q dq = mul(b.q, {0, b.W[0], b.W[1], b.W[2]});
  return {{dq[0] / 2, dq[1] / 2, dq[2] / 2, dq[3] / 2}, {c[0] / kI[0], c[1] / kI[1], c[2] / kI[2]}};
}
Body add(const Body& a, const Body& d, double s) {
  Body r;
  for (int i = 0; i < 4; ++i) r.q[i] = a.q[i] + s * d.q[i];
  for (int i = 0; i < 3; ++i) r.W[i] = a.W[i] + s * d.W[i];
  return r;
}
State reference(const State& x0, double t, int n) {  // classical RK4 in double, n steps
  Body b{x0.q, to_body(x0.q, x0.omega)};
  const double h = t / n;
  for (int k = 0; k < n; ++k) {
    const Body k1 = field(b), k2 = field(add(b, k1, h / 2)), k3 = field(add(b, k2, h / 2)), k4 = field(add(b, k3, h));
    for (int i = 0; i < 4; ++i) b.q[i] += h / 6 * (k1.q[i] + 2 * k2.q[i] + 2 * k3.q[i] + k4.q[i]);
    for (int i = 0; i < 3; ++i) b.W[i] += h / 6 * (k1.W[i] + 2 * k2.W[i] + 2 * k3.W[i] + k4.W[i]);
  }
  return {b.q, to_world(b.q, b.W)};
}

double distance(const State& a, const State& b) {  // q and -q are one attitude
  double plus = 0, minus = 0, w = 0;
  for (int i = 0; i < 4; ++i)
    plus = std::max(plus, std::fabs(a.q[i] - b.q[i])), minus = std::max(minus, std::fabs(a.q[i] + b.q[i]));
  for (int i = 0; i < 3; ++i) w = std::max(w, std::fabs(a.omega[i] - b.omega[i]));
  return std::max(std::min(plus, minus), w);
}

// The rotation angle between two attitudes.
double angle_between(const Q& a, const Q& b) {
  const double d = std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return 2 * std::acos(std::min(1.0, d));
}

constexpr double kFloatEps = FLT_EPSILON;

struct Own {
  std::map<std::string, bool> holds;    // unit_quaternion, energy, casimir, noether
  std::map<std::string, double> drift;  // the largest change over the 64 steps
  double order = 0;
};

Own measure(Bullet& bullet, int flags) {
  const State x0{{std::cos(0.3), 0.6 * std::sin(0.3), 0.8 * std::sin(0.3), 0}, {0.3, 0.5, -0.7}};
  auto invariants = [](const State& x) {
    const V3 W = to_body(x.q, x.omega);
    double e = 0, c = 0;
    for (int i = 0; i < 3; ++i) e += kI[i] * W[i] * W[i] / 2, c += kI[i] * W[i] * kI[i] * W[i];
    const V3 pi = to_world(x.q, {kI[0] * W[0], kI[1] * W[1], kI[2] * W[2]});
    const double n = x.q[0] * x.q[0] + x.q[1] * x.q[1] + x.q[2] * x.q[2] + x.q[3] * x.q[3];
    return std::array<double, 6>{n, e, c, pi[0], pi[1], pi[2]};
  };
  const auto v0 = invariants(x0);
  std::array<double, 4> drift{};  // |q|^2, energy, |Pi|^2, pi (relative to their sizes, which are about 1)
  State x = x0;
  for (int k = 0; k < 64; ++k) {
    x = bullet.step(x, 1.0 / 8, flags);
    const auto v = invariants(x);
    drift[0] = std::max(drift[0], std::fabs(v[0] - 1));
    drift[1] = std::max(drift[1], std::fabs(v[1] - v0[1]) / v0[1]);
    drift[2] = std::max(drift[2], std::fabs(v[2] - v0[2]) / v0[2]);
    for (int i = 3; i < 6; ++i) drift[3] = std::max(drift[3], std::fabs(v[i] - v0[i]));
  }
  Own own;
  const char* names[] = {"unit_quaternion", "energy", "casimir", "noether"};
  for (int i = 0; i < 4; ++i) own.holds[names[i]] = drift[i] <= 32 * 64 * kFloatEps, own.drift[names[i]] = drift[i];
  // The order: error at t = 1 against RK4 with 2^14 steps, for h = 1/4 ... 1/16.
  const State exact = reference(x0, 1, 1 << 14);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int Ns[] = {4, 8, 16};
  for (int N : Ns) {
    State y = x0;
    for (int k = 0; k < N; ++k) y = bullet.step(y, 1.0 / N, flags);
    const double lx = std::log(1.0 / N), ly = std::log(distance(y, exact));
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  own.order = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
  return own;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: bullet_confirm REPORT_DIR/verdicts.json\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "bullet_confirm: cannot read " << argv[1] << "\n";
    return 2;
  }
  const nlohmann::json report = nlohmann::json::parse(in);
  Bullet bullet;
  int disagreements = 0, compared = 0;
  struct Which {
    const char* name;
    int flags;
  };
  const Which which[] = {{"stepSimulation", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY},
                         {"stepSimulation_gyroscopic_explicit", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT},
                         {"stepSimulation_gyroscopic_off", 0}};
  for (const Which w : which) {
    const Own own = measure(bullet, w.flags);
    const nlohmann::json* integ = nullptr;
    for (const auto& i : report.at("integrators"))
      if (i.at("name") == w.name) integ = &i;
    if (!integ) {
      std::cout << w.name << ": not in the report\n";
      ++disagreements;
      continue;
    }
    for (const auto& [claim, holds] : own.holds) {
      std::string status;
      for (const auto& row : integ->at("claims"))
        if (row.at("claim") == claim) status = row.at("status");
      if (status.empty() || status == "-") continue;  // not run in this report
      const bool suite = status.rfind("holds (not claimed)", 0) == 0 || status.rfind("verified", 0) == 0;
      ++compared;
      std::cout << w.name << " " << claim << ": suite '" << status << "', this test "
                << (holds ? "holds" : "does not hold")
                << " (largest change over 64 steps of h = 1/8: " << own.drift.at(claim) << ")"
                << (suite == holds ? "" : "  <-- DISAGREE") << "\n";
      disagreements += suite != holds;
    }
    // The suite's order, from the convergence series integrator_order measured (its own states and
    // reference), fitted over the points it used, against this test's.
    for (const auto& v : report.at("verdicts")) {
      if (v.value("property", "") != "integrator_order" || v.value("integrator", "") != w.name) continue;
      std::string measured;
      for (const auto& f : v.value("claims", nlohmann::json::array()))
        if (f.value("claim", "") == "order") measured = f.value("measured", "");
      const auto at = measured.find("order ");
      if (at == std::string::npos) continue;
      const double suite = std::atof(measured.c_str() + at + 6);
      ++compared;
      const bool agree = std::fabs(suite - own.order) <= 0.2;
      std::printf("%s order: suite '%s', this test %.3f%s\n", w.name, measured.c_str(), own.order,
                  agree ? "" : "  <-- DISAGREE");
      disagreements += !agree;
    }
  }
  // Bullet's own code, measured: a step below FLT_EPSILON does nothing; the explicit gyroscopic term
  // is clamped; with the gyroscopic term off, the world's omega never changes.
  {
    const State x0{{std::cos(0.4), 0.6 * std::sin(0.4), 0, 0.8 * std::sin(0.4)}, {0.7, -0.2, 0.4}};
    const State tiny = bullet.step(x0, 0.5 * kFloatEps, BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
    const double moved = distance(tiny, x0);
    std::printf("a step of h = FLT_EPSILON / 2 moves the state by %g (float round-off of the input: %g at most)\n",
                moved, 2 * kFloatEps);
    ++compared;
    if (moved > 2 * kFloatEps) {
      std::cout << "  <-- a step below FLT_EPSILON was expected to do nothing\n";
      ++disagreements;
    }
    // The explicit gyroscopic term is clamped: at a fast state the change of the world's angular
    // momentum in one short step stands at Bullet's default maximum gyroscopic force (100), where the
    // term (I omega) x omega itself is far larger; at a slow state it is the term.
    auto torque = [&](const State& x, double h) {
      const State y = bullet.step(x, h, BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT);
      const V3 Lx = to_world(x.q, [&] {
        const V3 W = to_body(x.q, x.omega);
        return V3{kI[0] * W[0], kI[1] * W[1], kI[2] * W[2]};
      }());
      const V3 Ly = to_world(y.q, [&] {
        const V3 W = to_body(y.q, y.omega);
        return V3{kI[0] * W[0], kI[1] * W[1], kI[2] * W[2]};
      }());
      double n = 0;
      for (int i = 0; i < 3; ++i) n += (Ly[i] - Lx[i]) * (Ly[i] - Lx[i]);
      return std::sqrt(n) / h;
    };
    // A free body keeps L = I_world omega: the explicit term is what turns omega as the inertia turns
    // with the body, |omega x L| of it a second. Clamped at 100, L moves by the rest: |dL/dt| =
    // |omega x L| - 100 at a fast state, about 0 (first order in h) at a slow one.
    const State fast{x0.q, {70, -20, 40}};
    const V3 W = to_body(fast.q, fast.omega);
    const V3 L = to_world(fast.q, {kI[0] * W[0], kI[1] * W[1], kI[2] * W[2]});
    const V3 wxL = {fast.omega[1] * L[2] - fast.omega[2] * L[1], fast.omega[2] * L[0] - fast.omega[0] * L[2],
                    fast.omega[0] * L[1] - fast.omega[1] * L[0]};
    const double term = std::sqrt(wxL[0] * wxL[0] + wxL[1] * wxL[1] + wxL[2] * wxL[2]);
    const double capped = torque(fast, 1e-4), slow = torque(x0, 1e-4);
    std::printf(
        "explicit gyroscopic term at |omega| = 83: |omega x L| = %.4g, and L moves by |dL/dt| = %.4g: "
        "the term applied is %.4g (Bullet's default maximum gyroscopic force: 100); at |omega| = 0.8 L "
        "moves by %.3g\n",
        term, capped, term - capped, slow);
    ++compared;
    if (!(std::fabs(term - capped - 100) <= 2)) {
      std::cout << "  <-- the explicit gyroscopic term was expected to be clamped at 100\n";
      ++disagreements;
    }
    State y = x0;
    double changed = 0;
    for (int k = 0; k < 64; ++k) {
      y = bullet.step(y, 1.0 / 8, 0);
      for (int i = 0; i < 3; ++i) changed = std::max(changed, std::fabs(y.omega[i] - x0.omega[i]));
    }
    std::printf("gyroscopic term off, 64 steps of h = 1/8: the world's omega changes by %g at most\n", changed);
    ++compared;
    if (changed > 4 * kFloatEps) {
      std::cout << "  <-- with the gyroscopic term off the world's omega was expected to stay\n";
      ++disagreements;
    }
  }
  std::cout << compared << " findings compared, " << disagreements << " disagreements\n";
  return compared > 0 && disagreements == 0 ? 0 : 1;
}
