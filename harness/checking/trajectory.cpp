#include "harness/checking/trajectory.hpp"

#include "harness/checking/first_fix.hpp"
#include "harness/checking/integrator_verdicts.hpp"

#include "harness/trajectories/reference_flow.hpp"

#include "properties/support/loglog_fit.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {
double norm2(const std::array<double, 3>& v) { return v[0] * v[0] + v[1] * v[1] + v[2] * v[2]; }
}  // namespace

namespace {

// Measured quantities of one trajectory against its reference.
struct Analysis {
  Trajectory tr;
  double roundoff = 0;  // relative size below which a residual is round-off for this file
  std::vector<double> casimir, energy, orthogonality, det, spatial, error_Pi, error_O;
  double max_casimir = 0, max_energy = 0, max_orth = 0, max_det = 0, max_spatial = 0, max_error = 0;
  double scale_Pi = 1;
};

Analysis analyse(Trajectory tr) {
  Analysis a;
  a.tr = std::move(tr);
  const Trajectory& t = a.tr;
  const double eps = std::numeric_limits<double>::epsilon();
  const double eps_data = std::max(eps, 0.5 * std::pow(10.0, 1 - t.digits));
  const double steps = (t.rows.back().t - t.rows.front().t) / t.step;
  // Round-off level: printing error of a few units in the last printed digit, plus a rounding
  // error per step that at worst adds up linearly (4 eps per step).
  a.roundoff = 64 * eps_data + 4 * std::max(1.0, steps) * eps;

  double I[3];
  for (int k = 0; k < 3; ++k) I[k] = from_decimal<double>(t.inertia[k]);
  const auto& r0 = t.rows.front();
  const double C0 = norm2(r0.Pi);
  const double H0 = (r0.Pi[0] * r0.Pi[0] / I[0] + r0.Pi[1] * r0.Pi[1] / I[1] + r0.Pi[2] * r0.Pi[2] / I[2]) / 2;
  const double Cs = C0 > 0 ? C0 : 1, Hs = H0 > 0 ? H0 : 1;
  a.scale_Pi = std::max({std::abs(r0.Pi[0]), std::abs(r0.Pi[1]), std::abs(r0.Pi[2])});
  if (a.scale_Pi == 0) a.scale_Pi = 1;
  std::array<double, 3> pi0{};
  if (t.has_O)
    for (int i = 0; i < 3; ++i)
      pi0[i] = r0.O[3 * i] * r0.Pi[0] + r0.O[3 * i + 1] * r0.Pi[1] + r0.O[3 * i + 2] * r0.Pi[2];

  // The reference, in 50 digits, from the initial state exactly as written.
  Vec3<Real50> Iq;
  for (int k = 0; k < 3; ++k) Iq(k) = from_decimal<Real50>(t.inertia[k]);
  RigidBodyState<Real50> x0{Vec3<Real50>::Zero(), Mat3<Real50>::Identity()};
  for (int k = 0; k < 3; ++k) x0.Pi(k) = from_decimal<Real50>(t.first_row[1 + k]);
  if (t.has_O)
    for (int k = 0; k < 9; ++k) x0.O(k / 3, k % 3) = from_decimal<Real50>(t.first_row[4 + k]);
  const Real50 t0 = from_decimal<Real50>(t.first_row[0]);
  std::vector<Real50> times;
  for (std::size_t i = 0; i < t.rows.size(); ++i) times.push_back(i == 0 ? t0 : Real50(t.rows[i].t));
  std::vector<RigidBodyState<Real50>> ref;
  try {
    ref = reference_rigid_body(Iq, x0, t0, times);
  } catch (const std::exception& e) {
    throw TrajectoryError(t.path + ": the reference solution cannot be computed: " + e.what());
  }

  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    const double C = norm2(r.Pi);
    const double H = (r.Pi[0] * r.Pi[0] / I[0] + r.Pi[1] * r.Pi[1] / I[1] + r.Pi[2] * r.Pi[2] / I[2]) / 2;
    a.casimir.push_back(std::abs(C - C0) / Cs);
    a.energy.push_back(std::abs(H - H0) / Hs);
    double e = 0;
    for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(r.Pi[k] - ref[i].Pi(k).convert_to<double>()));
    a.error_Pi.push_back(e / a.scale_Pi);
    if (t.has_O) {
      double orth = 0, eo = 0;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
          double s = 0;
          for (int k = 0; k < 3; ++k) s += r.O[3 * k + p] * r.O[3 * k + q];
          orth = std::max(orth, std::abs(s - (p == q ? 1.0 : 0.0)));
          eo = std::max(eo, std::abs(r.O[3 * p + q] - ref[i].O(p, q).convert_to<double>()));
        }
      const auto& O = r.O;
      const double det =
          O[0] * (O[4] * O[8] - O[5] * O[7]) - O[1] * (O[3] * O[8] - O[5] * O[6]) + O[2] * (O[3] * O[7] - O[4] * O[6]);
      double sp = 0;
      for (int p = 0; p < 3; ++p) {
        const double pi = O[3 * p] * r.Pi[0] + O[3 * p + 1] * r.Pi[1] + O[3 * p + 2] * r.Pi[2];
        sp = std::max(sp, std::abs(pi - pi0[p]));
      }
      a.orthogonality.push_back(orth);
      a.det.push_back(std::abs(det - 1));
      a.spatial.push_back(sp / a.scale_Pi);
      a.error_O.push_back(eo);
    }
  }
  auto mx = [](const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); };
  a.max_casimir = mx(a.casimir);
  a.max_energy = mx(a.energy);
  a.max_orth = std::max(mx(a.orthogonality), mx(a.det));
  a.max_det = mx(a.det);
  a.max_spatial = mx(a.spatial);
  a.max_error = std::max(mx(a.error_Pi), mx(a.error_O));
  return a;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

