// Integrators of the kind students write, for the rigid body with its attitude (Pi, O) of (2.20),
//     dPi/dt = Pi x Omega,   dO/dt = O hat(Omega),   Omega = I^-1 Pi,
// and for Manakov's SO(n) rigid body with attitude (M, O) of (2.34)/(2.36),
//     dM/dt = [M, Omega],    dO/dt = O Omega,        A Omega + Omega A = M.
// Each is one step x_n -> x_{n+1} of size h (h may be negative). Their claims (order, symmetry,
// preserved invariants, Poisson map) are stated in reference_integrators.cpp and verified by the
// integrator-scoped properties (properties/integrators/integrator_claims.cpp), as anyone's would be.
#pragma once

#include "core/subject.hpp"
#include "impl/manakov.hpp"
#include "impl/so3.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>

namespace gm::ref {

// ---------------------------------------------------------------------------------------------
// The rigid body with attitude.

template <class T>
RigidBodyState<T> rigid_body_field(const Vec3<T>& I, const RigidBodyState<T>& x) {
  const Vec3<T> W = x.Pi.cwiseQuotient(I);
  return {cross<T>(x.Pi, W), (x.O * hat<T>(W)).eval()};
}

// Classical fourth-order Runge-Kutta on (Pi, O): order 4, no invariant is kept exactly (the
// control that drifts).
template <class T>
RigidBodyState<T> rk4_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  auto add = [](const RigidBodyState<T>& a, const RigidBodyState<T>& d, const T& c) {
    return RigidBodyState<T>{(a.Pi + c * d.Pi).eval(), (a.O + c * d.O).eval()};
  };
  const T half = h / T(2);
  const auto k1 = rigid_body_field<T>(I, x);
  const auto k2 = rigid_body_field<T>(I, add(x, k1, half));
  const auto k3 = rigid_body_field<T>(I, add(x, k2, half));
  const auto k4 = rigid_body_field<T>(I, add(x, k3, h));
  const T w = h / T(6);
  return {(x.Pi + w * (k1.Pi + T(2) * k2.Pi + T(2) * k3.Pi + k4.Pi)).eval(),
          (x.O + w * (k1.O + T(2) * k2.O + T(2) * k3.O + k4.O)).eval()};
}

// Cayley transform cay(w) = (Id - hat(w))^-1 (Id + hat(w)) of a vector, in closed form:
// (Id - hat(w))^-1 = (Id + hat(w) + w w^T) / (1 + |w|^2). Orthogonal with determinant 1.
template <class T>
Mat3<T> cayley3(const Vec3<T>& w) {
  const Mat3<T> W = hat<T>(w);
  const Mat3<T> inv = (Mat3<T>::Identity() + W + w * w.transpose()) / (T(1) + w.squaredNorm());
  return (inv * (Mat3<T>::Identity() + W)).eval();
}

// Implicit midpoint rule on (Pi, O):
//     x_{n+1} = x_n + h f((x_n + x_{n+1}) / 2).
// The Pi-part is solved for the midpoint P = (Pi_n + Pi_{n+1}) / 2 by Newton's method on
//     g(P) = P - Pi_n - (h/2) P x I^-1 P = 0,   Dg = Id - (h/2) (hat(P) I^-1 - hat(I^-1 P)),
// iterated until the correction is at round-off (or stops decreasing); the O-part is then linear in
// O_{n+1} and its solution is O_{n+1} = O_n cay((h/2) Omega_mid). The rule preserves every
// quadratic invariant of the system: |Pi|^2, h, O^T O and the spatial momentum O Pi.
template <class T>
RigidBodyState<T> implicit_midpoint_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  const T half = h / T(2);
  Vec3<T> P = x.Pi + half * cross<T>(x.Pi, x.Pi.cwiseQuotient(I));  // explicit half step
  T scale(0);
  for (int i = 0; i < 3; ++i) scale = std::max(scale, abs_value(x.Pi(i)));
  T last_correction(-1);
  for (int iter = 0; iter < 60; ++iter) {
    const Vec3<T> W = P.cwiseQuotient(I);
    const Vec3<T> g = P - x.Pi - half * cross<T>(P, W);
    const Mat3<T> Dg = Mat3<T>::Identity() - half * (hat<T>(P) * Vec3<T>(I.cwiseInverse()).asDiagonal() - hat<T>(W));
    const Vec3<T> delta = Dg.partialPivLu().solve(g);
    P -= delta;
    T c(0);
    for (int i = 0; i < 3; ++i) c = std::max(c, abs_value(delta(i)));
    if (c <= T(2) * eps<T>() * scale) break;
    if (last_correction >= T(0) && c >= last_correction && c <= T(64) * eps<T>() * scale) break;  // round-off floor
    last_correction = c;
  }
  const Vec3<T> Wmid = P.cwiseQuotient(I);
  return {(T(2) * P - x.Pi).eval(), (x.O * cayley3<T>((half * Wmid).eval())).eval()};
}

