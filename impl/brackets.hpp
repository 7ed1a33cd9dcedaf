// Poisson brackets of the notes, each evaluated at a point from the gradients of its arguments.
#pragma once

#include "impl/so3.hpp"

namespace gm::ref {

// Lie-Poisson bracket, matrix form (2.23)/(3.10): {f, h}(Pi) = -<Pi, [df/dPi, dh/dPi]>,
// with Pi and the gradients as skew matrices and <,> the trace pairing (2.15).
template <class T>
T lie_poisson_2_23(const Mat3<T>& Pi_hat, const Mat3<T>& df_hat, const Mat3<T>& dh_hat) {
  return -pairing3<T>(Pi_hat, commutator(df_hat, dh_hat));
}

// Lie-Poisson bracket, R^3 form (3.6) (= (2.25)): {f, h}(Pi) = -Pi . (df/dPi x dh/dPi).
template <class T>
T lie_poisson_3_6(const Vec3<T>& Pi, const Vec3<T>& df, const Vec3<T>& dh) {
  return -Pi.dot(cross<T>(df, dh));
}

// Nambu R^3 bracket (3.13): {f, h} = -grad c . grad f x grad h, for any function c.
template <class T>
T nambu_3_13(const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) {
  return -dc.dot(cross<T>(df, dh));
}

// Nambu motion (3.14): dx/dt = {x, h} = grad c x grad h.
template <class T>
Vec3<T> nambu_motion_3_14(const Vec3<T>& dc, const Vec3<T>& dh) {
  return cross<T>(dc, dh);
}

// Canonical Poisson bracket on T*R^3 with {q_i, p_j} = delta_ij (section 3.5):
// {f, h} = df/dq . dh/dp - df/dp . dh/dq.
template <class T>
T canonical_bracket(const Vec3<T>& dfdq, const Vec3<T>& dfdp, const Vec3<T>& dhdq, const Vec3<T>& dhdp) {
  return dfdq.dot(dhdp) - dfdp.dot(dhdq);
}

// The system (3.16): dx1/dt = -a1 a3 x2 x3, dx2/dt = -a2 a3 x3 x1, dx3/dt = a1 a2 x1 x2.
template <class T>
Vec3<T> nambu_3_16(const Vec3<T>& a, const Vec3<T>& x) {
  return Vec3<T>(-a(0) * a(2) * x(1) * x(2), -a(1) * a(2) * x(2) * x(0), a(0) * a(1) * x(0) * x(1));
}

}  // namespace gm::ref
