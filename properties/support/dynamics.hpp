// Shared pieces of the dynamic properties: random bodies and states, the truths (invariants
// written from the notes' formulas), flows of the oracle's fields (Taylor) and of a subject's
// vector-field slots (Gragg-Bulirsch-Stoer), and the tolerance model for flows.
//
// Which flow where. A statement about a subject's *equations* (its vector-field slots) is
// checked along the flow of those slots, computed by support/flow.hpp; a statement about a
// subject's *functions* evaluated along the true motion (spatial momentum, I_space, ...) is
// checked along the Taylor oracle's flow of the notes' equations (oracle/fields.hpp), so a wrong
// vector field and a wrong function are caught separately.
//
// Tolerance model for flows (DESIGN.md, roundoff class). Both flows are accurate to round-off
// per step: the Taylor oracle and the GBS flow take steps with local error <= 16 eps(T) |x|, at
// 1 to 3 steps per unit of lambda t, where lambda bounds the angular speed (|Pi| / min I, or
// |M| / min(a_i + a_j)). So
//   - an invariant of degree d (|Pi|^2, h, O^T O, O Pi, tr M^k) drifts by at most about
//     d * 16 eps * 3 per unit of lambda t: it is compared with k = 64 d eps * scale * (1 + lambda t)
//     (or, when many sample times force short steps, with the steps actually taken / 3 in place
//     of 1 + lambda t: growth(lambda, t, steps));
//   - two accurate flows (or a flow and the exact solution) also differ by a phase error: a
//     perturbation of the invariants by delta changes the frequency by O(delta), and the phase
//     error grows like delta * lambda t, so states are compared with
//     k = 64 eps * scale * (1 + lambda t)^2;
//   - for the rigid body the flow's own conditioning is known: kappa(t) = max over s <= t of
//     |d Pi(s) / d Pi(0)|_inf, from the exact elliptic solution (rigid_body_conditioning). It is
//     O(1 + lambda t) for generic data, but grows like exp(omega t) on and near the separatrix
//     (where a step's error is amplified on the way to the unstable middle axis), so rigid-body
//     states are compared with k = 64 eps * scale * (1 + lambda t) * kappa(t), and attitudes,
//     which integrate the error of Omega once more, with an extra factor (1 + lambda t).
// scale is the size of the compared quantity (|x|_inf, |Pi|^2, ...), at least 1.
#pragma once

#include "core/subject.hpp"
#include "oracle/elliptic.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"
#include "properties/support/flow.hpp"
#include "properties/support/generators.hpp"

#include <rapidcheck.h>

#include <string>

#include <array>
#include <cmath>
#include <vector>

