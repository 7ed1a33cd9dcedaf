#include "harness/checking/portrait.hpp"

#include "harness/checking/trajectory.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/trajectories/reference_flow.hpp"

#include "properties/support/loglog_fit.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace gm::harness {

namespace {

constexpr double kConvergenceTime = 1.0;
constexpr int kFinestLevel = 9;  // steps 1/4 ... 1/512
constexpr double kLongTime = 8.0;
constexpr int kLongSteps = 256;

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

template <class T>
T energy(const Vec3<T>& I, const Vec3<T>& Pi) {
  return (Pi(0) * Pi(0) / I(0) + Pi(1) * Pi(1) / I(1) + Pi(2) * Pi(2) / I(2)) / T(2);
}

template <class T>
std::string run_portrait(const Integrator<T>& in, const IntegratorClaims& claims, const std::string& scalar) {
  const Vec3<T> I = portrait_inertia<T>();
  const RigidBodyState<T> x0 = portrait_start<T>();
  Verdict v;
  v.property = "portrait";
  v.integrator = in.name;
  v.scalar = scalar;
  v.title = "pictures of the integrator";
  std::ostringstream msg;

  // Convergence: error at t = 1 against the 50-digit reference, for h = 1/4 ... 1/512.
  const std::vector<Real50> at{Real50(kConvergenceTime)};
  const auto ref = reference_rigid_body(portrait_inertia<Real50>(), portrait_start<Real50>(), Real50(0), at).front();
  Series convergence;
  convergence.figure = "convergence";
  convergence.name = "error at t = 1";
  convergence.x_label = "step size h";
  convergence.y_label = "max error in Pi and O";
  convergence.log_x = convergence.log_y = true;
  convergence.reference_slope = claims.order;
  for (int level = 2; level <= kFinestLevel; ++level) {
    const int n = 1 << level;
    const T h = T(kConvergenceTime) / T(n);
    RigidBodyState<T> x = x0;
    for (int i = 0; i < n; ++i) x = in.rigid_body_step(I, x, h);
    double err = 0;
    for (int k = 0; k < 3; ++k)
      err = std::max(err, std::abs(to_double(x.Pi(k)) - ref.Pi(k).template convert_to<double>()));
    for (int k = 0; k < 9; ++k)
      err = std::max(err, std::abs(to_double(x.O(k / 3, k % 3)) - ref.O(k / 3, k % 3).template convert_to<double>()));
    // In 50 digits the difference must be taken in 50 digits, not after rounding to double.
    if constexpr (!std::is_same_v<T, double>) {
      Real50 e50(0);
      for (int k = 0; k < 3; ++k) e50 = std::max(e50, Real50(abs(Real50(x.Pi(k)) - ref.Pi(k))));
      for (int k = 0; k < 9; ++k) e50 = std::max(e50, Real50(abs(Real50(x.O(k / 3, k % 3)) - ref.O(k / 3, k % 3))));
      err = e50.template convert_to<double>();
    }
    convergence.points.emplace_back(to_double(h), err);
    if (!std::isfinite(err)) break;
  }
  // The suite's one log-log fit (h from 1/4 down), over the errors above 1000 eps(T).
  std::vector<double> hs, errs;
  for (const auto& [h, e] : convergence.points) hs.push_back(h), errs.push_back(e);
  const conv::SlopeFit fit = conv::loglog_slope(hs, errs, std::vector<double>(hs.size(), 1e3 * eps_double<T>()));
  msg << "measured order " << (fit.measured() ? sci(fit.slope) : std::string("(not measurable)"))
      << " (log-log slope of the error at t = 1 over h = 1/4 ... 1/512, round-off plateau left out)";
  if (claims.order > 0) msg << ", claimed " << claims.order;
  v.series.push_back(convergence);

  // Invariants over a longer run.
  Series cas, en, orth;
  for (Series* s : {&cas, &en, &orth}) {
    s->figure = "invariants over time";
    s->x_label = "t";
    s->y_label = "relative residual";
    s->log_y = true;
  }
  cas.name = "|Pi|^2";
  en.name = "energy";
  orth.name = "O^T O - Id";
  const T h = T(kLongTime) / T(kLongSteps);
  const T C0 = x0.Pi.squaredNorm(), H0 = energy(I, x0.Pi);
  RigidBodyState<T> x = x0;
  double worst_c = 0, worst_e = 0, worst_o = 0;
  for (int i = 1; i <= kLongSteps; ++i) {
    x = in.rigid_body_step(I, x, h);
    const double t = to_double(T(h * T(i)));
    const double c = to_double(T(abs_value(T(x.Pi.squaredNorm() - C0)) / C0));
    const double e = to_double(T(abs_value(T(energy(I, x.Pi) - H0)) / H0));
    const double o = to_double(max_abs((x.O.transpose() * x.O - Mat3<T>::Identity()).eval()));
    cas.points.emplace_back(t, c);
    en.points.emplace_back(t, e);
    orth.points.emplace_back(t, o);
    worst_c = std::max(worst_c, c);
    worst_e = std::max(worst_e, e);
    worst_o = std::max(worst_o, o);
  }
  msg << "; over t = 8 with h = 1/32 the largest relative residuals are " << sci(worst_c) << " in |Pi|^2, "
      << sci(worst_e) << " in the energy, " << sci(worst_o) << " in O^T O - Id (eps = " << sci(eps_double<T>()) << ")";
  v.series.push_back(cas);
  v.series.push_back(en);
  v.series.push_back(orth);
  v.outcome = Outcome::Pass;
  v.message = msg.str();
  return verdicts_to_string({v});
}

}  // namespace

std::vector<PortraitTask> portrait_task_list(const SubjectSet& s, const CheckConfig& cfg) {
  std::vector<PortraitTask> tasks;
  auto add = [&](const auto* sub, ScalarKind k) {
    if (!sub) return;
    if (std::find(cfg.scalars.begin(), cfg.scalars.end(), k) == cfg.scalars.end()) return;
    for (const auto& in : sub->integrators) {
      if (!in.rigid_body_step) continue;
      if (!cfg.integrator.empty() && in.name != cfg.integrator) continue;
      const std::string name = in.name, scalar = scalar_name(k);
      IntegratorClaims claims;
      if (const IntegratorClaims* c = s.claims_for(name)) claims = *c;
      tasks.push_back(PortraitTask{name, scalar, [sub, name, claims, scalar]() {
                                     for (const auto& i : sub->integrators)
                                       if (i.name == name) return run_portrait(i, claims, scalar);
                                     return std::string("[]");
                                   }});
    }
  };
  add(s.d.get(), ScalarKind::Double);
  add(s.mp.get(), ScalarKind::MP50);
  return tasks;
}

Verdict portrait_from_task(const PortraitTask& task, const TaskResult& result) {
  Verdict v;
  v.property = task.property;
  v.integrator = task.integrator;
  v.scalar = task.scalar;
  v.seconds = result.seconds;  // where a check's time goes: the pictures are part of it
  if (result.status == TaskResult::Status::Ok) {
    try {
      auto vs = verdicts_from_string(result.payload);
      if (!vs.empty()) {
        vs.front().seconds = result.seconds;
        return vs.front();
      }
    } catch (const std::exception& e) {
      v.message = std::string("the pictures could not be read back: ") + e.what();
    }
  }
  v.outcome = result.status == TaskResult::Status::TimedOut  ? Outcome::Timeout
              : result.status == TaskResult::Status::Crashed ? Outcome::Crash
                                                             : Outcome::Error;
  if (v.message.empty()) v.message = "no pictures: drawing them " + result.detail;
  return v;
}

}  // namespace gm::harness