Series series_of(const std::string& figure, const std::string& name, const std::string& y_label, const Trajectory& t,
                 const std::vector<double>& y) {
  Series s;
  s.figure = figure;
  s.name = name;
  s.x_label = "t";
  s.y_label = y_label;
  s.log_y = true;
  const std::size_t stride = std::max<std::size_t>(1, t.rows.size() / 400);  // at most ~400 points per curve
  for (std::size_t i = 0; i < t.rows.size(); i += stride) s.points.emplace_back(t.rows[i].t, y[i]);
  if ((t.rows.size() - 1) % stride) s.points.emplace_back(t.rows.back().t, y.back());
  return s;
}

}  // namespace

namespace {

// The same warning for several files is said once, naming them.
std::vector<std::string> warnings_of(const std::vector<Analysis>& runs) {
  std::vector<std::pair<std::string, std::string>> seen;
  for (const auto& a : runs)
    for (const auto& w : a.tr.warnings) {
      auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& x) { return x.first == w; });
      const std::string file = fs::path(a.tr.path).filename().string();
      if (it == seen.end())
        seen.push_back({w, file});
      else
        it->second += ", " + file;
    }
  std::vector<std::string> out;
  for (const auto& [w, files] : seen) out.push_back(files + ": " + w);
  return out;
}

// A verdict on one file (its run).
Verdict run_verdict(const std::string& subject, const Analysis& a, const std::string& id, const std::string& spec,
                    const std::string& title) {
  Verdict v;
  v.subject = subject;
  v.property = id;
  v.spec = spec;
  v.title = title;
  v.scalar = "double";
  v.integrator = fs::path(a.tr.path).stem().string();
  v.cases = 1;
  return v;
}

// An invariant: measured always; a failure only when it was claimed and is above round-off.
Verdict invariant_verdict(const std::string& subject, const TrajectoryCheckOptions& o, const Analysis& a,
                          const std::string& claim, const std::string& id, const std::string& spec,
                          const std::string& title, double measured, const std::string& what) {
  Verdict v = run_verdict(subject, a, id, spec, title);
  const bool claimed = o.preserves.count(claim) > 0;
  const bool holds = measured <= a.roundoff;
  const std::string evidence = "max " + what + " = " + sci(measured) + " over " + std::to_string(a.tr.rows.size()) +
                               " rows; round-off level for this file " + sci(a.roundoff) + " (" +
                               std::to_string(a.tr.digits) + " digits printed)";
  v.claims.push_back(ClaimFinding{claim, claimed, holds, evidence});
  v.outcome = claimed && !holds ? Outcome::Fail : Outcome::Pass;
  v.message =
      (claimed ? (holds ? "claimed and conserved to round-off: " : "false claim: not conserved to round-off: ")
               : (holds ? "conserved to round-off (not claimed): " : "not conserved to round-off (not claimed): ")) +
      evidence;
  v.worst_absolute = measured;
  v.worst_eps_units = measured / std::numeric_limits<double>::epsilon();
  v.checks = static_cast<long>(a.tr.rows.size());
  return v;
}

