// geomech-dynamics-report: the figures of the dynamics issue, measured on the reference subject.
//
//   1. the worst residual of every exactly conserved quantity along the flows the properties use
//      (the reference's vector fields integrated by support/flow.hpp; its functions along the
//      Taylor oracle), in double and in 50 digits, over random cases drawn as the properties draw
//      them, with the bar: every one within 1e-40 in 50 digits;
//   2. the same for what each integrator keeps (64 steps of h = 1/8);
//   3. the integrators' measured orders (log-log slopes against the Taylor oracle);
//   4. the exact elliptic solution against the Taylor oracle in 50 digits.
//
// Usage: geomech-dynamics-report [cases_double [cases_mp50]]   (defaults 20 and 4; fixed seed)
#include "impl/reference_subject.hpp"
#include "properties/integrators/support/convergence.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/spectrum.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>

namespace gm {
namespace {

// Draws like support/dynamics.hpp's, from a fixed-seed generator (no RapidCheck here).
struct Draw {
  std::mt19937_64 rng{20240601};
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  template <class T>
  T quarter(int lo, int hi) {
    return T(integer(lo, hi)) / T(4);
  }
  template <class T>
  T entry() {  // k / 64, 8 <= |k| <= 64
    const int k = integer(8, 64);
    return T(integer(0, 1) ? -k : k) / T(64);
  }
  template <class T>
  Vec3<T> inertia() {
    const T a = quarter<T>(2, 8), b = a + quarter<T>(1, 4), c = b + quarter<T>(1, 4);
    return Vec3<T>(b + c, c + a, a + b);
  }
  template <class T>
  Vec3<T> momentum() {
    return Vec3<T>(entry<T>(), entry<T>(), entry<T>());
  }
  template <class T>
  Mat3<T> rotation() {  // Cayley of a skew matrix with entries k / 4, as gen::rotation3
    MatX<Rational> S = MatX<Rational>::Zero(3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        S(i, j) = Rational(integer(-8, 8)) / 4;
        S(j, i) = -S(i, j);
      }
    return Mat3<T>(convert_matrix<T>(gen::cayley_rational(S)));
  }
  template <class T>
  std::vector<T> manakov_a(int n) {
    std::vector<T> a{quarter<T>(2, 4)};
    for (int i = 1; i < n; ++i) a.push_back(a.back() + quarter<T>(1, 2));
    return a;
  }
  template <class T>
  MatX<T> skew(int n, const T& factor) {
    MatX<T> M = MatX<T>::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) M(i, j) = entry<T>() * factor, M(j, i) = -M(i, j);
    return M;
  }
};

struct Worst {
  std::map<std::string, std::pair<double, double>> by;  // quantity -> (double, mp50)
  std::vector<std::string> order;
  void add(const std::string& q, bool mp, double r) {
    if (!by.count(q)) order.push_back(q), by[q] = {0, 0};
    double& w = mp ? by[q].second : by[q].first;
    if (!(r <= w)) w = r;
  }
};

template <class T>
double d(const T& x) {
  return to_double(abs_value(x));
}

template <class T>
void conserved_along_flows(Worst& w, int cases) {
  const bool mp = !std::is_same_v<T, double>;
  const Subject<T>& s = *reference_subject().get<T>();
  Draw dr;
  const T horizon = mp ? T(10) : T(20), attitude_horizon = mp ? T(5) : T(20);
  for (int c = 0; c < cases; ++c) {
    const Vec3<T> I = dr.inertia<T>(), Pi0 = dr.momentum<T>();
    const Mat3<T> O0 = dr.rotation<T>();
    for (const auto& Pi : dyn::subject_euler(s, I, Pi0, dyn::times_to(horizon, 20))) {
      w.add("|Pi|^2 along Euler's flow (3.8)", mp, d(T(dyn::casimir(Pi) - dyn::casimir(Pi0))));
      w.add("h (3.4) along Euler's flow", mp, d(T(dyn::energy(I, Pi) - dyn::energy(I, Pi0))));
    }
    const RigidBodyState<T> x0{Pi0, O0};
    for (const auto& x : dyn::subject_rigid_body(s, I, x0, dyn::times_to(attitude_horizon, 10))) {
      w.add("O^T O - Id along (2.10)", mp, d(max_abs((x.O.transpose() * x.O - Mat3<T>::Identity()).eval())));
      w.add("det O - 1 along (2.10)", mp, d(T(x.O.determinant() - T(1))));
      w.add("O Pi (Noether) along the subject's (2.20)", mp, d(max_abs((x.O * x.Pi - O0 * Pi0).eval())));
    }
    const Vec3<T> pi0 = s.spatial_momentum(O0, Pi0);
    for (const auto& x : dyn::oracle_rigid_body(I, x0, dyn::times_to(horizon, 10))) {
      w.add("spatial_momentum(O, Pi) along the oracle's (2.20)", mp,
            d(max_abs((s.spatial_momentum(x.O, x.Pi) - pi0).eval())));
      const Vec3<T> omega = x.O * x.Pi.cwiseQuotient(I), omega0 = O0 * Pi0.cwiseQuotient(I);
      w.add("I_space omega (Remark 2.1)", mp,
            d(max_abs((s.inertia_space(x.O, I) * omega - s.inertia_space(O0, I) * omega0).eval())));
    }
    // Manakov, n = 3..6 (horizons as in properties/s2_2_manakov/manakov_flow.cpp).
    const int n = 3 + c % 4;
    const auto a = dr.manakov_a<T>(n);
    const MatX<T> M0 = dr.skew<T>(n, T(1) / T(2));
    const auto tr0 = spectral::power_traces<T>(M0, n);
    const VecX<T> ev0 = spectral::skew_spectrum<T>(M0);
    for (const auto& x : dyn::subject_manakov(s, dyn::diag_of(a), ManakovState<T>{M0, MatX<T>::Identity(n, n)},
                                              dyn::times_to(mp ? T(1) : T(10), 5))) {
      const auto tr = spectral::power_traces<T>(x.M, n);
      double worst_tr = 0;
      for (int k = 2; k <= n; ++k) worst_tr = std::max(worst_tr, d(T(tr[k - 1] - tr0[k - 1])));
      w.add("tr(M^k), k = 2..n, along Manakov's flow (n = 3..6)", mp, worst_tr);
      w.add("eigenvalues of -M^2 along Manakov's flow", mp, d(max_abs((spectral::skew_spectrum<T>(x.M) - ev0).eval())));
      w.add("O M O^T along Manakov's flow", mp, d(max_abs((x.O * x.M * x.O.transpose() - M0).eval())));
      w.add("energy -tr(Omega M)/4 along Manakov's flow", mp,
            d(T(dyn::manakov_energy(a, x.M) - dyn::manakov_energy(a, M0))));
    }
  }
}

template <class T>
void kept_by_integrators(Worst& w, int cases) {
  const bool mp = !std::is_same_v<T, double>;
  const Subject<T>& s = *reference_subject().get<T>();
  Draw dr;
  for (int c = 0; c < cases; ++c) {
    const Vec3<T> I = dr.inertia<T>(), Pi0 = dr.momentum<T>();
    const Mat3<T> O0 = dr.rotation<T>();
    const int n = 3 + c % 3;
    const auto a = dr.manakov_a<T>(n);
    const MatX<T> A = dyn::diag_of(a), M0 = dr.skew<T>(n, T(1));
    for (const auto& in : s.integrators) {
      const IntegratorClaims* cl = reference_subject().claims_for(in.name);
      if (in.rigid_body_step) {
        RigidBodyState<T> x{Pi0, O0};
        for (int k = 0; k < 64; ++k) {
          x = in.rigid_body_step(I, x, T(1) / T(8));
          if (cl->casimir) w.add(in.name + ": |Pi|^2", mp, d(T(dyn::casimir(x.Pi) - dyn::casimir(Pi0))));
          if (cl->energy) w.add(in.name + ": h", mp, d(T(dyn::energy(I, x.Pi) - dyn::energy(I, Pi0))));
          if (cl->orthogonality)
            w.add(in.name + ": O^T O - Id", mp, d(max_abs((x.O.transpose() * x.O - Mat3<T>::Identity()).eval())));
          if (cl->casimir && cl->orthogonality)
            w.add(in.name + ": O Pi (not a claim flag)", mp, d(max_abs((x.O * x.Pi - O0 * Pi0).eval())));
        }
      }
      if (in.manakov_step) {
        ManakovState<T> x{M0, MatX<T>::Identity(n, n)};
        const T c2 = (M0 * M0).trace(), e0 = dyn::manakov_energy(a, M0);
        const VecX<T> ev0 = spectral::skew_spectrum<T>(M0);
        for (int k = 0; k < 32; ++k) {
          x = in.manakov_step(A, x, T(1) / T(8));
          if (cl->casimir) w.add(in.name + " (Manakov): tr(M^2)", mp, d(T((x.M * x.M).trace() - c2)));
          if (cl->energy) w.add(in.name + " (Manakov): energy", mp, d(T(dyn::manakov_energy(a, x.M) - e0)));
          if (cl->orthogonality)
            w.add(in.name + " (Manakov): O^T O - Id", mp,
                  d(max_abs((x.O.transpose() * x.O - MatX<T>::Identity(n, n)).eval())));
          if (cl->spectrum)
            w.add(in.name + " (Manakov): eigenvalues of -M^2", mp,
                  d(max_abs((spectral::skew_spectrum<T>(x.M) - ev0).eval())));
        }
      }
    }
  }
}

template <class T>
void orders(int cases) {
  const Subject<T>& s = *reference_subject().get<T>();
  Draw dr;
  for (int c = 0; c < cases; ++c) {
    const Vec3<T> I = dr.inertia<T>(), Pi0 = dr.momentum<T>();
    const Mat3<T> O0 = dr.rotation<T>();
    const RigidBodyState<T> exact = dyn::oracle_rigid_body(I, RigidBodyState<T>{Pi0, O0}, {T(1)}).front();
    for (const auto& in : s.integrators) {
      if (!in.rigid_body_step) continue;
      std::vector<double> hs, errs, floors;
      std::printf("  %-24s %-6s", in.name.c_str(), ScalarInfo<T>::name);
      for (int N : {8, 16, 32, 64, 128}) {
        RigidBodyState<T> x{Pi0, O0};
        for (int k = 0; k < N; ++k) x = in.rigid_body_step(I, x, T(1) / T(N));
        const double e = std::max(d(max_abs((x.Pi - exact.Pi).eval())), d(max_abs((x.O - exact.O).eval())));
        hs.push_back(1.0 / N), errs.push_back(e), floors.push_back(16.0 * eps_double<T>() * N);
        std::printf(" %9.3e", e);
      }
      const auto fit = conv::loglog_slope(hs, errs, floors);
      std::printf("   slope %.4f (%d points)\n", fit.slope, fit.used);
    }
  }
}

template <class T>
void manakov_orders(int cases) {
  const Subject<T>& s = *reference_subject().get<T>();
  Draw dr;
  for (int c = 0; c < cases; ++c) {
    const int n = 3 + c % 2;
    const auto a = dr.manakov_a<T>(n);
    const MatX<T> A = dyn::diag_of(a), M0 = dr.skew<T>(n, T(1));
    const ManakovState<T> x0{M0, MatX<T>::Identity(n, n)};
    const ManakovState<T> exact = dyn::oracle_manakov(a, x0, {T(1)}).front();
    for (const auto& in : s.integrators) {
      if (!in.manakov_step) continue;
      std::vector<double> hs, errs, floors;
      std::printf("  %-24s %-6s n = %d", in.name.c_str(), ScalarInfo<T>::name, n);
      for (int N : {8, 16, 32, 64}) {
        ManakovState<T> x = x0;
        for (int k = 0; k < N; ++k) x = in.manakov_step(A, x, T(1) / T(N));
        const double e = std::max(d(max_abs((x.M - exact.M).eval())), d(max_abs((x.O - exact.O).eval())));
        hs.push_back(1.0 / N), errs.push_back(e), floors.push_back(16.0 * eps_double<T>() * N * n);
        std::printf(" %9.3e", e);
      }
      const auto fit = conv::loglog_slope(hs, errs, floors);
      std::printf("   slope %.4f (%d points)\n", fit.slope, fit.used);
    }
  }
}

void elliptic_vs_taylor() {
  Draw dr;
  double worst = 0;
  for (int c = 0; c < 20; ++c) {
    const Vec3<Real50> I = dr.inertia<Real50>(), P = dr.momentum<Real50>();
    const oracle::FreeRigidBodySolution<Real50> sol({I(0), I(1), I(2)}, {P(0), P(1), P(2)});
    const auto times = dyn::times_to(Real50(20), 20);
    oracle::FreeRigidBodyField<Real50> f(I(0), I(1), I(2));
    oracle::TaylorSolver<Real50, decltype(f)> ts(f, 3, Real50("1e-50"));
    const auto xs = ts.sample({P(0), P(1), P(2)}, Real50(0), times);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const auto p = sol(times[i]);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, d(Real50(p[k] - xs[i][k])));
    }
  }
  std::printf("  20 random triaxial bodies, t <= 20, 50 digits: worst |elliptic - Taylor| = %.3e\n", worst);
}

