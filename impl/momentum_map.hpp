// Clebsch variables and the cotangent-lift momentum map (section 3.5 and the closing part).
#pragma once

#include "impl/energy.hpp"

#include <utility>

namespace gm::ref {

// Cotangent-lift momentum map for SO(3) acting on R^3: J(q, p) = p x q.
template <class T>
Vec3<T> momentum_map(const Vec3<T>& q, const Vec3<T>& p) {
  return cross<T>(p, q);
}

// Clebsch equations (3.21): Pi = P x Q, dQ/dt = -Omega x Q, dP/dt = -Omega x P,
// with Omega = I^-1 Pi. Returns (dQ/dt, dP/dt).
template <class T>
std::pair<Vec3<T>, Vec3<T>> clebsch_3_21(const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) {
  const Vec3<T> W = omega_3_5<T>(I, cross<T>(P, Q));
  return {-cross<T>(W, Q), -cross<T>(W, P)};
}

}  // namespace gm::ref