// Rotation exp(theta hat(e_i)) about the i-th axis.
template <class T>
Mat3<T> axis_rotation(int i, const T& theta) {
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta);
  Mat3<T> R = Mat3<T>::Identity();
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  R(j, j) = c;
  R(j, k) = -s;
  R(k, j) = s;
  R(k, k) = c;
  return R;
}

// The exact flow, for time t, of h_i = Pi_i^2 / (2 I_i) (3.4) on (Pi, O): Pi_i and hence
// omega = Pi_i / I_i stay constant, dPi/dt = Pi x omega e_i rotates Pi about e_i by -omega t, and
// dO/dt = O hat(omega e_i) gives O exp(omega t hat(e_i)). (O Pi is unchanged.)
template <class T>
void axis_flow(const Vec3<T>& I, int i, const T& t, RigidBodyState<T>& x) {
  const T theta = t * x.Pi(i) / I(i);
  x.Pi = axis_rotation<T>(i, T(-theta)) * x.Pi;
  x.O = x.O * axis_rotation<T>(i, theta);
}

// Explicit Lie-Poisson splitting: the Strang composition of the exact flows of h1, h2, h3,
//     Phi_1(h/2) Phi_2(h/2) Phi_3(h) Phi_2(h/2) Phi_1(h/2).
// Each sub-flow is a rotation, so |Pi|^2, O^T O and O Pi are kept to round-off; each is the exact
// flow of a Hamiltonian for the Lie-Poisson bracket (3.6), so the step is a Poisson map; the
// composition is symmetric, hence of order 2; the energy h is not kept (error O(h^2)).
template <class T>
RigidBodyState<T> lie_poisson_splitting_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
  RigidBodyState<T> y = x;
  const T half = h / T(2);
  axis_flow<T>(I, 0, half, y);
  axis_flow<T>(I, 1, half, y);
  axis_flow<T>(I, 2, h, y);
  axis_flow<T>(I, 1, half, y);
  axis_flow<T>(I, 0, half, y);
  return y;
}

// The same splitting kept as an engine keeps its state (core/state_form.hpp, "quaternion_wxyz pi"):
// the attitude a unit quaternion q = (w, x, y, z) and the spatial momentum pi = O Pi (2.30), which
// no sub-flow changes (Noether, Theorem 2.2). The flow of h_i turns O into O exp(theta hat(e_i)),
// i.e. q into q (cos(theta/2), sin(theta/2) e_i) (Hamilton's product, the rotation on the body's side),
// with theta = t Pi_i / I_i and Pi_i = (O^T pi)_i, read from q. The reference keeps this integrator
// in that form so that every integrator property also runs through the suite's conversions
// (core/declared_step.hpp) and the quaternion's own claim (unit_quaternion) has a subject that makes it.
template <class T>
Vec4<T> quaternion_product(const Vec4<T>& a, const Vec4<T>& b) {
  return Vec4<T>(
      a(0) * b(0) - a(1) * b(1) - a(2) * b(2) - a(3) * b(3), a(0) * b(1) + a(1) * b(0) + a(2) * b(3) - a(3) * b(2),
      a(0) * b(2) - a(1) * b(3) + a(2) * b(0) + a(3) * b(1), a(0) * b(3) + a(1) * b(2) - a(2) * b(1) + a(3) * b(0));
}

template <class T>
void axis_flow_quaternion(const Vec3<T>& I, int i, const T& t, const Vec3<T>& pi, Vec4<T>& q) {
  using std::cos;
  using std::sin;
  const Mat3<T> O = state_form::rotation_of<T>(q);
  const T theta = t * O.col(i).dot(pi) / I(i);
  Vec4<T> turn(cos(T(theta / T(2))), T(0), T(0), T(0));
  turn(1 + i) = sin(T(theta / T(2)));
  q = quaternion_product<T>(q, turn);
}

template <class T>
EngineState<T> lie_poisson_splitting_quaternion_step(const Vec3<T>& I, const EngineState<T>& x, const T& h) {
  EngineState<T> y = x;
  const T half = h / T(2);
  axis_flow_quaternion<T>(I, 0, half, x.pi, y.q);
  axis_flow_quaternion<T>(I, 1, half, x.pi, y.q);
  axis_flow_quaternion<T>(I, 2, h, x.pi, y.q);
  axis_flow_quaternion<T>(I, 1, half, x.pi, y.q);
  axis_flow_quaternion<T>(I, 0, half, x.pi, y.q);
  return y;
}

// ---------------------------------------------------------------------------------------------
// Manakov's rigid body on SO(n) with attitude.

template <class T>
ManakovState<T> manakov_field(const MatX<T>& A, const ManakovState<T>& x) {
  const MatX<T> W = manakov_Omega<T>(A, x.M);
  return {commutator(x.M, W), (x.O * W).eval()};
}

