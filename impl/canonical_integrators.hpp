// Integrators in the canonical variables of the Clebsch formulations:
//   (3.21) on T*R^3, z = (Q, P), Pi = P x Q, Omega = I^-1 Pi:
//       dQ/dt = -Omega x Q = dH/dP,   dP/dt = -Omega x P = -dH/dQ,   H(Q, P) = h(P x Q) (3.4);
//   (3.23) on T*R^{n x n}, z = (Q, P), M = Q^T P - P^T Q (the corrected momentum of
//       mm.manakov-clebsch), A Omega + Omega A = M:
//       dQ/dt = Q Omega = dH/dP,      dP/dt = P Omega = -dH/dQ,      H(Q, P) = -tr(Omega M) / 4.
// (Both are canonical Hamiltonian systems: dH = <Omega, dPi> gives dH/dP = Q x Omega and
// dH/dQ = Omega x P for (3.21); dH = -tr(Omega dM)/2 gives dH/dP = Q Omega, dH/dQ = -P Omega for
// (3.23), in the Frobenius pairing.) H is of degree 4 in z, so a method that keeps quadratic
// invariants does not keep H. Claims: reference_integrators.cpp.
#pragma once

#include "core/subject.hpp"
#include "impl/integrators.hpp"
#include "impl/manakov.hpp"
#include "impl/momentum_map.hpp"

namespace gm::ref {

// The two systems on one footing: a state is the matrix Z = [Q; P] (6 x 1 for (3.21), 2n x n for
// (3.23)), Q its top half and P its bottom half, so that the implicit solve and RK4 are written
// once (and the canonical two-form is <dQ, dP'> - <dP, dQ'> on both).
template <class T>
MatX<T> stack(const Vec3Pair<T>& z) {
  MatX<T> Z(6, 1);
  Z.col(0) << z.first, z.second;
  return Z;
}
template <class T>
MatX<T> stack(const MatXPair<T>& z) {
  const auto n = z.first.rows();
  MatX<T> Z(2 * n, z.first.cols());
  Z.topRows(n) = z.first;
  Z.bottomRows(n) = z.second;
  return Z;
}
template <class T>
Vec3Pair<T> unstack3(const MatX<T>& Z) {
  return {Vec3<T>(Z.col(0).head(3)), Vec3<T>(Z.col(0).tail(3))};
}
template <class T>
MatXPair<T> unstack_n(const MatX<T>& Z) {
  const auto n = Z.rows() / 2;
  return {MatX<T>(Z.topRows(n)), MatX<T>(Z.bottomRows(n))};
}

// The vector fields (3.21) and (3.23) on the stacked state.
template <class T>
MatX<T> clebsch_field(const Vec3<T>& I, const MatX<T>& Z) {
  const auto [dQ, dP] = clebsch_3_21<T>(I, Vec3<T>(Z.col(0).head(3)), Vec3<T>(Z.col(0).tail(3)));
  return stack<T>(Vec3Pair<T>{dQ, dP});
}
template <class T>
MatX<T> manakov_clebsch_field(const MatX<T>& A, const MatX<T>& Z) {
  const auto [Q, P] = unstack_n<T>(Z);
  const auto [dQ, dP] = manakov_clebsch_3_23<T>(A, Q, P);
  return stack<T>(MatXPair<T>{dQ, dP});
}

// Implicit midpoint rule z_{n+1} = z_n + h f((z_n + z_{n+1}) / 2): the midpoint Z is the fixed
// point of Z = z_n + (h/2) f(Z), iterated to round-off (integrators.hpp, fixed_point). It is a
// symplectic map for every canonical Hamiltonian system (its Jacobian is the Cayley transform of
// (h/2) J Hess H at the midpoint, conjugated), symmetric, of order 2; it keeps quadratic
// invariants, among them the momentum maps Pi = P x Q and M = Q^T P - P^T Q of the symmetries
// (3.21) and (3.23) are built on, but not the quartic H.
template <class T, class Field>
MatX<T> canonical_midpoint(const MatX<T>& Z0, const T& h, const Field& f, const char* who) {
  const T half = h / T(2);
  const MatX<T> mid =
      fixed_point<T>((Z0 + half * f(Z0)).eval(), [&](const MatX<T>& Z) { return (Z0 + half * f(Z)).eval(); }, who);
  return (T(2) * mid - Z0).eval();
}

// Classical RK4: order 4, not symplectic.
template <class T, class Field>
MatX<T> canonical_rk4(const MatX<T>& Z, const T& h, const Field& f) {
  const T half = h / T(2);
  const MatX<T> k1 = f(Z);
  const MatX<T> k2 = f((Z + half * k1).eval());
  const MatX<T> k3 = f((Z + half * k2).eval());
  const MatX<T> k4 = f((Z + h * k3).eval());
  return (Z + (h / T(6)) * (k1 + T(2) * k2 + T(2) * k3 + k4)).eval();
}

template <class T>
Vec3Pair<T> clebsch_midpoint_step(const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
  return unstack3<T>(canonical_midpoint<T>(
      stack<T>(z), h, [&](const MatX<T>& Z) { return clebsch_field<T>(I, Z); }, "Clebsch (3.21) implicit midpoint"));
}
template <class T>
MatXPair<T> manakov_clebsch_midpoint_step(const MatX<T>& A, const MatXPair<T>& z, const T& h) {
  return unstack_n<T>(canonical_midpoint<T>(
      stack<T>(z), h, [&](const MatX<T>& Z) { return manakov_clebsch_field<T>(A, Z); },
      "Clebsch (3.23) implicit midpoint"));
}
template <class T>
Vec3Pair<T> clebsch_rk4_step(const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
  return unstack3<T>(canonical_rk4<T>(stack<T>(z), h, [&](const MatX<T>& Z) { return clebsch_field<T>(I, Z); }));
}
template <class T>
MatXPair<T> manakov_clebsch_rk4_step(const MatX<T>& A, const MatXPair<T>& z, const T& h) {
  return unstack_n<T>(
      canonical_rk4<T>(stack<T>(z), h, [&](const MatX<T>& Z) { return manakov_clebsch_field<T>(A, Z); }));
}

// Explicit symplectic splitting of (3.21). H = sum_i H_i with H_i = Pi_i^2 / (2 I_i), and the
// flow of H_i is the cotangent lift of a rotation: Pi_i is constant along it (it is the momentum
// map component of rotations about e_i, mm.hamiltonian-action), so Omega = (Pi_i / I_i) e_i and
// Q, P both turn about e_i by the angle -t Pi_i / I_i. Each sub-flow is the exact flow of a
// Hamiltonian, hence symplectic; the Strang composition
//     Phi_1(h/2) Phi_2(h/2) Phi_3(h) Phi_2(h/2) Phi_1(h/2)
// is symplectic, symmetric, of order 2, and keeps Pi = P x Q's length (each factor rotates Pi) but
// not H. (Its image under z -> P x Q is lie_poisson_splitting_step.)
template <class T>
Vec3Pair<T> clebsch_splitting_step(const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
  Vec3<T> Q = z.first, P = z.second;
  auto flow = [&](int i, const T& t) {
    const T Pi_i = cross<T>(P, Q)(i);
    const Mat3<T> R = axis_rotation<T>(i, T(-t * Pi_i / I(i)));
    Q = R * Q;
    P = R * P;
  };
  const T half = h / T(2);
  flow(0, half);
  flow(1, half);
  flow(2, h);
  flow(1, half);
  flow(0, half);
  return {Q, P};
}

}  // namespace gm::ref
