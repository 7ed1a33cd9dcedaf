// Integrators whose true behaviour is known by theory: each is a step a researcher or an
// engine writes, with the claims it makes, and the verdict theory gives is what the suite must say.
// tests/integrator_verdict_tests.py checks each, confirming the verdict by a computation of its own.
#pragma once

#include <geomech/student.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cases {

using namespace gm;

// The notes' (3.8), (3.5) and (2.11), written here so that each step below is self-contained.
template <class T>
Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
  const Vec3<T> W = Pi.cwiseQuotient(I);
  return Pi.cross(W);
}
template <class T>
Mat3<T> hat(const Vec3<T>& v) {
  Mat3<T> m;
  m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
  return m;
}
template <class T>
Mat3<T> cayley(const Mat3<T>& A) {
  const Mat3<T> Id = Mat3<T>::Identity();
  return (Id - A / T(2)).inverse() * (Id + A / T(2));
}
template <class T>
T size(const Vec3<T>& v) {
  return v.cwiseAbs().maxCoeff();
}

// The implicit midpoint rule on (Pi, O) (correct.hpp's Midpoint), with the vector field given:
// Pi' = Pi + h F(mid), O' = O cay(h hat(I^-1 mid)). F = (3.8) gives the true midpoint rule.
template <class T, class Field>
RigidBodyState<T> midpoint(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h, const Field& F) {
  Vec3<T> next = x.Pi;
  for (int it = 0; it < 200; ++it) {
    const Vec3<T> mid = (x.Pi + next) / T(2);
    const Vec3<T> again = x.Pi + h * F(mid);
    const T change = (again - next).cwiseAbs().maxCoeff();
    next = again;
    if (change <= T(8) * std::numeric_limits<T>::epsilon() * size(x.Pi)) break;
  }
  const Vec3<T> W_mid = ((x.Pi + next) / T(2)).cwiseQuotient(I);
  return {next, x.O * cayley<T>(h * hat<T>(W_mid))};
}

struct None {};  // the implementation: integrators only

// 1. Backward Euler, claiming order 1 (true) and bounded energy (false: it loses energy at every
//    step, the classic dissipative method).
struct BackwardEuler {
  static constexpr const char* name = "backward_euler";
  static constexpr gm::student::Claims claims{.order = 1, .bounded_energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    Vec3<T> next = x.Pi;
    for (int it = 0; it < 400; ++it) {
      const Vec3<T> again = x.Pi + h * euler_3_8<T>(I, next);
      const T change = (again - next).cwiseAbs().maxCoeff();
      next = again;
      if (change <= T(8) * std::numeric_limits<T>::epsilon() * size(x.Pi)) break;
    }
    return {next, x.O * cayley<T>(h * hat<T>(Vec3<T>(next.cwiseQuotient(I))))};
  }
};

// 2. Explicit Euler under two names: the same step, so the same verdicts.
template <class T>
RigidBodyState<T> explicit_euler(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  return {x.Pi + h * euler_3_8<T>(I, x.Pi), x.O * (Mat3<T>::Identity() + h * hat<T>(Vec3<T>(x.Pi.cwiseQuotient(I))))};
}
struct ExplicitEuler {
  static constexpr const char* name = "explicit_euler";
  static constexpr gm::student::Claims claims{.order = 1, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return explicit_euler<T>(I, x, h);
  }
};
struct ExplicitEulerTwin {
  static constexpr const char* name = "explicit_euler_twin";
  static constexpr gm::student::Claims claims{.order = 1, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return explicit_euler<T>(I, x, h);
  }
};

// 3. A step that raises on every call.
struct AlwaysRaises {
  static constexpr const char* name = "always_raises";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>&, const RigidBodyState<T>&, const T&) {
    throw std::runtime_error("the engine is not initialised");
  }
};

