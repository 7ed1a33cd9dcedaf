// Integrators computed in single precision, as the steps of most real-time engines are, whose true
// behaviour at float's precision is known by theory: the reference methods (explicit Euler, the
// midpoint rule, a splitting, RK4), judged at float's round-off, get the verdicts their exact
// arithmetic gives wherever truncation stands above that round-off; and four float defects stay
// found. tests/float_verdicts.py checks each, confirming the verdict by a computation of its own.
//
//   ./geomech check examples/integrators/float_cases.cpp --integrator float_midpoint
//
// Each step takes the state in the scalar it is driven in, rounds it to float, computes in float and
// returns the float result, as an engine's float build does behind a double interface. Each states
// `precision = "float"`, but one midpoint rule states nothing: the suite must detect that it computes
// in float and judge it the same way.
#pragma once

#include "verdict_cases.hpp"

#include <cmath>

namespace float_cases {

using namespace gm;

constexpr const char* kFloat = "computes every value in float (a 32-bit IEEE number), as an engine's float build does";

template <class T>
float f(const T& v) {
  return static_cast<float>(static_cast<double>(v));
}

template <class T>
RigidBodyState<float> to_float(const RigidBodyState<T>& x) {
  RigidBodyState<float> y;
  for (int i = 0; i < 3; ++i) y.Pi(i) = f(x.Pi(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) y.O(i, j) = f(x.O(i, j));
  return y;
}

template <class T>
RigidBodyState<T> from_float(const RigidBodyState<float>& y) {
  RigidBodyState<T> x;
  for (int i = 0; i < 3; ++i) x.Pi(i) = T(double(y.Pi(i)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) x.O(i, j) = T(double(y.O(i, j)));
  return x;
}

template <class T>
Vec3<float> to_float(const Vec3<T>& v) {
  return Vec3<float>(f(v(0)), f(v(1)), f(v(2)));
}

// `Step(I, x, h)` computed in float.
template <class T, class Step>
RigidBodyState<T> in_float(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h, Step&& step) {
  return from_float<T>(step(to_float(I), to_float(x), f(h)));
}

// Strang splitting of h = sum Pi_i^2 / (2 I_i) into three exact rotations (correct.hpp's
// Splitting): a Poisson map that keeps |Pi|^2 and O^T O, O Pi (Noether), with a bounded energy error.
template <class T>
Mat3<T> axis_rotation(int axis, const T& angle) {
  using std::cos;
  using std::sin;
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  Mat3<T> R = Mat3<T>::Identity();
  const T c = cos(angle), s = sin(angle);
  R(j, j) = c;
  R(j, k) = -s;
  R(k, j) = s;
  R(k, k) = c;
  return R;
}
template <class T>
void axis_flow(int axis, const Vec3<T>& I, RigidBodyState<T>& x, const T& t) {
  const T angle = t * x.Pi(axis) / I(axis);
  x.Pi = axis_rotation<T>(axis, -angle) * x.Pi;
  x.O = x.O * axis_rotation<T>(axis, angle);
}
template <class T>
RigidBodyState<T> splitting(const Vec3<T>& I, RigidBodyState<T> x, const T& h) {
  axis_flow<T>(0, I, x, h / T(2));
  axis_flow<T>(1, I, x, h / T(2));
  axis_flow<T>(2, I, x, h);
  axis_flow<T>(1, I, x, h / T(2));
  axis_flow<T>(0, I, x, h / T(2));
  return x;
}

template <class T>
RigidBodyState<T> true_midpoint(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  return cases::midpoint<T>(I, x, h, [&](const Vec3<T>& P) { return cases::euler_3_8<T>(I, P); });
}

// 1. Explicit Euler in float: order 1 (true); the Casimir and the energy grow (not claimed).
struct FloatExplicitEuler {
  static constexpr const char* name = "float_explicit_euler";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 1};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      return cases::explicit_euler<float>(If, xf, hf);
    });
  }
};

