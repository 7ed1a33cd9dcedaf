// Semi-implicit Euler as physics engines write it, in the state forms engines keep (the C++ twin of
// semi_implicit_euler.py; bug_semi_implicit_euler.cpp includes this with one conversion wrong in
// each step). An engine steps the angular velocity first (explicitly, with the gyroscopic term), then
// turns the attitude with the new angular velocity and renormalises its quaternion. Each integrator
// keeps its state in another form and says so in `state`; the suite converts to the notes' (Pi, O)
// with I, and this file converts nothing to them. Written for double, as an engine is.
#pragma once

#include <geomech/student.hpp>

#include <cmath>

namespace engines {

using gm::EngineState;
using V3 = gm::Vec3<double>;
using V4 = gm::Vec4<double>;
using M3 = gm::Mat3<double>;

// The slips of bug_semi_implicit_euler.cpp (one in each integrator), off here.
#ifndef ENGINE_SLIP
#define ENGINE_SLIP 0
#endif
constexpr bool kSlip = ENGINE_SLIP != 0;

inline V4 qmul(const V4& a, const V4& b) {  // Hamilton's product of (w, x, y, z) quaternions
  const V3 av = a.tail<3>(), bv = b.tail<3>();
  V4 c;
  c << a(0) * b(0) - av.dot(bv), a(0) * bv + b(0) * av + av.cross(bv);
  return c;
}

inline M3 rotation(const V4& q) {  // body -> world, of a unit quaternion (w, x, y, z)
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  M3 R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),    //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

inline M3 axis_angle(const V3& v, double h) {  // exp(h hat(v)), Rodrigues
  const double a = v.norm();
  if (a == 0) return M3::Identity();
  const V3 k = v / a;
  M3 K;
  K << 0, -k(2), k(1), k(2), 0, -k(0), -k(1), k(0), 0;
  return M3::Identity() + std::sin(h * a) * K + (1 - std::cos(h * a)) * K * K;
}

// Omega <- Omega + h I^-1 ((I Omega) x Omega): Euler's equations (2.2), explicitly.
inline V3 body_velocity_step(const V3& I, const V3& W, double h) {
  return W + h * V3(I.cwiseProduct(W).cross(W)).cwiseQuotient(I);
}

// q <- normalise(q + (h/2) q (0, Omega)): the body's rate turns q on the body's side (world_side:
// the slip of applying it as (0, Omega) q, the world's rate).
inline V4 turn(const V4& q, const V3& W, double h, bool world_side = false) {
  const V4 pure(0, W(0), W(1), W(2));
  const V4 d = world_side ? qmul(pure, q) : qmul(q, pure);
  return (q + h / 2 * d).normalized();
}

constexpr const char* kWhy = "written as an engine is, in double";

// The engine's own form: a quaternion (w, x, y, z) and the world-frame angular velocity omega.
struct WorldOmega {
  static constexpr const char* name = ENGINE_SLIP ? "world_omega_transpose_slip" : "semi_implicit_world_omega";
  static constexpr const char* state = "quaternion_wxyz omega";
  static constexpr const char* precision = "double";
  static constexpr const char* precision_reason = kWhy;
  static constexpr gm::student::Claims claims{.order = 1, .unit_quaternion = true};
  static EngineState<double> rigid_body_step(const V3& I, const EngineState<double>& x, const double& h) {
    const M3 R = rotation(x.q);
    // world -> body: Omega = R^T omega (the slip: R omega)
    const V3 W = body_velocity_step(I, kSlip ? V3(R * x.omega) : V3(R.transpose() * x.omega), h);
    EngineState<double> y = x;
    y.q = turn(x.q, W, h);
    y.omega = rotation(y.q) * W;  // body -> world with the new attitude
    return y;
  }
};

// A quaternion stored (x, y, z, w) and the body's Omega.
struct BodyOmegaXYZW {
  static constexpr const char* name = ENGINE_SLIP ? "body_Omega_on_world_side" : "semi_implicit_body_Omega_xyzw";
  static constexpr const char* state = "quaternion_xyzw Omega";
  static constexpr const char* precision = "double";
  static constexpr const char* precision_reason = kWhy;
  static constexpr gm::student::Claims claims{.order = 1, .unit_quaternion = true};
  static EngineState<double> rigid_body_step(const V3& I, const EngineState<double>& x, const double& h) {
    const V3 W = body_velocity_step(I, x.Omega, h);
    const V4 q = turn(V4(x.q(3), x.q(0), x.q(1), x.q(2)), W, h, kSlip);
    EngineState<double> y = x;
    y.q = V4(q(1), q(2), q(3), q(0));
    y.Omega = W;
    return y;
  }
};

// A rotation matrix and the spatial angular momentum pi, which a free body keeps.
struct MatrixSpatialMomentum {
  static constexpr const char* name = ENGINE_SLIP ? "matrix_pi_stale_attitude" : "semi_implicit_matrix_pi";
  static constexpr const char* state = "matrix pi";
  static constexpr const char* precision = "double";
  static constexpr const char* precision_reason = kWhy;
  static constexpr gm::student::Claims claims{.order = 1, .orthogonality = true};
  static EngineState<double> rigid_body_step(const V3& I, const EngineState<double>& x, const double& h) {
    V3 W = V3(x.O.transpose() * x.pi).cwiseQuotient(I);  // Omega = I^-1 O^T pi
    W = body_velocity_step(I, W, h);
    EngineState<double> y = x;
    y.O = x.O * axis_angle(W, h);
    y.pi = (kSlip ? x.O : y.O) * I.cwiseProduct(W);  // pi = O I Omega, the new O (the slip: the old)
    return y;
  }
};

struct NoSlots {
  static constexpr const char* description = ENGINE_SLIP ? "semi-implicit Euler in an engine's state forms, one "
                                                           "conversion wrong in each step"
                                                         : "semi-implicit Euler in an engine's state forms";
};

}  // namespace engines