// 4. The midpoint rule of an engine that refuses fast states (|Omega| >= 2^20, "resets above"):
//    order 2, Casimir, energy and orthogonality claimed and true where it works.
template <class T>
void refuse_fast(const Vec3<T>& I, const Vec3<T>& Pi) {
  if (size(Vec3<T>(Pi.cwiseQuotient(I))) >= T(1 << 20)) throw std::runtime_error("angular velocity out of range");
}
struct RaisesBeyond {
  static constexpr const char* name = "raises_beyond";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true, .energy = true, .orthogonality = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    refuse_fast<T>(I, x.Pi);
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

// 4b. The same engine, declaring where it is meant to work: nothing faster than 2^19 is drawn.
struct RaisesBeyondDeclared {
  static constexpr const char* name = "raises_beyond_declared";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true, .energy = true, .orthogonality = true};
  static constexpr gm::student::Domain domain{.max_omega = 524288};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    refuse_fast<T>(I, x.Pi);
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

// 4c. The negative control of a declared domain: the engine of 4b declaring the same domain, whose
//     step inside it is explicit Euler (2.6), claiming the Casimir. The claim is false where the step
//     is meant to work, so it must stay a FALSE CLAIM: a domain only discards the calls outside it.
struct WrongInsideDeclared {
  static constexpr const char* name = "wrong_inside_declared";
  static constexpr gm::student::Claims claims{.order = 1, .casimir = true};
  static constexpr gm::student::Domain domain{.max_omega = 524288};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    refuse_fast<T>(I, x.Pi);
    return explicit_euler<T>(I, x, h);
  }
};

// 4d. The engine of 4a with no domain declared and a defect far below where it raises: for
//     |Omega| < 2^-20 its "slow body" shortcut takes an explicit Euler step (2.6), which does not
//     keep the Casimir. A check whose cases meet the raise first must still find the defect, run
//     again inside the range where the step works: the Casimir claimed, a FALSE CLAIM.
struct WrongBelowRaise {
  static constexpr const char* name = "wrong_below_raise";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    refuse_fast<T>(I, x.Pi);
    if (size(Vec3<T>(x.Pi.cwiseQuotient(I))) < T(1) / T(1 << 20)) return explicit_euler<T>(I, x, h);  // "slow body"
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

// 5. A midpoint rule computed in single precision (as engines built with float are), claiming
//    order 2 and the Casimir: true in exact arithmetic, not at float's round-off.
struct SinglePrecision {
  static constexpr const char* name = "single_precision";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Vec3<float> If(float(to_double_value(I(0))), float(to_double_value(I(1))), float(to_double_value(I(2))));
    RigidBodyState<float> xf;
    for (int i = 0; i < 3; ++i) xf.Pi(i) = float(to_double_value(x.Pi(i)));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) xf.O(i, j) = float(to_double_value(x.O(i, j)));
    const RigidBodyState<float> yf =
        midpoint<float>(If, xf, float(to_double_value(h)), [&](const Vec3<float>& P) { return euler_3_8<float>(If, P); });
    RigidBodyState<T> y;
    for (int i = 0; i < 3; ++i) y.Pi(i) = T(double(yf.Pi(i)));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y.O(i, j) = T(double(yf.O(i, j)));
    return y;
  }
  template <class T>
  static double to_double_value(const T& v) {
    return static_cast<double>(v);
  }
};

// 6. An engine's wrapper with a frame slip: the engine keeps the spatial momentum pi = O Pi; the
//    wrapper converts back with O instead of O^T. The engine's step is right; the wrapper is not:
//    step(x, h) does not tend to x as h -> 0 (unless O = Id).
struct FrameSlip {
  static constexpr const char* name = "frame_slip";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const RigidBodyState<T> y = midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
    const Vec3<T> pi = y.O * y.Pi;      // the engine's spatial momentum
    return {Vec3<T>(y.O * pi), y.O};   // the slip: O pi, where O^T pi is Pi
  }
};

// 7. A Lie-group RK4: Pi by the classical RK4 (order 4), O by one Cayley factor of the body's
//    angular velocity at the middle of the step (order 2). Claims order 4: false, and it is the
//    attitude that is order 2.
struct LieRK4 {
  static constexpr const char* name = "lie_rk4";
  static constexpr gm::student::Claims claims{.order = 4};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Vec3<T> k1 = euler_3_8<T>(I, x.Pi);
    const Vec3<T> k2 = euler_3_8<T>(I, Vec3<T>(x.Pi + h / T(2) * k1));
    const Vec3<T> k3 = euler_3_8<T>(I, Vec3<T>(x.Pi + h / T(2) * k2));
    const Vec3<T> k4 = euler_3_8<T>(I, Vec3<T>(x.Pi + h * k3));
    const Vec3<T> next = x.Pi + h / T(6) * (k1 + T(2) * k2 + T(2) * k3 + k4);
    const Vec3<T> W_mid = ((x.Pi + next) / T(2)).cwiseQuotient(I);
    return {next, x.O * cayley<T>(h * hat<T>(W_mid))};
  }
};