namespace gm::dyn {

// ---------------------------------------------------------------------------------------------
// Random data (dyadic, so the same draw is the same number in double and Real50).

// A value drawn from g inside a property, over g's full range whatever RapidCheck's current size
// (a flow property runs few cases, and the first, at size 0, would otherwise draw the minimum of
// every range: a sphere at rest). In multiprecision every rerun of a flow property costs tens of
// milliseconds, so there the draw is not shrunk either (a failing case is reported as drawn, and
// the double run of the same property shrinks it).
// `name` is what a counterexample calls the value (the notes' symbol, or what the value is of one):
// "a (I = (b + c, c + a, a + b))" rather than "double".
template <class T, class G>
auto pick(const G& g, const std::string& name = {}) {
  if constexpr (std::is_same_v<T, double>)
    return *rc::gen::resize(100, g).as(name);
  else
    return *rc::gen::noShrink(rc::gen::resize(100, g)).as(name);
}

// A value k / 4 with lo <= k <= hi, shrinking toward lo / 4.
template <class T>
rc::Gen<T> quarter(int lo, int hi) {
  return rc::gen::map(rc::gen::inRange(lo, hi + 1), [](int k) { return T(k) / T(4); });
}

// Principal moments (b + c, c + a, a + b) with a, b, c in [1/2, 2]: in [1, 4], triangle
// inequalities strict; shrinks toward the sphere I = (1, 1, 1).
template <class T>
Vec3<T> draw_inertia() {
  const T a = pick<T>(quarter<T>(2, 8), "a (I = (b + c, c + a, a + b))");
  const T b = pick<T>(quarter<T>(2, 8), "b (I = (b + c, c + a, a + b))");
  const T c = pick<T>(quarter<T>(2, 8), "c (I = (b + c, c + a, a + b))");
  return Vec3<T>(b + c, c + a, a + b);
}

// Principal moments that are pairwise distinct.
template <class T>
Vec3<T> draw_triaxial_inertia() {
  const Vec3<T> I = draw_inertia<T>();
  RC_PRE(I(0) != I(1) && I(1) != I(2) && I(0) != I(2));
  return I;
}

// Body angular momentum with components k / 64, |k| <= 64, not zero.
template <class T>
Vec3<T> draw_momentum() {
  Vec3<T> P = pick<T>(gen::vec3<T>(64, 6), "Pi (0 is replaced by [1, 0, 0])");
  if (P.isZero()) P(0) = T(1);
  return P;
}

template <class T>
Mat3<T> draw_rotation() {
  return pick<T>(gen::rotation3<T>(), "O");
}

// An attitude for an integrator's check, where Lie-group code branches (../shared/DESIGN.md, "input
// regimes"): half the draws generic (draw_rotation), the others 2^-m rad from the identity or from a
// rotation by pi, m = 2..52 (small-angle series and their thresholds, 1e-3, 1e-6, sqrt(eps); the
// other branch point of the log map). Exact rational rotations: Cayley of a small skew about a
// rational unit axis, times 2 n n^T - Id for a rational unit n. The regime is a named pick, so a
// failure names it, and shrinking keeps it when only it fails.
template <class T>
Mat3<T> draw_attitude() {
  const int regime = pick<T>(rc::gen::inRange(0, 4),
                             "attitude (0, 1 generic; 2 2^-m rad from the identity; 3 2^-m rad from a rotation by pi)");
  if (regime < 2) return draw_rotation<T>();
  const int m = pick<T>(rc::gen::inRange(2, 53), "m (the attitude 2^-m rad from its branch point)");
  // Near +1 and -1 (the identity), and near w = 0 (pi) from both sides: the quaternion given to a
  // step kept in one is q or -q (core/state_form.hpp, quaternion_sign_given).
  quaternion_sign_given() =
      pick<T>(rc::gen::inRange(0, 2), "sign of the quaternion given to a step kept in one (0: w >= 0; 1: -q, w <= 0)")
          ? -1
          : 1;
  static const int axes[5][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, 2}, {2, -1, 2}};  // / 1 or / 3: unit
  const auto unit = [](int k) {
    const Rational d = k < 3 ? Rational(1) : Rational(3);
    return Vec3<Rational>(Rational(axes[k][0]) / d, Rational(axes[k][1]) / d, Rational(axes[k][2]) / d);
  };
  const Vec3<Rational> a = unit(pick<T>(rc::gen::inRange(0, 5), "axis of the small rotation (one of 5)"));
  // Cayley of S = hat(a) t turns by 2 atan(t): t = 2^-(m+1) turns by about 2^-m rad.
  const Rational t = Rational(1) / Rational(boost::multiprecision::cpp_int(1) << (m + 1));
  MatX<Rational> S = MatX<Rational>::Zero(3, 3);
  S(0, 1) = -a(2) * t, S(0, 2) = a(1) * t, S(1, 0) = a(2) * t, S(1, 2) = -a(0) * t, S(2, 0) = -a(1) * t,
       S(2, 1) = a(0) * t;
  MatX<Rational> R = gen::cayley_rational(S);
  if (regime == 3) {
    const Vec3<Rational> n = unit(pick<T>(rc::gen::inRange(0, 5), "axis of the rotation by pi (one of 5)"));
    const Mat3<Rational> flip = Mat3<Rational>(Rational(2) * n * n.transpose()) - Mat3<Rational>::Identity();
    R = MatX<Rational>(flip * Mat3<Rational>(R));
  }
  return Mat3<T>(convert_matrix<T>(R));
}

