// The golden generator's performance, measured with Google Benchmark:
//
//   1. the 40-digit trajectory of the free rigid body I = (2, 1, 2/3), Pi(0) = (cos 1.1, 0,
//      sin 1.1), sampled at t = 0.5, 1, ..., 10, in Real50 (cpp_bin_float<50>):
//        - the Taylor oracle (oracle/taylor.hpp), local tolerance 1e-48, as the generator runs it
//          (higher orders in double-double and double) and with every order in Real50;
//        - Boost.Odeint's bulirsch_stoer on the same type, abs and rel tolerance 1e-45
//          (the configuration of ../shared/TOOLCHAIN.md);
//      each with its error (max over samples and components) against an independent 70-digit
//      solution (Gragg-Bulirsch-Stoer extrapolation, golden/extrapolation.hpp, tolerance 1e-64),
//      reported as the counter `error`; the run ends with the speed ratio;
//   2. the whole fixture set generated and verified in memory, as `geomech golden regenerate`.
//
// Run: cmake --build build --target golden_benchmark && build/bin/golden_benchmark
#include "core/scalar.hpp"
#include "golden/catalogue.hpp"
#include "golden/extrapolation.hpp"
#include "golden/generate.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <boost/numeric/odeint.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

// TOOLCHAIN.md, pitfall 6: odeint's value-type extraction recurses on number<>.
namespace boost::numeric::odeint::detail {
template <>
struct extract_value_type<gm::Real50, void> {
  typedef gm::Real50 type;
};
}  // namespace boost::numeric::odeint::detail

