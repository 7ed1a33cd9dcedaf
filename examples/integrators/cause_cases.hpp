// Integrators with one known defect each, whose failure has one cause that an experiment can
// confirm, or none: each must get that one confirmed cause, or "cause not identified", and never a
// second cause after a confirmed one, nor a cause the same run refutes (docs/CAUSES.md).
// tests/cause_verdicts.py checks each, confirming the cause by a computation of its own.
//
//   ./geomech check examples/integrators/cause_cases.cpp --integrator small_angle_series
#pragma once

#include "verdict_cases.hpp"

#include <cmath>

namespace cause_cases {

using namespace gm;

template <class T>
RigidBodyState<T> true_midpoint(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  return cases::midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return cases::euler_3_8<T>(I, P); });
}

// The rotation angle of O (atan2 of its skew and symmetric parts).
template <class T>
T angle_of(const Mat3<T>& O) {
  using std::atan2;
  using std::sqrt;
  const Mat3<T> A = O - O.transpose();
  const T s = sqrt(A(2, 1) * A(2, 1) + A(0, 2) * A(0, 2) + A(1, 0) * A(1, 0)) / T(2);
  return atan2(s, (O.trace() - T(1)) / T(2));
}

// 1. The midpoint rule whose attitude update switches to a truncated series, O (Id + h Omega_hat),
//    when the attitude's own rotation angle is below 1e-3 rad (an engine's small-angle shortcut,
//    taken on the wrong angle). Order 2 claimed: false near the identity, where relative equilibria
//    drawn with O = Id sit. The cause: a branch on the attitude's angle, never the special state.
struct SmallAngleSeries {
  static constexpr const char* name = "small_angle_series";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    RigidBodyState<T> y = true_midpoint<T>(I, x, h);
    if (angle_of<T>(x.O) < T(1) / T(1000)) {
      const Vec3<T> W = ((x.Pi + y.Pi) / T(2)).cwiseQuotient(I);
      y.O = x.O * (Mat3<T>::Identity() + h * cases::hat<T>(W));
    }
    return y;
  }
};

// 2. The midpoint rule that returns its input for h <= 0 (as engines that refuse negative steps do),
//    claiming order 2 and symmetry: the symmetry is false, and the failure says the step does
//    nothing for h < 0.
struct IgnoresNegative {
  static constexpr const char* name = "ignores_negative_h";
  static constexpr gm::student::Claims claims{.order = 2, .symmetric = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    if (!(h > T(0))) return x;
    return true_midpoint<T>(I, x, h);
  }
};

// 3. The midpoint rule behind a silent speed cap: before the step the momentum is shrunk so that one
//    step turns the body by at most pi/4 (|Omega| h <= pi/4), as engines limit the angular motion of
//    a step; the cap changes the body's own state, so the momentum is lost for good. Order 2 and the
//    Casimir claimed: the Casimir is false for steps that would turn it further.
struct SpeedCap {
  static constexpr const char* name = "speed_cap";
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    using std::abs;
    using std::sqrt;
    RigidBodyState<T> capped = x;
    const Vec3<T> W = x.Pi.cwiseQuotient(I);
    const T turn = abs(h) * sqrt(W.squaredNorm());
    const T limit = T(3.14159265358979323846264338327950288) / T(4);
    if (turn > limit) capped.Pi *= limit / turn;
    return true_midpoint<T>(I, capped, h);
  }
};

// 4. A step that raises for slow states (|Omega| < 2^-20: "a body at rest") and takes explicit Euler
//    elsewhere, claiming order 2: the order is a FALSE CLAIM (its checks ran and failed), whatever
//    the raise stopped.
struct RaisesSlowWrongElsewhere {
  static constexpr const char* name = "raises_slow_wrong_elsewhere";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    if (cases::size<T>(Vec3<T>(x.Pi.cwiseQuotient(I))) < T(1) / T(1 << 20))
      throw std::domain_error("a body at rest has no rotation to integrate");
    return cases::explicit_euler<T>(I, x, h);
  }
};

// 5. The midpoint rule without the gyroscopic term: Pi is held (dPi/dt = 0 where (3.8) is
//    Pi x Omega), O turned by Omega. Order 2 claimed: false; its cause is the field, never a wrong h,
//    never "cause not identified".
struct NoGyroscopic {
  static constexpr const char* name = "no_gyroscopic";
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Vec3<T> W = x.Pi.cwiseQuotient(I);
    return {x.Pi, Mat3<T>(x.O * cases::cayley<T>(h * cases::hat<T>(W)))};
  }
};

struct None {};

}  // namespace cause_cases
