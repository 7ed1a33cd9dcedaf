// Property throughput: random cases checked per second, for the same property in
// double, in 50 digits and in exact rationals, in one run, so the three read as ratios.
//
// Representative properties: one cheap identity (the hat map is a Lie-algebra isomorphism:
// a few 3x3 products) and one heavy one (the Jacobi identity of the Lie-Poisson bracket (3.6) for
// random degree-4 polynomials, with certified derivatives of the subject's bracket).
//
// Run: cmake --build build --target property_benchmark && build/bin/property_benchmark
#include "impl/reference_subject.hpp"
#include "properties/runner.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

void run_cases(benchmark::State& state, const char* property, gm::ScalarKind k) {
  const gm::Property* p = gm::find_property(property);
  if (!p) {
    state.SkipWithError((std::string("no property ") + property).c_str());
    return;
  }
  const int cases = static_cast<int>(state.range(0));
  gm::RunOptions o;
  o.cases = cases;
  o.honour_rc_params = false;
  long total = 0;
  for (auto _ : state) {
    for (const auto& v : gm::run_property(*p, gm::reference_subject(), k, o)) {
      if (v.outcome != gm::Outcome::Pass) state.SkipWithError("the reference failed the property");
      total += v.cases;
    }
  }
  state.counters["cases_per_s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}

#define GM_THROUGHPUT(name, property, kind, cases)                                 \
  void name(benchmark::State& s) { run_cases(s, property, gm::ScalarKind::kind); } \
  BENCHMARK(name)->Arg(cases)->Unit(benchmark::kMillisecond)->MinTime(1.0)

GM_THROUGHPUT(hat_isomorphism_double, "hat_is_lie_algebra_isomorphism", Double, 1000);
GM_THROUGHPUT(hat_isomorphism_mp50, "hat_is_lie_algebra_isomorphism", MP50, 1000);
GM_THROUGHPUT(hat_isomorphism_exact, "hat_is_lie_algebra_isomorphism", Exact, 1000);
GM_THROUGHPUT(lie_poisson_jacobi_double, "lie_poisson_3_6_jacobi", Double, 100);
GM_THROUGHPUT(lie_poisson_jacobi_mp50, "lie_poisson_3_6_jacobi", MP50, 100);
GM_THROUGHPUT(lie_poisson_jacobi_exact, "lie_poisson_3_6_jacobi", Exact, 100);

}  // namespace

BENCHMARK_MAIN();
