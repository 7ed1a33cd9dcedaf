#include "harness/work_precision.hpp"

#include "harness/reference_flow.hpp"
#include "harness/verdict_io.hpp"
#include "impl/integrators.hpp"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace gm::harness {

namespace {

constexpr double kTime = 4.0;        // the error is measured at t = 4
constexpr int kLevels = 10;          // 4 * 2^k steps, k = 0..9: h = 1 ... 1/512
constexpr double kLongStep = 0.25;   // long-time energy: h = 1/4
constexpr int kLongSteps = 1 << 15;  // t to 8192

const char* kFigureSteps = "work-precision: error against steps";
const char* kFigureEvals = "work-precision: error against vector-field evaluations";
const char* kFigureTime = "work-precision: error against wall time";
const char* kFigureEnergy = "long-time energy (log t)";

using Step = std::function<RigidBodyState<double>(const Vec3<double>&, const RigidBodyState<double>&, const double&)>;

struct Method {
  std::string name;
  std::string source;  // "subject" or "suite"
  Step step;           // empty for the adaptive Odeint method
  int evals_per_step;  // vector-field evaluations per step; 0 when not known (implicit, splitting, the subject's)
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double error_against(const RigidBodyState<double>& x, const RigidBodyState<Real50>& ref) {
  double e = 0;
  for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(x.Pi(k) - ref.Pi(k).convert_to<double>()));
  for (int k = 0; k < 9; ++k) e = std::max(e, std::abs(x.O(k / 3, k % 3) - ref.O(k / 3, k % 3).convert_to<double>()));
  return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
}

struct Run {
  long steps = 0;
  long evals = 0;  // 0: not known
  double seconds = 0;
  double error = 0;
};

// One run to t = 4 in n steps. A run shorter than 5 ms is repeated (up to 1000 times) and the
// mean time kept, so that the clock's resolution does not decide the short runs.
Run fixed_step_run(const Method& m, int n, const RigidBodyState<Real50>& ref) {
  const Vec3<double> I = portrait_inertia<double>();
  const double h = kTime / n;
  RigidBodyState<double> x;
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  do {
    x = portrait_start<double>();
    for (int i = 0; i < n; ++i) x = m.step(I, x, h);
    ++reps;
  } while (seconds_since(t0) < 5e-3 && reps < 1000);
  Run r;
  r.seconds = seconds_since(t0) / reps;
  r.steps = n;
  r.evals = static_cast<long>(m.evals_per_step) * n;
  r.error = error_against(x, ref);
  return r;
}

// Boost.Odeint: the controlled Dormand-Prince 5(4) stepper, absolute and relative tolerance tol,
// on (Pi, O) packed in 12 numbers; steps and right-hand-side calls counted.
Run odeint_run(double tol, const RigidBodyState<Real50>& ref) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 12>;
  const Vec3<double> I = portrait_inertia<double>();
  long evals = 0, steps = 0;
  auto field = [&](const State& y, State& dy, double) {
    ++evals;
    RigidBodyState<double> x;
    for (int k = 0; k < 3; ++k) x.Pi(k) = y[k];
    for (int k = 0; k < 9; ++k) x.O(k / 3, k % 3) = y[3 + k];
    const RigidBodyState<double> d = ref::rigid_body_field<double>(I, x);
    for (int k = 0; k < 3; ++k) dy[k] = d.Pi(k);
    for (int k = 0; k < 9; ++k) dy[3 + k] = d.O(k / 3, k % 3);
  };
  State y{};
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  do {
    const RigidBodyState<double> x0 = portrait_start<double>();
    for (int k = 0; k < 3; ++k) y[k] = x0.Pi(k);
    for (int k = 0; k < 9; ++k) y[3 + k] = x0.O(k / 3, k % 3);
    evals = 0;
    steps = static_cast<long>(odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(tol, tol),
                                                         field, y, 0.0, kTime, 0.01));
    ++reps;
  } while (seconds_since(t0) < 5e-3 && reps < 1000);
  Run r;
  r.seconds = seconds_since(t0) / reps;
  r.steps = steps;
  r.evals = evals;
  RigidBodyState<double> x;
  for (int k = 0; k < 3; ++k) x.Pi(k) = y[k];
  for (int k = 0; k < 9; ++k) x.O(k / 3, k % 3) = y[3 + k];
  r.error = error_against(x, ref);
  return r;
}