void print(const Worst& w) {
  std::printf("  %-58s %12s %12s  %s\n", "quantity", "double", "50 digits", "<= 1e-40 in 50 digits");
  for (const auto& q : w.order) {
    const auto [dd, mm] = w.by.at(q);
    std::printf("  %-58s %12.3e %12.3e  %s\n", q.c_str(), dd, mm, mm <= 1e-40 ? "yes" : "NO");
  }
}

}  // namespace
}  // namespace gm

int main(int argc, char** argv) {
  const int cd = argc > 1 ? std::atoi(argv[1]) : 20;
  const int cm = argc > 2 ? std::atoi(argv[2]) : 4;
  using namespace gm;
  std::printf("Conserved quantities along the flows the properties use (%d cases in double, %d in 50 digits)\n", cd,
              cm);
  Worst w;
  conserved_along_flows<double>(w, cd);
  conserved_along_flows<Real50>(w, cm);
  print(w);
  std::printf("\nWhat each integrator keeps (claimed invariants; 64 steps of h = 1/8, Manakov 32 steps, n = 3..5)\n");
  Worst wi;
  kept_by_integrators<double>(wi, cd);
  kept_by_integrators<Real50>(wi, cm);
  print(wi);
  std::printf("\nMeasured orders: max error at t = 1 against the Taylor oracle for h = 1/8 .. 1/128\n");
  orders<double>(2);
  orders<Real50>(2);
  std::printf("\nMeasured orders on Manakov's equations (h = 1/8 .. 1/64)\n");
  manakov_orders<double>(2);
  manakov_orders<Real50>(2);
  std::printf("\nThe exact elliptic solution against the Taylor oracle\n");
  elliptic_vs_taylor();
  return 0;
}