// Generic data, where a degenerate draw (a sphere, a symmetric top, Pi along an axis, an
// equilibrium of Manakov's equations) would make a check vacuous or an "unclaimed property holds"
// note false: pairwise distinct moments (b + c, c + a, a + b) with a < b < c in a random axis
// order, and momenta whose components all have size >= 1/8.
template <class T>
Vec3<T> draw_generic_inertia() {
  const T a = pick<T>(quarter<T>(2, 8), "a (I = (b + c, c + a, a + b) in an axis order)");
  const T b = a + pick<T>(quarter<T>(1, 4), "b - a");
  const T c = b + pick<T>(quarter<T>(1, 4), "c - b");
  const int perm = pick<T>(rc::gen::inRange(0, 6), "axis order of I (one of the 6 permutations)");
  const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const T I[3] = {b + c, c + a, a + b};
  return Vec3<T>(I[order[perm][0]], I[order[perm][1]], I[order[perm][2]]);
}

template <class T>
T generic_entry() {
  const int k = pick<T>(rc::gen::inRange(8, 65), "k (an entry +-k/64)");
  const bool negative = pick<T>(rc::gen::inRange(0, 2), "sign (1: the entry is -k/64)") == 1;
  return T(negative ? -k : k) / T(64);
}

template <class T>
Vec3<T> draw_generic_momentum() {
  return Vec3<T>(generic_entry<T>(), generic_entry<T>(), generic_entry<T>());
}

// Pairwise distinct a_i (a_0 in [1/2, 1], steps of 1/4 to 1/2) and a skew M with every entry of
// size in [1/8, 1] (drawn as the momentum's components).
template <class T>
std::vector<T> draw_generic_manakov_a(int n) {
  std::vector<T> a{pick<T>(quarter<T>(2, 4), "a_0 (A = diag(a))")};
  for (int i = 1; i < n; ++i) a.push_back(a.back() + pick<T>(quarter<T>(1, 2), "a_i - a_(i-1)"));
  return a;
}

template <class T>
MatX<T> draw_generic_skew(int n) {
  MatX<T> M = MatX<T>::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      M(i, j) = generic_entry<T>();
      M(j, i) = -M(i, j);
    }
  return M;
}

// Manakov data: A = diag(a) with a_i in [1/2, 2]; M skew with entries in [-1, 1].
template <class T>
std::vector<T> draw_manakov_a(int n) {
  std::vector<T> a;
  for (int i = 0; i < n; ++i) a.push_back(pick<T>(quarter<T>(2, 8), "a_i (A = diag(a))"));
  return a;
}

template <class T>
MatX<T> diag_of(const std::vector<T>& a) {
  MatX<T> A = MatX<T>::Zero(static_cast<Eigen::Index>(a.size()), static_cast<Eigen::Index>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i) A(i, i) = a[i];
  return A;
}

template <class T>
MatX<T> draw_skew(int n, int max_abs = 64) {
  MatX<T> M = pick<T>(gen::skew<T>(n, max_abs, 6), "M (0 is replaced by E_12 - E_21)");
  if (M.isZero()) M(0, 1) = T(1), M(1, 0) = T(-1);
  return M;
}

// ---------------------------------------------------------------------------------------------
// Truths.

template <class T>
T casimir(const Vec3<T>& Pi) {
  return Pi.squaredNorm();
}

// (3.4): h = sum Pi_i^2 / (2 I_i).
template <class T>
T energy(const Vec3<T>& I, const Vec3<T>& Pi) {
  return (Pi(0) * Pi(0) / I(0) + Pi(1) * Pi(1) / I(1) + Pi(2) * Pi(2) / I(2)) / T(2);
}

// Manakov for A = diag(a): Omega_ij = M_ij / (a_i + a_j), energy -tr(Omega M) / 4.
template <class T>
MatX<T> manakov_omega_diag(const std::vector<T>& a, const MatX<T>& M) {
  const auto n = M.rows();
  MatX<T> W(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) W(i, j) = M(i, j) / (a[i] + a[j]);
  return W;
}

template <class T>
T manakov_energy(const std::vector<T>& a, const MatX<T>& M) {
  return -(manakov_omega_diag<T>(a, M) * M).trace() / T(4);
}

