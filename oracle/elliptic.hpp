// The exact solution of the free rigid body, dPi/dt = Pi x I^-1 Pi (3.7)/(3.8), in Jacobi
// elliptic functions: an oracle independent of the Taylor integrator (oracle/taylor.hpp) and of
// impl/. Written for any Boost.Math-capable floating type: double, Real50, Real70.
//
// Notation. L2 = |Pi|^2 and 2h = sum Pi_i^2 / I_i are the two invariants. For a triaxial body let
// s, m, l index the smallest, middle and largest moment. The sign of
//     Q_m = L2 - 2h I_m
// decides the regime:
//     Q_m > 0: Pi circulates around the axis of the largest moment  (c = l, a = s),
//     Q_m < 0: Pi circulates around the axis of the smallest moment (c = s, a = l),
//     Q_m = 0: the separatrix (heteroclinic orbits between the unstable steady rotations
//              about the middle axis) or that unstable rotation itself.
// With b = m, the solution is (Landau & Lifshitz, Mechanics, section 37, for any ordering)
//     Pi_a = A cn(u, k),  Pi_b = B sn(u, k),  Pi_c = C dn(u, k),  u = omega t + u0,
//     A^2 = I_a P_c / (I_c - I_a),   B^2 = I_b P_c / (I_c - I_b),   C^2 = I_c P_a / (I_c - I_a),
//     omega^2 = (I_c - I_b) P_a / (I_a I_b I_c),   k^2 = (I_b - I_a) P_c / ((I_c - I_b) P_a),
// where P_c = 2h I_c - L2 and P_a = L2 - 2h I_a. Each of P_c, P_a and Q_m is evaluated as a sum of
// terms of one sign (P_c = sum_{i != c} Pi_i^2 (I_c - I_i) / I_i, and so on), so none suffers
// cancellation, and the complementary modulus k'^2 = (I_c - I_a) Q_m / ((I_c - I_b) P_a) is as
// accurate near the separatrix as far from it.
//
// Signs and the phase at t = 0. A > 0 is a choice (shifting u by 2K flips cn and sn together);
// C has the constant sign of Pi_c(0) (dn > 0); substituting the ansatz in (3.7) fixes
//     sign B = sigma * sign C * sign(1/I_a - 1/I_c),
// where sigma = +1 when (a, b, c) is a cyclic permutation of the axes (0, 1, 2) and -1 otherwise
// ((3.7) reads dPi_i/dt = (1/I_k - 1/I_j) Pi_j Pi_k for cyclic (i, j, k)). The phase is
//     u0 = F(phi0, k),  phi0 = atan2(Pi_b(0) / B, Pi_a(0) / A)   (so sn u0 = sin phi0, cn u0 = cos phi0),
// F the incomplete elliptic integral of the first kind (Boost's ellint_1(k, phi), any real phi).
// sn, cn, dn come from Boost.Math's jacobi_elliptic (which takes the modulus k, not the parameter
// m = k^2) at an argument reduced to |v| <= K/2 by the quarter-period shifts (see jacobi()).
//
// Degenerate cases, each with its own exact formula:
//   - Pi(0) = 0: Pi(t) = 0.
//   - a sphere (I1 = I2 = I3): Pi(t) = Pi(0).
//   - a symmetric top, I_i = I_j != I_k exactly, (i, j, k) cyclic: Pi_k is constant and
//     (Pi_i, Pi_j) rotates with nu = Pi_k (1/I_k - 1/I_i):
//       Pi_i = Pi_i(0) cos(nu t) + Pi_j(0) sin(nu t),  Pi_j = -Pi_i(0) sin(nu t) + Pi_j(0) cos(nu t).
//   - a steady rotation about a principal axis (Pi(0) along an axis): Pi(t) = Pi(0).
//   - exactly on the separatrix (Q_m == 0 as evaluated, see below): k = 1, cn = dn = sech, sn = tanh:
//       Pi_s = A sech u,  Pi_m = B tanh u,  Pi_l = C sech u,  sign A = sign Pi_s(0),
//       sign C = sign Pi_l(0), sign B = sigma * sign A * sign C, sinh u0 = (Pi_m(0)/B) / (Pi_l(0)/C).
// "Exactly on the separatrix" is decided on q_m = I_s I_l Q_m = Pi_l^2 (I_l - I_m) I_s +
// Pi_s^2 (I_s - I_m) I_l, which is exact for data whose products are representable (e.g.
// I = (3, 4, 6), |Pi_s| = |Pi_l|): data that are on the separatrix only up to rounding get the
// elliptic formula with k close to 1, which is the honest answer for such data (the motion near a
// separatrix is that ill-conditioned).
//
// Invalid input (a non-positive or non-finite moment, a non-finite Pi) throws
// std::invalid_argument with a message saying which.
#pragma once

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace gm::oracle {

enum class RigidBodyRegime {
  Rest,            // Pi = 0
  Sphere,          // I1 = I2 = I3
  SymmetricTop,    // exactly two equal moments
  SteadyRotation,  // Pi along a principal axis of a triaxial body (stable or not)
  MajorAxis,       // circulation around the axis of the largest moment (Q_m > 0)
  MinorAxis,       // circulation around the axis of the smallest moment (Q_m < 0)
  Separatrix,      // Q_m = 0, off the unstable equilibrium
};

inline const char* regime_name(RigidBodyRegime r) {
  switch (r) {
    case RigidBodyRegime::Rest:
      return "rest";
    case RigidBodyRegime::Sphere:
      return "sphere";
    case RigidBodyRegime::SymmetricTop:
      return "symmetric top";
    case RigidBodyRegime::SteadyRotation:
      return "steady rotation";
    case RigidBodyRegime::MajorAxis:
      return "rotation about the major axis";
    case RigidBodyRegime::MinorAxis:
      return "rotation about the minor axis";
    case RigidBodyRegime::Separatrix:
      return "separatrix";
  }
  return "?";
}

template <class T>
class FreeRigidBodySolution {
 public:
  using Vec = std::array<T, 3>;

  FreeRigidBodySolution(const Vec& I, const Vec& Pi0) : I_(I), Pi0_(Pi0) {
    using std::isfinite;
    for (int i = 0; i < 3; ++i) {
      if (!finite(I[i]) || !(I[i] > T(0)))
        throw std::invalid_argument("FreeRigidBodySolution: moment of inertia I" + std::to_string(i + 1) +
                                    " must be positive and finite");
      if (!finite(Pi0[i])) throw std::invalid_argument("FreeRigidBodySolution: Pi(0) must be finite");
    }
    if (Pi0[0] == T(0) && Pi0[1] == T(0) && Pi0[2] == T(0)) {
      regime_ = RigidBodyRegime::Rest;
      return;
    }
    if (I[0] == I[1] && I[1] == I[2]) {
      regime_ = RigidBodyRegime::Sphere;
      return;
    }
    if (I[0] == I[1] || I[1] == I[2] || I[2] == I[0]) {
      setup_symmetric_top();
      return;
    }
    setup_triaxial();
  }

  RigidBodyRegime regime() const { return regime_; }
  // Modulus k of the elliptic functions (0 for the closed-form degenerate cases, 1 on the separatrix).
  const T& modulus() const { return k_; }
  // Frequency omega of the elliptic argument u = omega t + u0 (nu for a symmetric top).
  const T& frequency() const { return omega_; }
  // Period of Pi(t): 4K(k)/omega in the circulating regimes, 2 pi/|nu| for a symmetric top;
  // 0 when Pi is constant or on the separatrix (no period).
  T period() const {
    if (regime_ == RigidBodyRegime::MajorAxis || regime_ == RigidBodyRegime::MinorAxis) return T(4) * K_ / omega_;
    if (regime_ == RigidBodyRegime::SymmetricTop && omega_ != T(0))
      return T(2) * boost::math::constants::pi<T>() / abs_(omega_);
    return T(0);
  }
  // Axes (a, b, c) of the elliptic formulas, see the header comment.
  std::array<int, 3> axes() const { return {a_, b_, c_}; }

  // Pi(t).
  Vec operator()(const T& t) const {
    switch (regime_) {
      case RigidBodyRegime::Rest:
      case RigidBodyRegime::Sphere:
      case RigidBodyRegime::SteadyRotation:
        return Pi0_;
      case RigidBodyRegime::SymmetricTop: {
        using std::cos;
        using std::sin;
        const T phase = omega_ * t;
        const T co = cos(phase), si = sin(phase);
        Vec p = Pi0_;
        p[a_] = Pi0_[a_] * co + Pi0_[b_] * si;
        p[b_] = -Pi0_[a_] * si + Pi0_[b_] * co;
        return p;
      }
      case RigidBodyRegime::Separatrix: {
        using std::cosh;
        using std::tanh;
        const T u = omega_ * t + u0_;
        const T sech = T(1) / cosh(u);
        Vec p;
        p[a_] = A_ * sech;
        p[b_] = B_ * tanh(u);
        p[c_] = C_ * sech;
        return p;
      }
      case RigidBodyRegime::MajorAxis:
      case RigidBodyRegime::MinorAxis: {
        T sn, cn, dn;
        jacobi(T(omega_ * t + u0_), sn, cn, dn);
        Vec p;
        p[a_] = A_ * cn;
        p[b_] = B_ * sn;
        p[c_] = C_ * dn;
        return p;
      }
    }
    return Pi0_;
  }

 private:
  static bool finite(const T& x) {
    using boost::multiprecision::isfinite;
    using std::isfinite;
    return isfinite(x);
  }
  static T abs_(const T& x) { return x < T(0) ? T(-x) : x; }
  static T sign_(const T& x) { return x < T(0) ? T(-1) : T(1); }
  static long long to_integer(const T& x) {
    if constexpr (std::is_same_v<T, double>)
      return static_cast<long long>(x);
    else
      return x.template convert_to<long long>();
  }
  static T round_(const T& x) {
    using std::floor;
    return floor(x + T(0.5));
  }
  // sn, cn, dn of u. Boost's jacobi_elliptic (descending Landen/AGM) loses accuracy where the
  // amplitude nears an odd multiple of pi/2 (u near K, 3K, ...): there it read ~600 eps off in
  // 50 digits. So u is written u = m K + v with |v| <= K/2 and the quarter-period shifts
  //   sn(v + K) = cn v / dn v,  cn(v + K) = -k' sn v / dn v,  dn(v + K) = k' / dn v,
  //   (sn, cn, dn)(v + 2K) = (-sn v, -cn v, dn v)
  // bring the evaluation to |v| <= K/2, with the complementary modulus k' from its accurate
  // one-signed formula. This also reduces u modulo the period 4K.
  void jacobi(const T& u, T& sn, T& cn, T& dn) const {
    using std::floor;
    const T m_real = floor(u / K_ + T(0.5));
    const T v = u - m_real * K_;
    T c, d;
    const T s = boost::math::jacobi_elliptic(k_, v, &c, &d);
    long long m = to_integer(m_real) % 4;
    if (m < 0) m += 4;
    switch (m) {
      case 0:
        sn = s, cn = c, dn = d;
        break;
      case 1:
        sn = c / d, cn = -kc_ * s / d, dn = kc_ / d;
        break;
      case 2:
        sn = -s, cn = -c, dn = d;
        break;
      default:
        sn = -c / d, cn = kc_ * s / d, dn = kc_ / d;
        break;
    }
  }

  // +1 when (a, b, c) is a cyclic permutation of (0, 1, 2), -1 otherwise.
  static int parity(int a, int b, int c) {
    (void)c;
    return ((b - a + 3) % 3 == 1) ? 1 : -1;
  }

  void setup_symmetric_top() {
    regime_ = RigidBodyRegime::SymmetricTop;
    // The two equal moments i, j and the distinct one k, with (i, j, k) cyclic.
    int i, j, k;
    if (I_[0] == I_[1])
      i = 0, j = 1, k = 2;
    else if (I_[1] == I_[2])
      i = 1, j = 2, k = 0;
    else
      i = 2, j = 0, k = 1;
    a_ = i;
    b_ = j;
    c_ = k;
    omega_ = Pi0_[k] * (T(1) / I_[k] - T(1) / I_[i]);
  }

  void setup_triaxial() {
    using std::asinh;
    using std::atan2;
    using std::sqrt;
    // s, m, l: smallest, middle, largest moment.
    int s = 0, l = 0;
    for (int i = 1; i < 3; ++i) {
      if (I_[i] < I_[s]) s = i;
      if (I_[i] > I_[l]) l = i;
    }
    const int m = 3 - s - l;
    const Vec& P = Pi0_;
    auto sq = [](const T& x) { return x * x; };
    // q_m = I_s I_l (L2 - 2h I_m): exact for data with representable products.
    const T q_m = sq(P[l]) * (I_[l] - I_[m]) * I_[s] + sq(P[s]) * (I_[s] - I_[m]) * I_[l];
    b_ = m;
    if (q_m > T(0)) {
      regime_ = RigidBodyRegime::MajorAxis;
      c_ = l, a_ = s;
    } else if (q_m < T(0)) {
      regime_ = RigidBodyRegime::MinorAxis;
      c_ = s, a_ = l;
    } else {
      regime_ = RigidBodyRegime::Separatrix;
      c_ = l, a_ = s;
    }
    const int a = a_, b = b_, c = c_;
    // One-signed sums (see the header): P_c = 2h I_c - L2, P_a = L2 - 2h I_a, Q_m = L2 - 2h I_m.
    T Pc(0), Pa(0);
    for (int i = 0; i < 3; ++i) {
      if (i != c) Pc += sq(P[i]) * (I_[c] - I_[i]) / I_[i];
      if (i != a) Pa += sq(P[i]) * (I_[i] - I_[a]) / I_[i];
    }
    if (regime_ == RigidBodyRegime::Separatrix) {
      if (P[s] == T(0) && P[l] == T(0)) {  // the unstable steady rotation about the middle axis
        regime_ = RigidBodyRegime::SteadyRotation;
        return;
      }
      k_ = T(1);
      A_ = sign_(P[a]) * sqrt(I_[a] * Pc / (I_[c] - I_[a]));
      C_ = sign_(P[c]) * sqrt(I_[c] * Pa / (I_[c] - I_[a]));
      B_ = T(parity(a, b, c)) * sign_(A_) * sign_(C_) * sqrt(I_[b] * Pc / (I_[c] - I_[b]));
      omega_ = sqrt((I_[c] - I_[b]) * Pa / (I_[a] * I_[b] * I_[c]));
      // sinh u0 = tanh u0 / sech u0, read from the larger of the two sech components.
      const T sech0 = abs_(P[c] / C_) >= abs_(P[a] / A_) ? T(P[c] / C_) : T(P[a] / A_);
      u0_ = asinh(T(P[b] / B_) / sech0);
      return;
    }
    if (Pc == T(0)) {  // Pi along the axis c: a stable steady rotation
      regime_ = RigidBodyRegime::SteadyRotation;
      return;
    }
    const T Qm = q_m / (I_[s] * I_[l]);
    const T k2 = (I_[b] - I_[a]) * Pc / ((I_[c] - I_[b]) * Pa);
    kc_ = sqrt(T((I_[c] - I_[a]) * Qm / ((I_[c] - I_[b]) * Pa)));
    k_ = sqrt(k2);
    A_ = sqrt(I_[a] * Pc / (I_[c] - I_[a]));
    C_ = sign_(P[c]) * sqrt(I_[c] * Pa / (I_[c] - I_[a]));
    const T sign_inv = (T(1) / I_[a] - T(1) / I_[c]) < T(0) ? T(-1) : T(1);
    B_ = T(parity(a, b, c)) * sign_(C_) * sign_inv * sqrt(I_[b] * Pc / (I_[c] - I_[b]));
    omega_ = sqrt((I_[c] - I_[b]) * Pa / (I_[a] * I_[b] * I_[c]));
    const T phi0 = atan2(T(P[b] / B_), T(P[a] / A_));
    K_ = boost::math::ellint_1(k_);
    u0_ = boost::math::ellint_1(k_, phi0);
  }

  Vec I_, Pi0_;
  RigidBodyRegime regime_ = RigidBodyRegime::Rest;
  int a_ = 0, b_ = 1, c_ = 2;
  T A_{0}, B_{0}, C_{0}, omega_{0}, k_{0}, kc_{1}, K_{0}, u0_{0};
};

}  // namespace gm::oracle