Series series(const char* figure, const std::string& name, const char* x_label, bool log_x = true) {
  Series s;
  s.figure = figure;
  s.name = name;
  s.x_label = x_label;
  s.y_label = std::string(figure) == kFigureEnergy ? "|H - H0| / H0" : "max error in Pi and O at t = 4";
  s.log_x = log_x;
  s.log_y = true;
  return s;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string run_work_precision(const std::vector<Method>& methods) {
  Verdict v;
  v.property = "work-precision";
  v.scalar = "double";
  v.title = "work-precision diagram and long-time energy, against the suite's methods";
  const std::vector<Real50> at{Real50(kTime)};
  const RigidBodyState<Real50> ref =
      reference_rigid_body(portrait_inertia<Real50>(), portrait_start<Real50>(), Real50(0), at).front();

  // The cheapest run of each method reaching an error of 1e-6: the figure the message quotes.
  const double target = 1e-6;
  std::map<std::string, Run> cheapest;
  auto consider = [&](const std::string& name, const Run& r) {
    if (r.error <= target && (!cheapest.count(name) || r.seconds < cheapest[name].seconds)) cheapest[name] = r;
  };
  auto record = [&](const std::string& label, const std::vector<Run>& runs) {
    Series st = series(kFigureSteps, label, "steps"), ev = series(kFigureEvals, label, "vector-field evaluations"),
           tm = series(kFigureTime, label, "wall time [s]");
    for (const Run& r : runs) {
      st.points.emplace_back(static_cast<double>(r.steps), r.error);
      tm.points.emplace_back(r.seconds, r.error);
      if (r.evals > 0) ev.points.emplace_back(static_cast<double>(r.evals), r.error);
      consider(label, r);
    }
    v.series.push_back(st);
    if (!ev.points.empty()) v.series.push_back(ev);
    v.series.push_back(tm);
  };
  for (const Method& m : methods) {
    std::vector<Run> runs;
    for (int k = 0; k < kLevels; ++k) {
      runs.push_back(fixed_step_run(m, 4 << k, ref));
      if (!std::isfinite(runs.back().error)) break;
    }
    record(m.source + ": " + m.name, runs);
  }
  {
    std::vector<Run> runs;
    for (int e = 2; e <= 13; ++e) runs.push_back(odeint_run(std::pow(10.0, -e), ref));
    record("suite: odeint runge_kutta_dopri5 (adaptive)", runs);
  }

  // Long-time energy, sampled at about 40 points per decade of t.
  const Vec3<double> I = portrait_inertia<double>();
  for (const Method& m : methods) {
    Series en = series(kFigureEnergy, m.source + ": " + m.name, "t");
    RigidBodyState<double> x = portrait_start<double>();
    const double H0 = (x.Pi.cwiseProduct(x.Pi).cwiseQuotient(I)).sum() / 2;
    double next = 1;
    for (int i = 1; i <= kLongSteps; ++i) {
      x = m.step(I, x, kLongStep);
      if (i < next) continue;
      next = std::max(next + 1, next * 1.06);
      const double H = (x.Pi.cwiseProduct(x.Pi).cwiseQuotient(I)).sum() / 2;
      en.points.emplace_back(i * kLongStep, std::abs(H - H0) / H0);
      if (!std::isfinite(H)) break;
    }
    v.series.push_back(en);
  }

  std::ostringstream msg;
  msg << "error at t = 4 against wall time, steps and vector-field evaluations (figures/work-precision.csv); cheapest "
         "run reaching an error of 1e-6:";
  for (const auto& [name, r] : cheapest)
    msg << " " << name << " " << sci(r.seconds * 1e3) << " ms (" << r.steps << " steps" << (r.evals ? ", " + std::to_string(r.evals) + " evaluations" : "") << ");";
  if (cheapest.empty()) msg << " none;";
  msg << " long-time energy over " << kLongSteps << " steps of h = 1/4 on log axes";
  v.message = msg.str();
  v.outcome = Outcome::Pass;
  return verdicts_to_string({v});
}

}  // namespace

std::optional<PortraitTask> work_precision_task(const SubjectSet& s, const CheckConfig& cfg) {
  if (!s.d) return std::nullopt;
  if (std::find(cfg.scalars.begin(), cfg.scalars.end(), ScalarKind::Double) == cfg.scalars.end()) return std::nullopt;
  std::vector<std::string> names;
  for (const auto& in : s.d->integrators)
    if (in.rigid_body_step && (cfg.integrator.empty() || in.name == cfg.integrator)) names.push_back(in.name);
  if (names.empty()) return std::nullopt;
  const Subject<double>* sub = s.d.get();
  PortraitTask t;
  t.scalar = "double";
  t.property = "work-precision";
  t.run = [sub, names]() {
    std::vector<Method> methods;
    for (const auto& in : sub->integrators)
      if (std::find(names.begin(), names.end(), in.name) != names.end())
        methods.push_back({in.name, "subject", in.rigid_body_step, 0});
    methods.push_back({"rk4", "suite", ref::rk4_step<double>, 4});
    methods.push_back({"implicit_midpoint", "suite", ref::implicit_midpoint_step<double>, 0});
    methods.push_back({"lie_poisson_splitting", "suite", ref::lie_poisson_splitting_step<double>, 0});
    return run_work_precision(methods);
  };
  return t;
}

std::string work_precision_csv(const CheckResult& r) {
  const Verdict* wp = nullptr;
  for (const auto& p : r.portraits)
    if (p.property == "work-precision") wp = &p;
  if (!wp) return {};
  // The steps series fixes the rows; evaluations and times are matched by method and position.
  std::map<std::string, const Series*> evals, times;
  for (const auto& s : wp->series) {
    if (s.figure == kFigureEvals) evals[s.name] = &s;
    if (s.figure == kFigureTime) times[s.name] = &s;
  }
  std::ostringstream csv;
  csv << "method,source,steps,vector_field_evaluations,seconds,error_at_t4\n";
  char buf[64];
  auto num = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return std::string(buf);
  };
  for (const auto& s : wp->series) {
    if (s.figure != kFigureSteps) continue;
    const auto colon = s.name.find(": ");
    const std::string source = s.name.substr(0, colon), method = s.name.substr(colon + 2);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Series* e = evals.count(s.name) ? evals[s.name] : nullptr;
      const Series* t = times.count(s.name) ? times[s.name] : nullptr;
      csv << '"' << method << "\"," << source << "," << static_cast<long>(s.points[i].first) << ","
          << (e && i < e->points.size() ? std::to_string(static_cast<long>(e->points[i].first)) : "") << ","
          << (t && i < t->points.size() ? num(t->points[i].first) : "") << "," << num(s.points[i].second) << "\n";
    }
  }
  return csv.str();
}

}  // namespace gm::harness