// 8. A Strang splitting with a little damping (Pi multiplied by exp(-h / 2^14) after each step, a
//    "numerical friction" engines add for stability), claiming bounded energy: false, it loses
//    energy at every step.
struct DampedSplitting {
  static constexpr const char* name = "damped_splitting";
  static constexpr gm::student::Claims claims{.bounded_energy = true};
  template <class T>
  static Mat3<T> rotation(int axis, const T& angle) {
    using std::cos;
    using std::sin;
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    Mat3<T> R = Mat3<T>::Identity();
    R(j, j) = cos(angle), R(j, k) = -sin(angle), R(k, j) = sin(angle), R(k, k) = cos(angle);
    return R;
  }
  template <class T>
  static void flow(int axis, const Vec3<T>& I, RigidBodyState<T>& x, const T& t) {
    const T angle = t * x.Pi(axis) / I(axis);
    x.Pi = rotation<T>(axis, -angle) * x.Pi;
    x.O = x.O * rotation<T>(axis, angle);
  }
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x0, const T& h) {
    using std::exp;
    RigidBodyState<T> x = x0;
    flow<T>(0, I, x, h / T(2)), flow<T>(1, I, x, h / T(2)), flow<T>(2, I, x, h), flow<T>(1, I, x, h / T(2)),
        flow<T>(0, I, x, h / T(2));
    x.Pi *= exp(-h / T(16384));
    return x;
  }
};

// 9. The midpoint rule behind a "nothing to do" guard: it returns its input for h < 2^-30.
struct StillBelow {
  static constexpr const char* name = "still_below";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true, .energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    using std::abs;
    if (abs(h) < T(1) / T(1073741824)) return x;
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

// 10. The midpoint rule with a capped angular velocity: beyond |Omega| = 2^10 the field is 0.347
//     times (3.8) (a "max angular velocity" setting, as engines have).
struct Capped {
  static constexpr const char* name = "capped";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const bool fast = size(Vec3<T>(x.Pi.cwiseQuotient(I))) > T(1024);
    const T factor = fast ? T(347) / T(1000) : T(1);
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return Vec3<T>(factor * euler_3_8<T>(I, P)); });
  }
};

// 11. A step that does nothing at all (Pi and O unchanged), claiming nothing.
struct Frozen {
  static constexpr const char* name = "frozen";
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>&, const RigidBodyState<T>& x, const T&) {
    return x;
  }
};

// 12. The classical RK4 on (Pi, O) together, claiming only its order: its energy drifts (slowly,
//     linearly in t), which an unclaimed energy row must say, not "holds".
struct RK4 {
  static constexpr const char* name = "rk4";
  static constexpr gm::student::Claims claims{.order = 4};
  template <class T>
  static RigidBodyState<T> f(const Vec3<T>& I, const RigidBodyState<T>& x) {
    return {euler_3_8<T>(I, x.Pi), Mat3<T>(x.O * hat<T>(Vec3<T>(x.Pi.cwiseQuotient(I))))};
  }
  template <class T>
  static RigidBodyState<T> plus(const RigidBodyState<T>& x, const T& a, const RigidBodyState<T>& k) {
    return {Vec3<T>(x.Pi + a * k.Pi), Mat3<T>(x.O + a * k.O)};
  }
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const auto k1 = f<T>(I, x), k2 = f<T>(I, plus<T>(x, h / T(2), k1)), k3 = f<T>(I, plus<T>(x, h / T(2), k2)),
               k4 = f<T>(I, plus<T>(x, h, k3));
    return {Vec3<T>(x.Pi + h / T(6) * (k1.Pi + T(2) * k2.Pi + T(2) * k3.Pi + k4.Pi)),
            Mat3<T>(x.O + h / T(6) * (k1.O + T(2) * k2.O + T(2) * k3.O + k4.O))};
  }
};