// Angular speed bounds for the tolerance model.
template <class T>
T rigid_body_rate(const Vec3<T>& I, const Vec3<T>& Pi) {
  using std::sqrt;
  return sqrt(Pi.squaredNorm()) / I.minCoeff();
}

template <class T>
T manakov_rate(const std::vector<T>& a, const MatX<T>& M) {
  using std::sqrt;
  T amin = a[0];
  for (const T& x : a) amin = std::min(amin, x);
  return sqrt(M.squaredNorm()) / (T(2) * amin);
}

// 1 + lambda t: the growth factor of the tolerance model above.
template <class T>
T growth(const T& lambda, const T& t) {
  return T(1) + lambda * abs_value(t);
}

// The same for a flow known to have taken `steps` steps: the model's 1 to 3 steps per unit of
// lambda t no longer holds when many sample times force short steps (a quadrature's nodes), and
// the local errors then add up over the steps actually taken.
template <class T>
T growth(const T& lambda, const T& t, long steps) {
  const T g = growth(lambda, t), n = T(steps) / T(3);
  return g < n ? n : g;
}

template <class T>
T at_least_one(const T& x) {
  return x < T(1) ? T(1) : x;
}

// kappa(t_max) = max over 32 times s in (0, t_max] of |d Pi(s) / d Pi(0)|_inf (infinity norm of the
// Jacobian), by central differences of the exact solution in double (relative step 1e-6: the
// estimate is good to a few digits, which is all a tolerance factor needs). At least 1.
template <class T>
T rigid_body_conditioning(const Vec3<T>& I, const Vec3<T>& Pi0, const T& t_max) {
  const std::array<double, 3> Id = {to_double(I(0)), to_double(I(1)), to_double(I(2))};
  const std::array<double, 3> P = {to_double(Pi0(0)), to_double(Pi0(1)), to_double(Pi0(2))};
  double size = 0;
  for (double p : P) size = std::max(size, std::abs(p));
  const double d = 1e-6 * (size > 0 ? size : 1.0);
  std::vector<oracle::FreeRigidBodySolution<double>> plus, minus;
  for (int j = 0; j < 3; ++j) {
    auto a = P, b = P;
    a[j] += d;
    b[j] -= d;
    plus.emplace_back(Id, a);
    minus.emplace_back(Id, b);
  }
  double kappa = 1;
  const double tm = to_double(t_max);
  for (int k = 1; k <= 32; ++k) {
    const double t = tm * k / 32;
    std::array<std::array<double, 3>, 3> J{};
    for (int j = 0; j < 3; ++j) {
      const auto p = plus[j](t), m = minus[j](t);
      for (int i = 0; i < 3; ++i) J[i][j] = (p[i] - m[i]) / (2 * d);
    }
    for (int i = 0; i < 3; ++i) kappa = std::max(kappa, std::abs(J[i][0]) + std::abs(J[i][1]) + std::abs(J[i][2]));
  }
  return T(kappa);
}

// ---------------------------------------------------------------------------------------------
// State packing: Pi then O row-major (the oracle's layout), M then O row-major for Manakov.

template <class T>
VecX<T> pack(const RigidBodyState<T>& x) {
  VecX<T> v(12);
  for (int i = 0; i < 3; ++i) v(i) = x.Pi(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v(3 + 3 * i + j) = x.O(i, j);
  return v;
}

template <class T>
RigidBodyState<T> unpack_rigid_body(const VecX<T>& v) {
  RigidBodyState<T> x;
  for (int i = 0; i < 3; ++i) x.Pi(i) = v(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) x.O(i, j) = v(3 + 3 * i + j);
  return x;
}

template <class T>
VecX<T> pack(const ManakovState<T>& x) {
  const auto n = x.M.rows();
  VecX<T> v(2 * n * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) v(n * i + j) = x.M(i, j), v(n * n + n * i + j) = x.O(i, j);
  return v;
}

template <class T>
ManakovState<T> unpack_manakov(const VecX<T>& v, int n) {
  ManakovState<T> x{MatX<T>(n, n), MatX<T>(n, n)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) x.M(i, j) = v(n * i + j), x.O(i, j) = v(n * n + n * i + j);
  return x;
}

template <class T>
std::vector<T> to_std(const VecX<T>& v) {
  return std::vector<T>(v.data(), v.data() + v.size());
}

template <class T>
VecX<T> from_std(const std::vector<T>& v) {
  VecX<T> out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) out(static_cast<Eigen::Index>(i)) = v[i];
  return out;
}