// 2. The implicit midpoint rule in float, with every claim the midpoint rule makes in exact arithmetic
//    (correct.hpp's Midpoint): order 2, symmetric, the Casimir, the energy, orthogonality, Noether,
//    equivariance, a bounded energy. Each holds at float's round-off.
struct FloatMidpoint {
  static constexpr const char* name = "float_midpoint";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 2,
                                              .symmetric = true,
                                              .casimir = true,
                                              .energy = true,
                                              .orthogonality = true,
                                              .noether = true,
                                              .equivariant = true,
                                              .bounded_energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      return true_midpoint<float>(If, xf, hf);
    });
  }
};

// 3. The same step stating no precision: detected to compute in float, and judged the same way.
struct FloatMidpointUnstated {
  static constexpr const char* name = "float_midpoint_unstated";
  static constexpr gm::student::Claims claims = FloatMidpoint::claims;
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return FloatMidpoint::rigid_body_step<T>(I, x, h);
  }
};

// 4. The splitting in float, with its claims: order 2, symmetric, the Casimir, orthogonality, a
//    Poisson map, Noether, equivariance, a bounded energy.
struct FloatSplitting {
  static constexpr const char* name = "float_splitting";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 2,
                                              .symmetric = true,
                                              .casimir = true,
                                              .orthogonality = true,
                                              .poisson = true,
                                              .noether = true,
                                              .equivariant = true,
                                              .bounded_energy = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      return splitting<float>(If, xf, hf);
    });
  }
};

// 5. Classical RK4 in float: order 4 (true, measured where its truncation error stands above
//    float's round-off); the Casimir and the energy are not kept (not claimed).
struct FloatRK4 {
  static constexpr const char* name = "float_rk4";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 4};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      return cases::RK4::rigid_body_step<float>(If, xf, hf);
    });
  }
};

// 6. The midpoint rule whose momentum is put back on its sphere |Pi| = |Pi0| after each step by a
//    factor rounded up, one unit of float's last place too large (a normalisation that leans one
//    way): |Pi|^2 gains about 2^-22 of itself at every step, whatever h, even where the step
//    changes nothing else. The Casimir claimed, a FALSE CLAIM named as systematic round-off with its
//    rate; the order claim verified (the drift is not a truncation error).
struct FloatRoundsUp {
  static constexpr const char* name = "float_rounds_up";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 2, .casimir = true};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      RigidBodyState<float> y = true_midpoint<float>(If, xf, hf);
      const float before = std::sqrt(xf.Pi.squaredNorm()), after = std::sqrt(y.Pi.squaredNorm());
      if (after > 0) y.Pi *= std::nextafter(before / after, 2.0f);  // the factor, rounded up once more
      return y;
    });
  }
};

// 7. An engine's float step without the gyroscopic term: the body's angular velocity is held
//    constant (dPi/dt = 0, where (3.8) is Pi x Omega), the attitude turned exactly by it. Order 1
//    claimed: false, it converges to another equation; the field named, in float as in double.
struct FloatNoGyroscopic {
  static constexpr const char* name = "float_no_gyroscopic";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 1};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      const Vec3<float> W = xf.Pi.cwiseQuotient(If);
      const Mat3<float> A = cases::hat<float>(Vec3<float>(hf * W));
      return RigidBodyState<float>{xf.Pi, Mat3<float>(xf.O * cases::cayley<float>(A))};
    });
  }
};

// 8. The midpoint rule in float that skips the attitude's update when the turn of one step is small,
//    |Omega h| <= 1e-6 rad (an engine's "nothing to integrate" shortcut): a slowly turning body never
//    turns. Order 2 claimed: false for slow motions, which a regime of small turns per step reaches
//    (a turn of 1e-6 rad per step is still eight units of float's last place in the attitude).
struct FloatRotationSkip {
  static constexpr const char* name = "float_rotation_skip";
  static constexpr const char* precision = "float";
  static constexpr const char* precision_reason = kFloat;
  static constexpr gm::student::Claims claims{.order = 2};
  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    return in_float(I, x, h, [](const Vec3<float>& If, const RigidBodyState<float>& xf, float hf) {
      RigidBodyState<float> y = true_midpoint<float>(If, xf, hf);
      const Vec3<float> turn = hf * Vec3<float>(((xf.Pi + y.Pi) / 2.0f).cwiseQuotient(If));
      if (std::sqrt(turn.squaredNorm()) <= 1e-6f) y.O = xf.O;  // "too small to integrate"
      return y;
    });
  }
};

struct None {};

}  // namespace float_cases