// 13. The midpoint rule with the gyroscopic term clamped to a fixed size: |dPi/dt| at most 2^10 (a
//     "max torque" setting). The cause named must be a cap of constant size (docs/CAUSES.md).
struct Clamped {
  static constexpr const char* name = "clamped";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static Vec3<T> clamp(const Vec3<T>& F) {
    const T limit(1024);
    return size(F) > limit ? Vec3<T>(F * (limit / size(F))) : F;
  }
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return clamp<T>(euler_3_8<T>(I, P)); });
  }
};

// 14. The same clamp behind a "nothing to do" guard for h below 2^-60: the failures it makes lie at
//     steps far above the guard, so the cause named must be the cap, and the guard said not to be it.
struct GuardedClamp {
  static constexpr const char* name = "guarded_clamp";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    using std::abs;
    if (abs(h) < T(1) / T(1152921504606846976.0)) return x;  // 2^-60
    return Clamped::rigid_body_step<T>(I, x, h);
  }
};

// 15. The classical RK4 claiming the Casimir (false: its drift is a truncation error, ~h^5 a step).
//     It is covariant in the units: scaled by lambda with h by 1/lambda, the relative drift is the
//     same, so "depends on the units" would be a wrong cause.
struct RK4Casimir {
  static constexpr const char* name = "rk4_casimir";
  static constexpr gm::student::Claims claims{.order = 4, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h);
};

template <class T>
RigidBodyState<T> RK4Casimir::rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  return RK4::rigid_body_step<T>(I, x, h);
}

// 16. Backward Euler computed in single precision, claiming bounded energy (false: it loses energy,
//     then sits on a plateau where float round-off moves H both ways): the loss must still be called
//     a loss, however many steps of the plateau's noise rise.
struct FloatBackwardEuler {
  static constexpr const char* name = "float_backward_euler";
  static constexpr gm::student::Claims claims{.bounded_energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const auto f = [](const T& v) { return static_cast<float>(SinglePrecision::to_double_value(v)); };
    const Vec3<float> If(f(I(0)), f(I(1)), f(I(2)));
    RigidBodyState<float> xf;
    for (int i = 0; i < 3; ++i) xf.Pi(i) = f(x.Pi(i));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) xf.O(i, j) = f(x.O(i, j));
    const RigidBodyState<float> yf = BackwardEuler::rigid_body_step<float>(If, xf, f(h));
    RigidBodyState<T> y;
    for (int i = 0; i < 3; ++i) y.Pi(i) = T(double(yf.Pi(i)));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y.O(i, j) = T(double(yf.O(i, j)));
    return y;
  }
};

