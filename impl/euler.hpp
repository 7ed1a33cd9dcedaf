// Euler's equations for the free rigid body, in each form the notes write them.
// I = (I1, I2, I3) are the principal moments of inertia, Omega the body angular velocity,
// Pi = I Omega the body angular momentum (3.1).
#pragma once

#include "impl/so3.hpp"

namespace gm::ref {

// (2.1): I1 dOmega1/dt = (I2 - I3) Omega2 Omega3, and cyclically.
template <class T>
Vec3<T> euler_2_1(const Vec3<T>& I, const Vec3<T>& W) {
  return Vec3<T>((I(1) - I(2)) * W(1) * W(2) / I(0), (I(2) - I(0)) * W(2) * W(0) / I(1),
                 (I(0) - I(1)) * W(0) * W(1) / I(2));
}

// (2.2) (= (2.9)): I dOmega/dt = I Omega x Omega.
template <class T>
Vec3<T> euler_2_2(const Vec3<T>& I, const Vec3<T>& W) {
  const Vec3<T> IW = I.cwiseProduct(W);
  return cross<T>(IW, W).cwiseQuotient(I);
}

// (3.7): dPi1/dt = (1/I3 - 1/I2) Pi2 Pi3, and cyclically.
template <class T>
Vec3<T> euler_3_7(const Vec3<T>& I, const Vec3<T>& P) {
  return Vec3<T>((T(1) / I(2) - T(1) / I(1)) * P(1) * P(2), (T(1) / I(0) - T(1) / I(2)) * P(2) * P(0),
                 (T(1) / I(1) - T(1) / I(0)) * P(0) * P(1));
}

// (3.8): dPi/dt = Pi x I^-1 Pi.
template <class T>
Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& P) {
  return cross<T>(P, P.cwiseQuotient(I));
}

// (2.12) / third equation of (2.20): dPi/dt = -[Omega_hat, Pi] for the skew matrix Pi = hat(Pi),
// with Omega_hat = hat(I^-1 vee(Pi)) from the fibre derivative (first equation of (2.20)).
template <class T>
Mat3<T> euler_matrix_2_12(const Vec3<T>& I, const Mat3<T>& Pi_hat) {
  const Mat3<T> Omega_hat = hat<T>(vee<T>(Pi_hat).cwiseQuotient(I));
  return (-commutator(Omega_hat, Pi_hat)).eval();
}

}  // namespace gm::ref