// ---------------------------------------------------------------------------------------------
// Oracle flows (Taylor series of the notes' equations, oracle/fields.hpp).

// (Pi, O) of (2.20) at each of `times`.
template <class T>
std::vector<RigidBodyState<T>> oracle_rigid_body(const Vec3<T>& I, const RigidBodyState<T>& x0,
                                                 const std::vector<T>& times) {
  oracle::RigidBodyAttitudeField<T> f(I(0), I(1), I(2));
  oracle::TaylorSolver<T, decltype(f)> solver(f, 12, eps<T>());
  std::vector<RigidBodyState<T>> out;
  for (const auto& s : solver.sample(to_std(pack(x0)), T(0), times)) out.push_back(unpack_rigid_body(from_std(s)));
  return out;
}

// (M, O) of Manakov's system with A = diag(a).
template <class T>
std::vector<ManakovState<T>> oracle_manakov(const std::vector<T>& a, const ManakovState<T>& x0,
                                            const std::vector<T>& times) {
  const int n = static_cast<int>(a.size());
  oracle::ManakovField<T> f(a);
  oracle::TaylorSolver<T, decltype(f)> solver(f, 2 * n * n, eps<T>());
  std::vector<ManakovState<T>> out;
  for (const auto& s : solver.sample(to_std(pack(x0)), T(0), times)) out.push_back(unpack_manakov(from_std(s), n));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Flows of a subject's slots.

// (Pi, O) under the subject's Euler equations (3.8) and reconstruction (2.10), Omega = I^-1 Pi
// (the truth (3.5)). Needs euler_3_8 and reconstruction_2_10.
template <class T>
std::vector<RigidBodyState<T>> subject_rigid_body(const Subject<T>& s, const Vec3<T>& I, const RigidBodyState<T>& x0,
                                                  const std::vector<T>& times, long* steps = nullptr) {
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    const RigidBodyState<T> x = unpack_rigid_body(v);
    const Vec3<T> W = x.Pi.cwiseQuotient(I);
    return pack(RigidBodyState<T>{s.euler_3_8(I, x.Pi), s.reconstruction_2_10(x.O, W)});
  });
  std::vector<RigidBodyState<T>> out;
  for (const auto& v : g.sample(pack(x0), T(0), times)) out.push_back(unpack_rigid_body(v));
  if (steps) *steps = g.stats().steps;
  return out;
}

// M alone under the subject's Manakov equations. Needs manakov_2_34.
template <class T>
std::vector<MatX<T>> subject_manakov_M(const Subject<T>& s, const MatX<T>& A, const MatX<T>& M0,
                                       const std::vector<T>& times, long* steps = nullptr) {
  const auto n = M0.rows();
  auto vec = [n](const MatX<T>& M) {
    VecX<T> v(n * n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) v(n * i + j) = M(i, j);
    return v;
  };
  auto mat = [n](const VecX<T>& v) {
    MatX<T> M(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) M(i, j) = v(n * i + j);
    return M;
  };
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) { return vec(s.manakov_2_34(A, mat(v))); });
  std::vector<MatX<T>> out;
  for (const auto& v : g.sample(vec(M0), T(0), times)) out.push_back(mat(v));
  if (steps) *steps = g.stats().steps;
  return out;
}

// Pi alone under the subject's (3.8). Needs euler_3_8.
template <class T>
std::vector<Vec3<T>> subject_euler(const Subject<T>& s, const Vec3<T>& I, const Vec3<T>& Pi0,
                                   const std::vector<T>& times, long* steps = nullptr) {
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) { return VecX<T>(s.euler_3_8(I, Vec3<T>(v))); });
  std::vector<Vec3<T>> out;
  for (const auto& v : g.sample(VecX<T>(Pi0), T(0), times)) out.push_back(Vec3<T>(v));
  if (steps) *steps = g.stats().steps;
  return out;
}