// Agreement with the reference solution: a solution of other equations (a sign error, a wrong
// inertia) drifts away at order one.
Verdict reference_verdict(const std::string& subject, const TrajectoryCheckOptions& o, const Analysis& a) {
  const std::string run = fs::path(a.tr.path).stem().string();
  Verdict v = run_verdict(subject, a, "trajectory_reference", "s3.euler-momentum-form",
                          std::string("agrees with the free rigid body (3.8)") + (a.tr.has_O ? " and (2.10)" : "") +
                              " from the same initial state, to the tolerance");
  v.worst_absolute = a.max_error;
  const bool ok = a.max_error <= o.tolerance;
  v.outcome = ok ? Outcome::Pass : Outcome::Fail;
  std::size_t worst = 0;
  for (std::size_t i = 0; i < a.error_Pi.size(); ++i)
    if (a.error_Pi[i] > a.error_Pi[worst]) worst = i;
  v.message = "max error against the 50-digit reference " + sci(a.max_error) + " (relative to |Pi(0)|" +
              std::string(a.tr.has_O ? ", and in O" : "") + "); allowed " + sci(o.tolerance) + " (--tolerance)";
  if (!ok) {
    const auto& row = a.tr.rows[worst];
    v.message += "\nthe largest error in Pi is at t = " + to_string_full(row.t) + ": the file has Pi = (" +
                 to_string_full(row.Pi[0]) + ", " + to_string_full(row.Pi[1]) + ", " + to_string_full(row.Pi[2]) +
                 "); a sign error in Euler's equations or a wrong inertia shows up this way";
  }
  v.series.push_back(series_of("error against the reference", run + ": Pi", "error / |Pi(0)|", a.tr, a.error_Pi));
  if (a.tr.has_O)
    v.series.push_back(series_of("error against the reference", run + ": O", "error / |Pi(0)|", a.tr, a.error_O));
  return v;
}

// Every verdict on one run, its pictures and its row among the integrators.
void check_one_run(CheckResult& r, const TrajectoryCheckOptions& o, const Analysis& a) {
  const std::string run = fs::path(a.tr.path).stem().string();
  r.verdicts.push_back(invariant_verdict(
      r.subject, o, a, "casimir", "trajectory_casimir", "s3.nambu-rigid-body-level-sets",
      "|Pi|^2 stays constant (the motion stays on its sphere)", a.max_casimir, "||Pi|^2 - |Pi(0)|^2| / |Pi(0)|^2"));
  r.verdicts.push_back(
      invariant_verdict(r.subject, o, a, "energy", "trajectory_energy", "s3.nambu-rigid-body-level-sets",
                        "the energy h = Pi . I^-1 Pi / 2 stays constant", a.max_energy, "|h - h(0)| / h(0)"));
  if (a.tr.has_O) {
    r.verdicts.push_back(invariant_verdict(r.subject, o, a, "orthogonality", "trajectory_orthogonality",
                                           "s2.reconstruction", "O stays in SO(3): O^T O = Id and det O = 1",
                                           a.max_orth, "max(|O^T O - Id|, |det O - 1|)"));
    r.verdicts.push_back(invariant_verdict(r.subject, o, a, "spatial_momentum", "trajectory_spatial_momentum",
                                           "s2.noether",
                                           "the spatial angular momentum pi = O Pi stays constant (Noether)",
                                           a.max_spatial, "|O Pi - O(0) Pi(0)| / |Pi(0)|"));
  }
  r.verdicts.push_back(reference_verdict(r.subject, o, a));
  // Pictures of the invariants over time.
  Verdict pic = run_verdict(r.subject, a, "portrait", "", "invariants over time");
  pic.outcome = Outcome::Pass;
  pic.series.push_back(series_of("invariants over time", run + ": |Pi|^2", "relative residual", a.tr, a.casimir));
  pic.series.push_back(series_of("invariants over time", run + ": energy", "relative residual", a.tr, a.energy));
  if (a.tr.has_O)
    pic.series.push_back(
        series_of("invariants over time", run + ": O^T O - Id", "relative residual", a.tr, a.orthogonality));
  r.portraits.push_back(pic);

  IntegratorInfo info;
  info.name = run;
  info.has_claims = !o.preserves.empty();
  info.claims.integrator = run;
  info.claims.casimir = o.preserves.count("casimir") > 0;
  info.claims.energy = o.preserves.count("energy") > 0;
  info.claims.orthogonality = o.preserves.count("orthogonality") > 0;
  info.steps = {"trajectory file, step " + sci(a.tr.step) + (a.tr.method.empty() ? "" : ", " + a.tr.method)};
  info.scalars = {"double"};
  r.integrators.push_back(info);
}

