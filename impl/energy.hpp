// Lagrangian, Legendre transform and Hamiltonian of the free rigid body.
#pragma once

#include "impl/so3.hpp"

namespace gm::ref {

// (2.5): l(Omega) = (1/2) I Omega . Omega = (1/2)(I1 Omega1^2 + I2 Omega2^2 + I3 Omega3^2).
template <class T>
T lagrangian_2_5(const Vec3<T>& I, const Vec3<T>& W) {
  return (I(0) * W(0) * W(0) + I(1) * W(1) * W(1) + I(2) * W(2) * W(2)) / T(2);
}

// (2.13): l = (1/2) <I Omega_hat, Omega_hat> with the trace pairing (2.15), where the inertia
// acts on skew matrices through the hat map: I Omega_hat := hat(I vee(Omega_hat)).
template <class T>
T lagrangian_2_13(const Vec3<T>& I, const Mat3<T>& Omega_hat) {
  const Mat3<T> I_Omega_hat = hat<T>(I.cwiseProduct(vee<T>(Omega_hat)));
  return pairing3<T>(I_Omega_hat, Omega_hat) / T(2);
}

// (3.1): Pi_i = I_i Omega_i = dl/dOmega_i (the fibre derivative, Definition 3.1).
template <class T>
Vec3<T> legendre_3_1(const Vec3<T>& I, const Vec3<T>& W) {
  return I.cwiseProduct(W);
}

// (3.5): Omega = dh/dPi = I^-1 Pi.
template <class T>
Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& P) {
  return P.cwiseQuotient(I);
}

// (3.3): h(Pi) = Pi . Omega - l(Omega), with Omega = I^-1 Pi.
template <class T>
T hamiltonian_3_3(const Vec3<T>& I, const Vec3<T>& P) {
  const Vec3<T> W = omega_3_5<T>(I, P);
  return P.dot(W) - lagrangian_2_5<T>(I, W);
}

// (3.4): h = (1/2) Pi . I^-1 Pi = Pi1^2/(2 I1) + Pi2^2/(2 I2) + Pi3^2/(2 I3).
template <class T>
T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& P) {
  return P(0) * P(0) / (T(2) * I(0)) + P(1) * P(1) / (T(2) * I(1)) + P(2) * P(2) / (T(2) * I(2));
}

// (2.21): h(Pi) = <Pi, Omega_hat> - l(Omega_hat), in matrix form, with
// Omega_hat = hat(I^-1 vee(Pi)) (the fibre derivative relation of the exercise).
template <class T>
T hamiltonian_2_21(const Vec3<T>& I, const Mat3<T>& Pi_hat) {
  const Mat3<T> Omega_hat = hat<T>(vee<T>(Pi_hat).cwiseQuotient(I));
  return pairing3<T>(Pi_hat, Omega_hat) - lagrangian_2_13<T>(I, Omega_hat);
}

// (2.27): c(Pi) = |Pi|^2 / 2, with which the Lie-Poisson bracket (3.6) is the Nambu bracket
// {c, f, h}; it Poisson-commutes with every function, a Casimir (section 3.3).
template <class T>
T casimir(const Vec3<T>& Pi) {
  return Pi.dot(Pi) / T(2);
}

}  // namespace gm::ref
