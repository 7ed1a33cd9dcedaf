// Reconstruction of the attitude O(t) in SO(3) and the spatial quantities (Remarks 2.1, 2.2).
#pragma once

#include "impl/euler.hpp"

namespace gm::ref {

// (2.10): dO/dt = O Omega_hat (left-invariant: Omega_hat = O^-1 dO/dt).
template <class T>
Mat3<T> reconstruction_2_10(const Mat3<T>& O, const Vec3<T>& Omega) {
  return O * hat<T>(Omega);
}

// The rigid body with its attitude, (2.20): dPi/dt = Pi x Omega, dO/dt = O Omega_hat,
// Omega = I^-1 Pi. Returns (dPi/dt, dO/dt).
template <class T>
std::pair<Vec3<T>, Mat3<T>> rigid_body_with_attitude(const Vec3<T>& I, const Vec3<T>& Pi, const Mat3<T>& O) {
  const Vec3<T> W = Pi.cwiseQuotient(I);
  return {cross<T>(Pi, W), reconstruction_2_10<T>(O, W)};
}

// Spatial angular momentum, Theorem 2.2: pi = Ad*_{O^-1} Pi, i.e. pi_hat = O Pi_hat O^-1,
// i.e. pi = O Pi. (The explicit formula printed in (2.30), O^-1 Pi O, is inverted: see the
// erratum sec2.noether-2.30 in spec/catalogue.json.)
template <class T>
Vec3<T> spatial_momentum(const Mat3<T>& O, const Vec3<T>& Pi) {
  return O * Pi;
}

// Remark 2.1: I_space = O I O^-1 (O orthogonal, so O^-1 = O^T).
template <class T>
Mat3<T> inertia_space(const Mat3<T>& O, const Vec3<T>& I) {
  return O * I.asDiagonal() * O.transpose();
}

// Remark 2.1: l_space(omega) = (1/2) omega . I_space omega.
template <class T>
T lagrangian_space(const Mat3<T>& I_space, const Vec3<T>& omega) {
  return omega.dot(I_space * omega) / T(2);
}

}  // namespace gm::ref