// (M, O) under the subject's Manakov equations: dM/dt = manakov_2_34(A, M),
// dO/dt = O manakov_Omega(A, M). Needs manakov_2_34 and manakov_Omega.
template <class T>
std::vector<ManakovState<T>> subject_manakov(const Subject<T>& s, const MatX<T>& A, const ManakovState<T>& x0,
                                             const std::vector<T>& times, long* steps = nullptr) {
  const int n = static_cast<int>(A.rows());
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    const ManakovState<T> x = unpack_manakov(v, n);
    return pack(ManakovState<T>{s.manakov_2_34(A, x.M), (x.O * s.manakov_Omega(A, x.M)).eval()});
  });
  std::vector<ManakovState<T>> out;
  for (const auto& v : g.sample(pack(x0), T(0), times)) out.push_back(unpack_manakov(v, n));
  if (steps) *steps = g.stats().steps;
  return out;
}

// How far the rigid-body flow properties integrate: t = 20 in double; in 50 digits every flow
// evaluation costs ~50x more, so t = 10.
template <class T>
T rigid_body_horizon() {
  return std::is_same_v<T, double> ? T(20) : T(10);
}

// Equally spaced times (t_end / count, ..., t_end).
template <class T>
std::vector<T> times_to(const T& t_end, int count) {
  std::vector<T> t;
  for (int i = 1; i <= count; ++i) t.push_back(t_end * T(i) / T(count));
  return t;
}

// The draws and the flows are instantiated once, in dynamics.cpp, for double and Real50: each
// drags in RapidCheck's generators, the Taylor oracle or the extrapolation integrator over a
// multiprecision type, which every dynamic property file would otherwise compile again.
#define GM_DYNAMICS_FOR(PREFIX, T)                                                                              \
  PREFIX template Vec3<T> draw_inertia<T>();                                                                    \
  PREFIX template Vec3<T> draw_triaxial_inertia<T>();                                                           \
  PREFIX template Vec3<T> draw_momentum<T>();                                                                   \
  PREFIX template Mat3<T> draw_rotation<T>();                                                                   \
  PREFIX template Mat3<T> draw_attitude<T>();                                                                   \
  PREFIX template Vec3<T> draw_generic_inertia<T>();                                                            \
  PREFIX template T generic_entry<T>();                                                                         \
  PREFIX template Vec3<T> draw_generic_momentum<T>();                                                           \
  PREFIX template std::vector<T> draw_generic_manakov_a<T>(int);                                                \
  PREFIX template MatX<T> draw_generic_skew<T>(int);                                                            \
  PREFIX template std::vector<T> draw_manakov_a<T>(int);                                                        \
  PREFIX template MatX<T> draw_skew<T>(int, int);                                                               \
  PREFIX template T rigid_body_conditioning<T>(const Vec3<T>&, const Vec3<T>&, const T&);                       \
  PREFIX template std::vector<RigidBodyState<T>> oracle_rigid_body<T>(const Vec3<T>&, const RigidBodyState<T>&, \
                                                                      const std::vector<T>&);                   \
  PREFIX template std::vector<ManakovState<T>> oracle_manakov<T>(const std::vector<T>&, const ManakovState<T>&, \
                                                                 const std::vector<T>&);                        \
  PREFIX template std::vector<RigidBodyState<T>> subject_rigid_body<T>(                                         \
      const Subject<T>&, const Vec3<T>&, const RigidBodyState<T>&, const std::vector<T>&, long*);               \
  PREFIX template std::vector<MatX<T>> subject_manakov_M<T>(const Subject<T>&, const MatX<T>&, const MatX<T>&,  \
                                                            const std::vector<T>&, long*);                      \
  PREFIX template std::vector<Vec3<T>> subject_euler<T>(const Subject<T>&, const Vec3<T>&, const Vec3<T>&,      \
                                                        const std::vector<T>&, long*);                          \
  PREFIX template std::vector<ManakovState<T>> subject_manakov<T>(                                              \
      const Subject<T>&, const MatX<T>&, const ManakovState<T>&, const std::vector<T>&, long*);

GM_DYNAMICS_FOR(extern, double)
GM_DYNAMICS_FOR(extern, Real50)

}  // namespace gm::dyn
