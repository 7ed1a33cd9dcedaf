// The exact free-rigid-body solution in double (oracle/elliptic.hpp), its accuracy and cost:
//
//   accuracy: over 1000 random bodies (moments satisfying the triangle inequality, momenta in
//   [-1, 1]^3, t in [0, 20], fixed seed), the double solution against the same formula evaluated
//   in 50 digits, in ulps: |Pi_double - Pi_50|_inf / (eps |Pi|_inf) for the state and
//   |h(Pi_double) - h_50| / (eps h) for the energy; median, 99th percentile and maximum are printed
//   before the timings (anchor: Principia's solver, <= 10 ulps on energy, ~200 on the state);
//
//   cost: one evaluation Pi(t) of a constructed solution, and the construction, in double and in
//   50 digits; side by side in the same run with the named alternative, the Taylor oracle
//   (oracle/taylor.hpp) integrating the same body from 0 to the same t in double.
//
// Run: cmake --build build --target elliptic_benchmark && build/bin/elliptic_benchmark
#include "core/scalar.hpp"
#include "oracle/elliptic.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using gm::Real50;

struct Body {
  std::array<double, 3> I, Pi;
  double t;
};

// Dyadic data (exact in both precisions): a, b, c in [1/8, 2] give I = (b + c, c + a, a + b).
std::vector<Body> random_bodies(int count) {
  std::mt19937_64 rng(20261121);
  std::uniform_int_distribution<int> abc(1, 16), pi(-64, 64), tt(0, 20 * 64);
  std::vector<Body> out;
  while (static_cast<int>(out.size()) < count) {
    const double a = abc(rng) / 8.0, b = abc(rng) / 8.0, c = abc(rng) / 8.0;
    Body body{{b + c, c + a, a + b}, {pi(rng) / 64.0, pi(rng) / 64.0, pi(rng) / 64.0}, tt(rng) / 64.0};
    if (body.Pi[0] == 0 && body.Pi[1] == 0 && body.Pi[2] == 0) continue;
    out.push_back(body);
  }
  return out;
}

template <class T>
T energy(const std::array<T, 3>& I, const std::array<T, 3>& P) {
  return P[0] * P[0] / I[0] + P[1] * P[1] / I[1] + P[2] * P[2] / I[2];
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * (v.size() - 1))];
}

void report_accuracy() {
  const auto bodies = random_bodies(1000);
  std::vector<double> state_ulps, energy_ulps;
  const double eps = std::numeric_limits<double>::epsilon();
  for (const auto& b : bodies) {
    const gm::oracle::FreeRigidBodySolution<double> d(b.I, b.Pi);
    const std::array<Real50, 3> I50{Real50(b.I[0]), Real50(b.I[1]), Real50(b.I[2])};
    const std::array<Real50, 3> P50{Real50(b.Pi[0]), Real50(b.Pi[1]), Real50(b.Pi[2])};
    const gm::oracle::FreeRigidBodySolution<Real50> m(I50, P50);
    const auto pd = d(b.t);
    const auto pm = m(Real50(b.t));
    double err = 0, size = 0;
    for (int i = 0; i < 3; ++i) {
      err = std::max(err, std::abs(pd[i] - pm[i].convert_to<double>()));
      size = std::max(size, std::abs(pm[i].convert_to<double>()));
    }
    state_ulps.push_back(err / (eps * size));
    const Real50 h50 = energy(I50, P50);  // conserved: its value at t = 0 is exact
    const double hd = energy(b.I, pd);
    energy_ulps.push_back(std::abs(hd - h50.convert_to<double>()) / (eps * h50.convert_to<double>()));
  }
  std::printf("Exact solution in double against 50 digits, 1000 random bodies, t in [0, 20]:\n");
  std::printf("  state  (|dPi|_inf / (eps |Pi|_inf)): median %.2f, p99 %.1f, max %.1f ulps\n",
              percentile(state_ulps, 0.5), percentile(state_ulps, 0.99), percentile(state_ulps, 1.0));
  std::printf("  energy (|dh| / (eps h)):             median %.2f, p99 %.1f, max %.1f ulps\n\n",
              percentile(energy_ulps, 0.5), percentile(energy_ulps, 0.99), percentile(energy_ulps, 1.0));
  std::fflush(stdout);
}

const std::vector<Body>& bench_bodies() {
  static const std::vector<Body> b = random_bodies(64);
  return b;
}

void BM_elliptic_evaluate_double(benchmark::State& state) {
  std::vector<gm::oracle::FreeRigidBodySolution<double>> sols;
  for (const auto& b : bench_bodies()) sols.emplace_back(b.I, b.Pi);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& b = bench_bodies()[i % sols.size()];
    benchmark::DoNotOptimize(sols[i % sols.size()](b.t));
    ++i;
  }
}
BENCHMARK(BM_elliptic_evaluate_double);

void BM_elliptic_construct_double(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& b = bench_bodies()[i++ % bench_bodies().size()];
    gm::oracle::FreeRigidBodySolution<double> s(b.I, b.Pi);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_elliptic_construct_double);

// The alternative: integrate to the same t with the Taylor oracle in double.
void BM_taylor_flow_double(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& b = bench_bodies()[i++ % bench_bodies().size()];
    gm::oracle::FreeRigidBodyField<double> f(b.I[0], b.I[1], b.I[2]);
    gm::oracle::TaylorSolver<double, decltype(f)> solver(f, 3, 1e-16);
    benchmark::DoNotOptimize(solver.flow({b.Pi[0], b.Pi[1], b.Pi[2]}, 0.0, b.t));
  }
}
BENCHMARK(BM_taylor_flow_double);

void BM_elliptic_evaluate_mp50(benchmark::State& state) {
  std::vector<gm::oracle::FreeRigidBodySolution<Real50>> sols;
  for (const auto& b : bench_bodies())
    sols.emplace_back(std::array<Real50, 3>{Real50(b.I[0]), Real50(b.I[1]), Real50(b.I[2])},
                      std::array<Real50, 3>{Real50(b.Pi[0]), Real50(b.Pi[1]), Real50(b.Pi[2])});
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& b = bench_bodies()[i % sols.size()];
    benchmark::DoNotOptimize(sols[i % sols.size()](Real50(b.t)));
    ++i;
  }
}
BENCHMARK(BM_elliptic_evaluate_mp50)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  report_accuracy();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