namespace {

using gm::Real50;
using gm::Real70;

std::vector<Real50> sample_times() {
  std::vector<Real50> t;
  for (int i = 1; i <= 20; ++i) t.push_back(Real50(i) / 2);
  return t;
}

std::vector<Real50> initial_state() { return {cos(Real50("1.1")), Real50(0), sin(Real50("1.1"))}; }

// The independent reference: the same initial state (the Real50 values, exactly), integrated in
// 70 digits by extrapolation.
const std::vector<std::vector<Real70>>& reference() {
  static const std::vector<std::vector<Real70>> ref = [] {
    gm::oracle::FreeRigidBodyField<Real70> f(Real70(2), Real70(1), Real70(2) / 3);
    auto g = [&](const std::vector<Real70>& x, std::vector<Real70>& dx) { f(x.data(), dx.data()); };
    gm::golden::ExtrapolationSettings<Real70> s;
    s.columns = 14;
    s.tolerance = Real70("1e-64");
    gm::golden::ExtrapolationSolver<Real70, decltype(g)> solver(g, 3, s);
    std::vector<Real70> x0, times;
    for (const auto& v : initial_state()) x0.push_back(Real70(v));
    for (const auto& t : sample_times()) times.push_back(Real70(t));
    return solver.sample(x0, Real70(0), times);
  }();
  return ref;
}

double max_error(const std::vector<std::vector<Real50>>& got) {
  Real70 worst(0);
  for (std::size_t i = 0; i < got.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const Real70 d = abs(Real70(got[i][k]) - reference()[i][k]);
      if (d > worst) worst = d;
    }
  return worst.convert_to<double>();
}

void taylor_run(benchmark::State& state, bool mixed) {
  const auto times = sample_times();
  const auto x0 = initial_state();
  std::vector<std::vector<Real50>> out;
  long steps = 0;
  for (auto _ : state) {
    gm::oracle::FreeRigidBodyField<Real50> f(Real50(2), Real50(1), Real50(2) / 3);
    gm::oracle::TaylorSolver<Real50, decltype(f)> solver(f, 3, Real50("1e-48"));
    solver.set_mixed_precision(mixed);
    out = solver.sample(x0, Real50(0), times);
    steps = solver.stats().steps;
    benchmark::DoNotOptimize(out);
  }
  state.counters["error"] = max_error(out);
  state.counters["steps"] = static_cast<double>(steps);
}
// As the golden generator runs it: the higher orders in double-double and double.
void BM_FreeRigidBody40Digits_Taylor(benchmark::State& state) { taylor_run(state, true); }
BENCHMARK(BM_FreeRigidBody40Digits_Taylor)->Unit(benchmark::kMillisecond);
// Every order in Real50: what the mixed precision saves.
void BM_FreeRigidBody40Digits_TaylorAllReal50(benchmark::State& state) { taylor_run(state, false); }
BENCHMARK(BM_FreeRigidBody40Digits_TaylorAllReal50)->Unit(benchmark::kMillisecond);

void BM_FreeRigidBody40Digits_OdeintBulirschStoer(benchmark::State& state) {
  namespace odeint = boost::numeric::odeint;
  using State = std::vector<Real50>;
  const auto times = sample_times();
  std::vector<Real50> all_times = {Real50(0)};
  all_times.insert(all_times.end(), times.begin(), times.end());
  const Real50 c1 = Real50(3) / 2 - Real50(1), c2 = Real50(1) / 2 - Real50(3) / 2, c3 = Real50(1) - Real50(1) / 2;
  auto euler = [&](const State& x, State& dx, const Real50&) {  // (3.7), as the oracle's field
    dx[0] = x[1] * x[2] * c1;
    dx[1] = x[2] * x[0] * c2;
    dx[2] = x[0] * x[1] * c3;
  };
  std::vector<std::vector<Real50>> out;
  long steps = 0;
  for (auto _ : state) {
    out.clear();
    State x = initial_state();
    odeint::bulirsch_stoer<State, Real50> stepper(Real50("1e-45"), Real50("1e-45"));
    steps = static_cast<long>(odeint::integrate_times(stepper, euler, x, all_times.begin(), all_times.end(),
                                                      Real50("0.1"), [&](const State& s, const Real50& t) {
                                                        if (t > 0) out.push_back(s);
                                                      }));
    benchmark::DoNotOptimize(out);
  }
  state.counters["error"] = max_error(out);
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_FreeRigidBody40Digits_OdeintBulirschStoer)->Unit(benchmark::kMillisecond);

void BM_RegenerateAllFixtures(benchmark::State& state) {
  for (auto _ : state) {
    for (const auto& d : gm::golden::fixture_definitions()) {
      const auto f = gm::golden::generate(gm::golden::make_request(d));
      benchmark::DoNotOptimize(f);
    }
  }
  state.counters["fixtures"] = static_cast<double>(gm::golden::fixture_definitions().size());
}
BENCHMARK(BM_RegenerateAllFixtures)->Unit(benchmark::kSecond)->Iterations(1);

// Remembers each benchmark's real time per iteration, to print the speed ratio at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Iteration) {
        real_[r.benchmark_name()] = r.GetAdjustedRealTime();
        cpu_[r.benchmark_name()] = r.GetAdjustedCPUTime();
      }
    ConsoleReporter::ReportRuns(runs);
  }
  // Real (wall) time and CPU time: on a shared machine the CPU time is the steadier figure.
  void print_ratio() const {
    const std::string t = "BM_FreeRigidBody40Digits_Taylor", o = "BM_FreeRigidBody40Digits_OdeintBulirschStoer";
    if (!real_.count(t) || !real_.count(o) || real_.at(t) <= 0 || cpu_.at(t) <= 0) return;
    std::printf(
        "\nTaylor oracle vs odeint bulirsch_stoer (Real50, same trajectory):\n"
        "  real time %.3g ms vs %.3g ms: %.1fx faster\n  CPU time  %.3g ms vs %.3g ms: %.1fx faster\n",
        real_.at(t), real_.at(o), real_.at(o) / real_.at(t), cpu_.at(t), cpu_.at(o), cpu_.at(o) / cpu_.at(t));
    const std::string a = "BM_FreeRigidBody40Digits_TaylorAllReal50";
    if (cpu_.count(a))
      std::printf("  mixed precision vs every order in Real50: CPU time %.3g ms vs %.3g ms: %.2fx faster\n", cpu_.at(t),
                  cpu_.at(a), cpu_.at(a) / cpu_.at(t));
  }

 private:
  std::map<std::string, double> real_, cpu_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratio();
  benchmark::Shutdown();
  return 0;
}