// Runs compared for the order are of one motion: one inertia, one Pi(0), O in all or none, and
// different steps.
void refuse_unlike_runs(const std::vector<Analysis>& runs) {
  const Trajectory& first = runs.front().tr;
  for (const auto& a : runs) {
    if (a.tr.inertia != first.inertia)
      throw TrajectoryError(a.tr.path + ": a different inertia than " + first.path +
                            "; runs compared for the order must be of one motion");
    if (a.tr.has_O != first.has_O)
      throw TrajectoryError(a.tr.path + ": O is given in one file and not in the other; compare like with like");
    for (int k = 1; k < 4; ++k)
      if (std::abs(a.tr.rows.front().Pi[k - 1] - first.rows.front().Pi[k - 1]) >
          1e-12 * std::max(1.0, std::abs(first.rows.front().Pi[k - 1])))
        throw TrajectoryError(a.tr.path + ": starts from a different Pi(0) than " + first.path);
  }
  std::map<double, int> steps;
  for (const auto& a : runs) ++steps[a.tr.step];
  for (const auto& [h, n] : steps)
    if (n > 1)
      throw TrajectoryError("two files have the same step size " + sci(h) + "; the order needs different steps");
}

// Convergence: several runs of one motion at different step sizes, judged by the suite's one
// log-log fit (properties/support/loglog_fit.hpp).
void check_order(CheckResult& r, const TrajectoryCheckOptions& o, const std::vector<Analysis>& runs) {
  refuse_unlike_runs(runs);
  // Error at the common final time (the latest time every run reaches), largest over rows up to it.
  double T = runs.front().tr.rows.back().t;
  for (const auto& a : runs) T = std::min(T, a.tr.rows.back().t);
  std::vector<std::pair<double, double>> pts;
  double plateau = 0;
  for (const auto& a : runs) {
    double e = 0;
    for (std::size_t i = 0; i < a.tr.rows.size() && a.tr.rows[i].t <= T * (1 + 1e-12); ++i)
      e = std::max({e, a.error_Pi[i], a.tr.has_O ? a.error_O[i] : 0.0});
    pts.emplace_back(a.tr.step, e);
    plateau = std::max(plateau, 16 * a.roundoff);
  }
  std::sort(pts.begin(), pts.end());
  // The suite's one log-log fit takes the steps from the largest down.
  std::vector<double> hs, errs;
  for (auto p = pts.rbegin(); p != pts.rend(); ++p) hs.push_back(p->first), errs.push_back(p->second);
  const conv::SlopeFit fit = conv::loglog_slope(hs, errs, std::vector<double>(hs.size(), plateau));
  std::vector<bool> used(fit.point.rbegin(), fit.point.rend());
  const double slope = fit.measured() ? fit.slope : std::nan("");
  Verdict v;
  v.subject = r.subject;
  v.property = "trajectory_order";
  v.spec = "";
  v.title = "convergence order: log-log slope of the error up to t = " + sci(T) + " against the step size";
  v.scalar = "double";
  v.integrator = "all runs";
  v.cases = static_cast<int>(runs.size());
  int n_used = 0;
  for (bool u : used) n_used += u;
  std::ostringstream m;
  m << "measured slope " << (std::isnan(slope) ? std::string("(not measurable)") : sci(slope)) << " from " << n_used
    << " of " << pts.size() << " step sizes (errors at or below the round-off plateau " << sci(plateau)
    << " left out, and every smaller step after one):";
  for (std::size_t i = 0; i < pts.size(); ++i)
    m << "\n  h = " << sci(pts[i].first) << ": error " << sci(pts[i].second) << (used[i] ? "" : " (left out)");
  const bool claimed = o.order > 0;
  const bool measurable = !std::isnan(slope) && n_used >= 2;
  // Exact for this problem: every error at round-off, so no slope, and none needed.
  const bool exact = std::all_of(pts.begin(), pts.end(),
                                 [&](const auto& p) { return std::isfinite(p.second) && p.second <= plateau; });
  const bool holds = exact || (measurable && std::abs(slope - o.order) <= 0.2);
  if (exact) m << "\nexact for this problem (error at round-off for every step size): any claimed order holds";
  if (claimed) {
    v.claims.push_back(
        ClaimFinding{"order", true, holds,
                     (exact ? std::string("exact for this problem (error at round-off for every step size)")
                            : "measured slope " + (measurable ? sci(slope) : std::string("not measurable"))) +
                         ", claimed " + std::to_string(o.order) + (exact ? "" : " (allowed difference 0.2)")});
    v.outcome = holds ? Outcome::Pass : Outcome::Fail;
    if (!measurable && !exact)
      m << "\nfewer than two step sizes lie above the round-off plateau: use larger steps to measure the order";
  } else {
    v.outcome = Outcome::Pass;
    m << "\n(no order claimed: give --order p to have it judged)";
  }
  v.message = m.str();
  Series s;
  s.figure = "convergence";
  s.name = "error up to t = " + sci(T);
  s.x_label = "step size h";
  s.y_label = "max error / |Pi(0)|";
  s.log_x = s.log_y = true;
  s.points = pts;
  s.reference_slope = o.order;
  v.series.push_back(s);
  r.verdicts.push_back(v);
  IntegratorInfo info;
  info.name = "all runs";
  info.has_claims = claimed;
  info.claims.integrator = "all runs";
  info.claims.order = o.order;
  info.steps = {"convergence over " + std::to_string(runs.size()) + " step sizes"};
  info.scalars = {"double"};
  r.integrators.push_back(info);
}

}  // namespace