// 17. The midpoint rule behind an engine's small-angle shortcut: an attitude within 1e-3 rad of the
//     identity is taken for the identity itself before the step (exact at the identity, where the
//     special states sit, wrong next to it). Order 2 and equivariance claimed, both false there: the
//     attitude regimes near the identity must catch it, name their regime, and name the attitude.
struct SmallAngleSnap {
  static constexpr const char* name = "small_angle_snap";
  static constexpr gm::student::Claims claims{.order = 2, .equivariant = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Mat3<T> A = x.O - x.O.transpose();
    const T sin2 = (A(2, 1) * A(2, 1) + A(0, 2) * A(0, 2) + A(1, 0) * A(1, 0)) / T(4);
    RigidBodyState<T> y = x;
    if (x.O.trace() > T(1) && sin2 < T(1) / T(1000000)) y.O = Mat3<T>::Identity();  // angle < 1e-3 rad
    return midpoint<T>(I, y, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

// 18. An engine's step in its own form (a quaternion (w, x, y, z) and the body's Omega) whose angular
//     damping has its sign flipped: Omega is multiplied by 1 + h c |Omega| where 1 / (1 + h c |Omega|)
//     was meant. dOmega/dt ~ c |Omega| Omega blows up in finite time (t ~ 1 / (c |Omega0|)); past
//     |Omega| ~ 1e154, |Omega|^2 overflows and the exact turn's cos(inf) makes the quaternion NaN.
//     Bounded energy claimed (false): the run must say the energy grew until H is not finite, never
//     "your step raised", since the step returned what it computed.
struct FlippedDamping {
  static constexpr const char* name = "flipped_damping";
  static constexpr const char* state = "quaternion_wxyz Omega";
  static constexpr const char* precision = "double";
  static constexpr const char* precision_reason = "written as an engine is, in double";
  static constexpr gm::student::Claims claims{.bounded_energy = true};
  static EngineState<double> rigid_body_step(const Vec3<double>& I, const EngineState<double>& x, const double& h) {
    const double c = 0.01;
    Vec3<double> W = x.Omega + h * Vec3<double>(I.cwiseProduct(x.Omega).cross(x.Omega)).cwiseQuotient(I);  // (2.2)
    W *= 1 + h * c * std::sqrt(W.dot(W));  // the flipped damping: "/=" was meant
    const double angle = h * std::sqrt(W.dot(W));
    const Vec3<double> axis = angle > 0 ? Vec3<double>(W / std::sqrt(W.dot(W))) : Vec3<double>::Zero();
    const Vec4<double> turn(std::cos(angle / 2), std::sin(angle / 2) * axis(0), std::sin(angle / 2) * axis(1),
                            std::sin(angle / 2) * axis(2));
    const Vec4<double>& q = x.q;
    EngineState<double> y = x;
    y.q = Vec4<double>(q(0) * turn(0) - q(1) * turn(1) - q(2) * turn(2) - q(3) * turn(3),
                       q(0) * turn(1) + q(1) * turn(0) + q(2) * turn(3) - q(3) * turn(2),
                       q(0) * turn(2) - q(1) * turn(3) + q(2) * turn(0) + q(3) * turn(1),
                       q(0) * turn(3) + q(1) * turn(2) - q(2) * turn(1) + q(3) * turn(0));  // q turn, on the body's side
    y.Omega = W;
    return y;
  }
};

// 19. The midpoint rule kept in a quaternion (w, x, y, z) and Pi, whose attitude goes through a
//     rotation vector "the shorter way round": angle 2 atan2(|v|, |w|) about v / |v|, taking |w|
//     without turning the axis. Exact for every q with w >= 0 (the half of the quaternions a
//     conversion from a matrix returns), wrong for the other half: near the identity given as -q,
//     the body is turned the other way. Order 2 and equivariance claimed, both false there: the
//     sign regime of the attitude draws must catch it and name the sign.
struct ShorterWayRound {
  static constexpr const char* name = "shorter_way_round";
  static constexpr const char* state = "quaternion_wxyz Pi";
  static constexpr gm::student::Claims claims{.order = 2, .equivariant = true};
  template <class T>
  static EngineState<T> rigid_body_step(const Vec3<T>& I, const EngineState<T>& x, const T& h) {
    using std::abs, std::atan2, std::cos, std::sin, std::sqrt;
    const Vec3<T> v(x.q(1), x.q(2), x.q(3));
    const T s = sqrt(v.dot(v));
    const T angle = T(2) * atan2(s, abs(x.q(0)));  // the defect: |w|, the axis v / |v| kept
    const Vec3<T> axis = s > T(0) ? Vec3<T>(v / s) : Vec3<T>::Zero();
    const Vec4<T> q(cos(angle / T(2)), sin(angle / T(2)) * axis(0), sin(angle / T(2)) * axis(1),
                    sin(angle / T(2)) * axis(2));  // exp of the rotation vector angle * axis
    const RigidBodyState<T> y =
        midpoint<T>(I, RigidBodyState<T>{x.Pi, Mat3<T>::Identity()}, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
    const Vec3<T> a = h * ((x.Pi + y.Pi) / T(2)).cwiseQuotient(I) / T(2);  // cay(h hat(W)) is the turn (1, h W / 2)
    Vec4<T> turned(q(0) - q(1) * a(0) - q(2) * a(1) - q(3) * a(2), q(0) * a(0) + q(1) + q(2) * a(2) - q(3) * a(1),
                   q(0) * a(1) - q(1) * a(2) + q(2) + q(3) * a(0), q(0) * a(2) + q(1) * a(1) - q(2) * a(0) + q(3));
    EngineState<T> out = x;
    out.q = turned / sqrt(turned.dot(turned));
    out.Pi = y.Pi;
    return out;
  }
};

// The midpoint rule itself, every claim true: the positive control.
struct Midpoint {
  static constexpr const char* name = "midpoint";
  static constexpr gm::student::Claims claims{.order = 2, .symmetric = true, .casimir = true, .energy = true,
                                              .orthogonality = true, .noether = true, .equivariant = true,
                                              .bounded_energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return euler_3_8<T>(I, P); });
  }
};

}  // namespace cases