template <class T>
ManakovState<T> manakov_rk4_step(const MatX<T>& A, const ManakovState<T>& x, const T& h) {
  auto add = [](const ManakovState<T>& a, const ManakovState<T>& d, const T& c) {
    return ManakovState<T>{(a.M + c * d.M).eval(), (a.O + c * d.O).eval()};
  };
  const T half = h / T(2);
  const auto k1 = manakov_field<T>(A, x);
  const auto k2 = manakov_field<T>(A, add(x, k1, half));
  const auto k3 = manakov_field<T>(A, add(x, k2, half));
  const auto k4 = manakov_field<T>(A, add(x, k3, h));
  const T w = h / T(6);
  return {(x.M + w * (k1.M + T(2) * k2.M + T(2) * k3.M + k4.M)).eval(),
          (x.O + w * (k1.O + T(2) * k2.O + T(2) * k3.O + k4.O)).eval()};
}

// Cayley transform (Id - S/2)^-1 (Id + S/2) of a skew matrix S: orthogonal, det 1.
template <class T>
MatX<T> cayley_half(const MatX<T>& S) {
  const MatX<T> Id = MatX<T>::Identity(S.rows(), S.cols());
  return (Id - S / T(2)).partialPivLu().solve(Id + S / T(2));
}

// Fixed-point iteration x = F(x) to round-off: stops when the change is at most 2 eps |x|, or when
// it stops decreasing once within 64 eps |x| (the round-off floor). Throws when it diverges.
template <class T, class F>
MatX<T> fixed_point(const MatX<T>& start, const F& F_, const char* who) {
  MatX<T> cur = start;
  T last(-1);
  for (int iter = 0; iter < 400; ++iter) {
    MatX<T> next = F_(cur);
    // Relative to the iterate's size: an absolute floor (max(1, |M|)) stops at once for a slowly
    // turning body (|M| << 1), leaving one iteration: not symmetric, invariants not kept.
    const T change = max_abs((next - cur).eval());
    const T size = max_abs(next);
    cur = std::move(next);
    if (change <= T(2) * eps<T>() * size) return cur;
    if (last >= T(0) && change >= last && change <= T(64) * eps<T>() * size) return cur;
    if (last >= T(0) && change > T(2) * last && iter > 8)
      throw std::domain_error(std::string(who) + ": fixed-point iteration diverges (step too large)");
    last = change;
  }
  throw std::domain_error(std::string(who) + ": fixed-point iteration did not converge");
}

// Implicit midpoint rule on (M, O): M_mid = M_n + (h/2) [M_mid, Omega(M_mid)] by fixed-point
// iteration (a contraction for h |Omega| small), M_{n+1} = 2 M_mid - M_n, and
// O_{n+1} = O_n cay(h Omega_mid). Preserves the quadratic invariants tr(M^2), the energy
// -tr(Omega M)/4, O^T O and O M O^T; not the higher invariants tr(M^4), ... (n >= 4).
template <class T>
ManakovState<T> manakov_implicit_midpoint_step(const MatX<T>& A, const ManakovState<T>& x, const T& h) {
  const T half = h / T(2);
  const MatX<T> start = x.M + half * commutator(x.M, manakov_Omega<T>(A, x.M));
  const MatX<T> Mmid = fixed_point<T>(
      start, [&](const MatX<T>& P) { return (x.M + half * commutator(P, manakov_Omega<T>(A, P))).eval(); },
      "manakov implicit midpoint");
  const MatX<T> W = manakov_Omega<T>(A, Mmid);
  return {(T(2) * Mmid - x.M).eval(), (x.O * cayley_half<T>((h * W).eval())).eval()};
}

// Isospectral Cayley method: U = cay(h Omega(M_*)) with M_* = (M_n + M_{n+1}) / 2, then
//     M_{n+1} = U^T M_n U,   O_{n+1} = O_n U.
// M_{n+1} is a similarity transform of M_n by an orthogonal matrix, so every eigenvalue (and
// tr(M^k) for every k) is kept to round-off, O stays orthogonal, and O M O^T is kept; so is the
// energy -tr(Omega M)/4 (because U commutes with W = Omega(M_*), see reference_integrators.cpp); the step
// with -h from x_{n+1} uses the same M_* and U^-1, so the method is symmetric, hence of order 2.
// M_{n+1} is found by fixed-point iteration and re-skewed (round-off only).
template <class T>
ManakovState<T> manakov_isospectral_step(const MatX<T>& A, const ManakovState<T>& x, const T& h) {
  auto U_of = [&](const MatX<T>& M1) {
    return cayley_half<T>((h * manakov_Omega<T>(A, ((x.M + M1) / T(2)).eval())).eval());
  };
  auto update = [&](const MatX<T>& M1) {
    const MatX<T> U = U_of(M1);
    const MatX<T> N = U.transpose() * x.M * U;
    return ((N - N.transpose()) / T(2)).eval();
  };
  const MatX<T> start = x.M + h * commutator(x.M, manakov_Omega<T>(A, x.M));
  const MatX<T> M1 = fixed_point<T>(start, update, "isospectral Cayley");
  const MatX<T> U = U_of(M1);
  const MatX<T> N = U.transpose() * x.M * U;
  return {((N - N.transpose()) / T(2)).eval(), (x.O * U).eval()};
}

}  // namespace gm::ref