CheckResult check_trajectories(const std::vector<std::string>& files, const TrajectoryCheckOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (files.empty()) throw TrajectoryError("no trajectory file given");
  for (const auto& claim : o.preserves)
    if (claim != "casimir" && claim != "energy" && claim != "orthogonality" && claim != "spatial_momentum")
      throw TrajectoryError("--preserves: unknown invariant '" + claim +
                            "' (known: casimir, energy, orthogonality, spatial_momentum)");
  std::vector<Analysis> runs;
  for (const auto& f : files) runs.push_back(analyse(read_trajectory(f, o.params)));

  CheckResult r;
  r.subject = files.size() == 1 ? fs::path(files.front()).stem().string() : "trajectories";
  r.description = runs.front().tr.method.empty() ? "trajectory files" : "trajectories of " + runs.front().tr.method;
  r.info.source = files.front();
  for (std::size_t i = 1; i < files.size(); ++i) r.info.source += ", " + files[i];
  r.selection = "the trajectory checks";
  r.info.randomised = false;
  r.info.warnings = warnings_of(runs);
  for (const auto& a : runs) check_one_run(r, o, a);
  if (runs.size() >= 2)
    check_order(r, o, runs);
  else if (o.order > 0)
    r.info.warnings.push_back("--order needs runs at several step sizes (give two or more files); it was not checked");
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  decide_integrator_verdicts(r);  // once, as a check of code does
  decide_first_fixes(r);
  return r;
}

}  // namespace gm::harness
