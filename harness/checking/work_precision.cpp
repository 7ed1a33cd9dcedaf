#include "harness/checking/work_precision.hpp"

#include "harness/checking/verdict_io.hpp"
#include "harness/trajectories/reference_flow.hpp"
#include "impl/canonical_integrators.hpp"
#include "impl/integrators.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

namespace gm::harness {

namespace {

constexpr int kLevels = 10;          // 4 * 2^k steps to t = 4, k = 0..9: h = 1 ... 1/512
constexpr double kTime = 4.0;        // the error is measured at t = 4
constexpr int kLongSteps = 1 << 15;  // long-time energy: 2^15 steps
constexpr double kLongBudget = 10;   // seconds per method for the long run, and for its fixed-step runs
                                     // (an Octave step costs ~0.7 ms)

using State = std::vector<double>;  // a problem's state, packed
using Stepper = std::function<State(const State&, double)>;

struct Method {
  std::string name;
  std::string source;  // "subject" or "suite"
  Stepper step;
  int evals_per_step = 0;  // vector-field evaluations per step; 0 when not known (implicit, splitting, the subject's)
  // n steps at once, the state after each (an implementation behind the protocol: one round trip
  // for a chunk of the long run; core/subject.hpp's Integrator::rigid_body_run); may be empty.
  std::function<std::vector<State>(const State&, double, int)> run;
};

// One system on which steps are compared: the packed start, the 50-digit state at t = 4 (from
// the harness's reference flow or the Taylor oracle), the vector field (for Boost.Odeint) and the
// energy (for the long run).
struct Problem {
  std::string label;  // as in the figures: "rigid body", "Manakov n = 4", ...
  State x0;
  std::vector<Real50> reference;
  std::function<State(const State&)> field;
  std::function<double(const State&)> energy;
  double long_step = 0.25;
  std::vector<Method> methods;  // the subject's first, then the suite's
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// Packing: (Pi, O): Pi then O row-major; (M, O): M then O row-major; (Q, P): Q then P (row-major).
State pack(const RigidBodyState<double>& x) {
  State s(x.Pi.data(), x.Pi.data() + 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.push_back(x.O(i, j));
  return s;
}
RigidBodyState<double> unpack_rigid_body(const State& s) {
  RigidBodyState<double> x;
  for (int k = 0; k < 3; ++k) x.Pi(k) = s[k];
  for (int k = 0; k < 9; ++k) x.O(k / 3, k % 3) = s[3 + k];
  return x;
}
void append(State& s, const MatX<double>& A) {
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < A.cols(); ++j) s.push_back(A(i, j));
}
MatX<double> block(const State& s, int offset, int rows, int cols) {
  if (s.size() < static_cast<std::size_t>(offset + rows * cols))
    throw std::length_error("the step returned a state of the wrong size");
  MatX<double> A(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) A(i, j) = s[offset + i * cols + j];
  return A;
}
State pack(const MatX<double>& a, const MatX<double>& b) {
  State s;
  append(s, a);
  append(s, b);
  return s;
}

// Max-norm error; infinite for a state that is not finite or not of the problem's size.
double error_against(const State& x, const std::vector<Real50>& ref) {
  const double inf = std::numeric_limits<double>::infinity();
  if (x.size() != ref.size()) return inf;
  double e = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double d = std::abs(x[k] - ref[k].convert_to<double>());
    if (!std::isfinite(d)) return inf;
    e = std::max(e, d);
  }
  return e;
}

struct Run {
  long steps = 0;
  long evals = 0;  // 0: not known
  double seconds = 0;
  double error = 0;
  std::string failure;  // what the step threw, if it did (the error is then infinite)
};

// One run to t = 4 in n steps. A run shorter than 5 ms is repeated (up to 1000 times) and the
// mean time kept, so that the clock's resolution does not decide the short runs.
Run fixed_step_run(const Problem& p, const Method& m, int n) {
  const double h = kTime / n;
  State x;
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    do {
      x = p.x0;
      for (int i = 0; i < n; ++i) x = m.step(x, h);
      ++reps;
    } while (seconds_since(t0) < 5e-3 && reps < 1000);
  } catch (const std::exception& e) {
    return Run{n, 0, seconds_since(t0), std::numeric_limits<double>::infinity(), e.what()};
  }
  return Run{n, static_cast<long>(m.evals_per_step) * n, seconds_since(t0) / reps, error_against(x, p.reference), {}};
}

// Boost.Odeint: the controlled Dormand-Prince 5(4) stepper, absolute and relative tolerance tol;
// steps and right-hand-side calls counted.
Run odeint_run(const Problem& p, double tol) {
  namespace odeint = boost::numeric::odeint;
  long evals = 0, steps = 0;
  auto rhs = [&](const State& y, State& dy, double) {
    ++evals;
    dy = p.field(y);
  };
  State y;
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  do {
    y = p.x0;
    evals = 0;
    steps = static_cast<long>(odeint::integrate_adaptive(
        odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(tol, tol), rhs, y, 0.0, kTime, 0.01));
    ++reps;
  } while (seconds_since(t0) < 5e-3 && reps < 1000);
  return Run{steps, evals, seconds_since(t0) / reps, error_against(y, p.reference), {}};
}

std::string figure_name(const Problem& p, const char* what) {
  return "work-precision, " + p.label + ": error against " + what;
}
std::string energy_figure(const Problem& p) { return "long-time energy, " + p.label + " (log t)"; }

Series series(const std::string& figure, const std::string& name, const char* x_label, const char* y_label) {
  Series s;
  s.figure = figure;
  s.name = name;
  s.x_label = x_label;
  s.y_label = y_label;
  s.log_x = s.log_y = true;
  return s;
}

// The diagram and the long run of one problem; appends to v and to the message's lists.
void draw(const Problem& p, Verdict& v, std::vector<std::string>& cheapest, std::vector<std::string>& cut,
          std::vector<std::string>& failed) {
  const char* y = "max error at t = 4";
  const double target = 1e-6;  // the message quotes the cheapest run of each method reaching this error
  auto record = [&](const std::string& label, const std::vector<Run>& runs) {
    Series st = series(figure_name(p, "steps"), label, "steps", y),
           ev = series(figure_name(p, "vector-field evaluations"), label, "vector-field evaluations", y),
           tm = series(figure_name(p, "wall time"), label, "wall time [s]", y);
    const Run* best = nullptr;
    for (const Run& r : runs) {
      st.points.emplace_back(static_cast<double>(r.steps), r.error);
      tm.points.emplace_back(r.seconds, r.error);
      if (r.evals > 0) ev.points.emplace_back(static_cast<double>(r.evals), r.error);
      if (r.error <= target && (!best || r.seconds < best->seconds)) best = &r;
    }
    v.series.push_back(st);
    if (!ev.points.empty()) v.series.push_back(ev);
    v.series.push_back(tm);
    if (best)
      cheapest.push_back(p.label + ", " + label + " " + sci(best->seconds * 1e3) + " ms (" +
                         std::to_string(best->steps) + " steps" +
                         (best->evals ? ", " + std::to_string(best->evals) + " evaluations" : "") + ")");
  };
  // Each method from h = 1 down to h = 1/512; a step that throws (an implicit solve diverging at
  // h = 1) or blows up leaves that point out, and the levels stop at the time budget.
  for (const Method& m : p.methods) {
    std::vector<Run> runs;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < kLevels && seconds_since(start) < kLongBudget; ++k) {
      Run r = fixed_step_run(p, m, 4 << k);
      if (!r.failure.empty())
        failed.push_back(p.label + ", " + m.source + ": " + m.name + " at h = " + sci(kTime / (4 << k)) + ": " +
                         r.failure);
      if (std::isfinite(r.error)) runs.push_back(r);
    }
    record(m.source + ": " + m.name, runs);
  }
  std::vector<Run> runs;
  for (int e = 2; e <= 13; ++e) runs.push_back(odeint_run(p, std::pow(10.0, -e)));
  record("suite: odeint runge_kutta_dopri5 (adaptive)", runs);

  // Long-time energy, sampled at about 40 points per decade of t; a method whose steps are slow
  // (a remote implementation) stops at the time budget, and the message says where.
  const double H0 = p.energy(p.x0);
  for (const Method& m : p.methods) {
    Series en = series(energy_figure(p), m.source + ": " + m.name, "t", "|H - H0| / H0");
    State x = p.x0;
    double next = 1;
    const auto start = std::chrono::steady_clock::now();
    std::vector<State> chunk;  // the steps of a run not taken yet (Method::run), in order
    std::size_t at = 0;
    bool by_runs = static_cast<bool>(m.run);
    for (int i = 1; i <= kLongSteps; ++i) {
      if (i % 256 == 0 && seconds_since(start) > kLongBudget) {
        cut.push_back(p.label + ", " + m.source + ": " + m.name + " at t = " + sci(i * p.long_step));
        break;
      }
      try {
        if (by_runs && at == chunk.size()) {
          try {
            chunk = m.run(x, p.long_step, std::min(256, kLongSteps - i + 1));
            at = 0;
          } catch (const std::exception&) {
            by_runs = false;  // one step at a time from here: an error is met at its own step
          }
        }
        x = by_runs ? chunk[at++] : m.step(x, p.long_step);
      } catch (const std::exception& e) {
        failed.push_back(p.label + ", " + m.source + ": " + m.name + " in the long run at t = " + sci(i * p.long_step) +
                         ": " + e.what());
        break;
      }
      if (i < next) continue;
      next = std::max(next + 1, next * 1.06);
      const double H = p.energy(x);
      en.points.emplace_back(i * p.long_step, std::abs(H - H0) / std::abs(H0));
      if (!std::isfinite(H)) break;
    }
    v.series.push_back(en);
  }
}

// ---------------------------------------------------------------------------------------------
// The four problems, one per kind of step. Each wraps the subject's steps (`mine`) and the suite's
// with the same adapter, the subject's first.

using Subjects = std::vector<const Integrator<double>*>;

// A subject's run of steps (Integrator::rigid_body_run / manakov_run) on packed states; empty when
// the subject has none.
template <class Param, class Unpack, class Pack, class Run>
std::function<std::vector<State>(const State&, double, int)> packed_run(Param p, Unpack unpack, Pack pack_state,
                                                                        Run run) {
  if (!run) return {};
  return [p, unpack, pack_state, run](const State& s, double h, int n) {
    std::vector<State> out;
    for (const auto& y : run(p, unpack(s), h, n)) out.push_back(pack_state(y));
    return out;
  };
}

double rigid_body_energy(const Vec3<double>& I, const Vec3<double>& Pi) {
  return Pi.cwiseProduct(Pi).cwiseQuotient(I).sum() / 2;
}

// The motion of the portraits (portrait.hpp).
Problem rigid_body_problem(const Subjects& mine) {
  Problem p;
  p.label = "rigid body";
  const Vec3<double> I = portrait_inertia<double>();
  p.x0 = pack(portrait_start<double>());
  const RigidBodyState<Real50> r =
      reference_rigid_body(portrait_inertia<Real50>(), portrait_start<Real50>(), Real50(0), {Real50(kTime)}).front();
  for (int k = 0; k < 3; ++k) p.reference.push_back(r.Pi(k));
  for (int k = 0; k < 9; ++k) p.reference.push_back(r.O(k / 3, k % 3));
  p.field = [I](const State& s) { return pack(ref::rigid_body_field<double>(I, unpack_rigid_body(s))); };
  p.energy = [I](const State& s) { return rigid_body_energy(I, Vec3<double>(s[0], s[1], s[2])); };
  auto wrap = [I](auto step) {
    return [I, step](const State& s, double h) { return pack(step(I, unpack_rigid_body(s), h)); };
  };
  for (const auto* in : mine)
    p.methods.push_back(
        {in->name, "subject", wrap(in->rigid_body_step), 0,
         packed_run(
             I, unpack_rigid_body, [](const RigidBodyState<double>& x) { return pack(x); }, in->rigid_body_run)});
  p.methods.insert(p.methods.end(),
                   {{"rk4", "suite", wrap(ref::rk4_step<double>), 4, {}},
                    {"implicit_midpoint", "suite", wrap(ref::implicit_midpoint_step<double>), 0, {}},
                    {"lie_poisson_splitting", "suite", wrap(ref::lie_poisson_splitting_step<double>), 0, {}}});
  return p;
}

// Manakov, n = 4, a = (1/2, 3/4, 1, 3/2), M with dyadic entries, O = Id; reference by the Taylor
// oracle in 50 digits (oracle/taylor.hpp, local tolerance eps).
constexpr int kManakovN = 4;
std::vector<double> manakov_a() { return {0.5, 0.75, 1.0, 1.5}; }
MatX<double> manakov_M0() {
  MatX<double> M(kManakovN, kManakovN);
  M << 0, 0.5, -0.25, 0.375, -0.5, 0, 0.625, -0.125, 0.25, -0.625, 0, 0.75, -0.375, 0.125, -0.75, 0;
  return M;
}

// (M, O) at t = 4 from (M0, Id), packed, by the Taylor oracle in 50 digits (local tolerance eps).
std::vector<Real50> manakov_at_t(const std::vector<double>& a, const MatX<Real50>& M0) {
  const int n = static_cast<int>(a.size());
  std::vector<Real50> a50;
  for (double v : a) a50.push_back(Real50(v));
  oracle::ManakovField<Real50> f(a50);
  oracle::TaylorSolver<Real50, decltype(f)> solver(f, 2 * n * n, eps<Real50>());
  std::vector<Real50> x0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) x0.push_back(M0(i, j));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) x0.push_back(Real50(i == j ? 1 : 0));
  return solver.flow(x0, Real50(0), Real50(kTime));
}

double manakov_energy(const MatX<double>& M) {
  const auto a = manakov_a();
  double e = 0;
  for (int i = 0; i < M.rows(); ++i)
    for (int j = 0; j < M.cols(); ++j) e += M(i, j) * M(i, j) / (a[i] + a[j]);
  return e / 4;  // -tr(Omega M)/4 with Omega_ij = M_ij / (a_i + a_j)
}

Problem manakov_problem(const Subjects& mine) {
  Problem p;
  const int n = kManakovN;
  p.label = "Manakov n = 4";
  const MatX<double> A = Eigen::Map<const VecX<double>>(manakov_a().data(), n).asDiagonal();
  p.x0 = pack(manakov_M0(), MatX<double>::Identity(n, n));
  p.reference = manakov_at_t(manakov_a(), manakov_M0().cast<Real50>());
  auto unpack = [n](const State& s) { return ManakovState<double>{block(s, 0, n, n), block(s, n * n, n, n)}; };
  p.field = [A, unpack](const State& s) {
    const ManakovState<double> d = ref::manakov_field<double>(A, unpack(s));
    return pack(d.M, d.O);
  };
  p.energy = [n](const State& s) { return manakov_energy(block(s, 0, n, n)); };
  p.long_step = 0.125;
  auto wrap = [A, unpack](auto step) {
    return [A, unpack, step](const State& s, double h) {
      const ManakovState<double> y = step(A, unpack(s), h);
      return pack(y.M, y.O);
    };
  };
  for (const auto* in : mine)
    p.methods.push_back(
        {in->name, "subject", wrap(in->manakov_step), 0,
         packed_run(
             A, unpack, [](const ManakovState<double>& y) { return pack(y.M, y.O); }, in->manakov_run)});
  p.methods.insert(p.methods.end(),
                   {{"rk4", "suite", wrap(ref::manakov_rk4_step<double>), 4, {}},
                    {"implicit_midpoint", "suite", wrap(ref::manakov_implicit_midpoint_step<double>), 0, {}},
                    {"isospectral_cayley", "suite", wrap(ref::manakov_isospectral_step<double>), 0, {}}});
  return p;
}

// Clebsch (3.21): the portraits' body I, dyadic Q(0) and P(0); Q(t) = O(t)^-1 Q(0),
// P(t) = O(t)^-1 P(0) (Remark 3.3) with (Pi, O) from the 50-digit reference started at
// (P(0) x Q(0), Id).
Problem clebsch_problem(const Subjects& mine) {
  Problem p;
  p.label = "Clebsch (3.21)";
  const Vec3<double> I = portrait_inertia<double>();
  const Vec3<double> Q0(0.5, -0.25, 0.75), P0(-0.25, 0.875, 0.5);
  p.x0 = pack(MatX<double>(Q0.transpose()), MatX<double>(P0.transpose()));
  const Vec3<Real50> Q50 = Q0.cast<Real50>(), P50 = P0.cast<Real50>();
  const RigidBodyState<Real50> r =
      reference_rigid_body(portrait_inertia<Real50>(), RigidBodyState<Real50>{P50.cross(Q50), Mat3<Real50>::Identity()},
                           Real50(0), {Real50(kTime)})
          .front();
  const Vec3<Real50> Q = r.O.transpose() * Q50, P = r.O.transpose() * P50;
  for (int k = 0; k < 3; ++k) p.reference.push_back(Q(k));
  for (int k = 0; k < 3; ++k) p.reference.push_back(P(k));
  auto to_pair = [](const State& s) {
    return Vec3Pair<double>{Vec3<double>(s[0], s[1], s[2]), Vec3<double>(s[3], s[4], s[5])};
  };
  auto from_pair = [](const Vec3Pair<double>& z) {
    return State{z.first(0), z.first(1), z.first(2), z.second(0), z.second(1), z.second(2)};
  };
  p.field = [I, to_pair, from_pair](const State& s) {
    const auto z = to_pair(s);
    return from_pair(ref::clebsch_3_21<double>(I, z.first, z.second));
  };
  p.energy = [I, to_pair](const State& s) {
    const auto z = to_pair(s);
    return rigid_body_energy(I, z.second.cross(z.first));
  };
  auto wrap = [I, to_pair, from_pair](auto step) {
    return [I, to_pair, from_pair, step](const State& s, double h) { return from_pair(step(I, to_pair(s), h)); };
  };
  for (const auto* in : mine) p.methods.push_back({in->name, "subject", wrap(in->clebsch_step), 0, {}});
  p.methods.insert(p.methods.end(), {{"rk4", "suite", wrap(ref::clebsch_rk4_step<double>), 4, {}},
                                     {"clebsch_midpoint", "suite", wrap(ref::clebsch_midpoint_step<double>), 0, {}},
                                     {"clebsch_splitting", "suite", wrap(ref::clebsch_splitting_step<double>), 0, {}}});
  return p;
}

// Clebsch (3.23), n = 3: Q(t) = Q(0) O(t), P(t) = P(0) O(t), (M, O) by the Taylor oracle.
constexpr int kClebschN = 3;
std::vector<double> manakov_clebsch_a() { return {0.5, 0.75, 1.0}; }

Problem manakov_clebsch_problem(const Subjects& mine) {
  Problem p;
  const int n = kClebschN;
  p.label = "Clebsch (3.23) n = 3";
  const std::vector<double> a = manakov_clebsch_a();
  const MatX<double> A = Eigen::Map<const VecX<double>>(a.data(), n).asDiagonal();
  MatX<double> Q0(n, n), P0(n, n);
  Q0 << 0.5, -0.25, 0.125, 0.25, 0.375, -0.5, -0.125, 0.5, 0.25;
  P0 << 0.25, 0.5, -0.375, -0.5, 0.125, 0.25, 0.375, -0.25, 0.5;
  p.x0 = pack(Q0, P0);
  {
    const MatX<Real50> Q50 = Q0.cast<Real50>(), P50 = P0.cast<Real50>();
    const std::vector<Real50> y = manakov_at_t(a, MatX<Real50>(Q50.transpose() * P50 - P50.transpose() * Q50));
    MatX<Real50> O(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) O(i, j) = y[n * n + i * n + j];
    const MatX<Real50> Q = Q50 * O, P = P50 * O;
    for (const MatX<Real50>* X : {&Q, &P})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) p.reference.push_back((*X)(i, j));
  }
  auto to_pair = [n](const State& s) { return MatXPair<double>{block(s, 0, n, n), block(s, n * n, n, n)}; };
  p.field = [A, to_pair](const State& s) {
    const auto z = to_pair(s);
    const auto d = ref::manakov_clebsch_3_23<double>(A, z.first, z.second);
    return pack(d.first, d.second);
  };
  p.energy = [a, to_pair](const State& s) {
    const auto z = to_pair(s);
    const MatX<double> M = ref::manakov_clebsch_M<double>(z.first, z.second);
    double e = 0;
    for (int i = 0; i < M.rows(); ++i)
      for (int j = 0; j < M.cols(); ++j) e += M(i, j) * M(i, j) / (a[i] + a[j]);
    return e / 4;
  };
  p.long_step = 0.125;
  auto wrap = [A, to_pair](auto step) {
    return [A, to_pair, step](const State& s, double h) {
      const MatXPair<double> y = step(A, to_pair(s), h);
      return pack(y.first, y.second);
    };
  };
  for (const auto* in : mine) p.methods.push_back({in->name, "subject", wrap(in->manakov_clebsch_step), 0, {}});
  p.methods.insert(p.methods.end(),
                   {{"rk4", "suite", wrap(ref::manakov_clebsch_rk4_step<double>), 4, {}},
                    {"clebsch_midpoint", "suite", wrap(ref::manakov_clebsch_midpoint_step<double>), 0, {}}});
  return p;
}

// One problem for each kind of step the chosen integrators have; their steps come first.
std::vector<Problem> problems_for(const Subject<double>& s, const std::vector<std::string>& names) {
  auto having = [&](auto step) {
    Subjects mine;
    for (const auto& in : s.integrators)
      if (std::find(names.begin(), names.end(), in.name) != names.end() && static_cast<bool>(in.*step))
        mine.push_back(&in);
    return mine;
  };
  std::vector<Problem> out;
  if (const Subjects m = having(&Integrator<double>::rigid_body_step); !m.empty()) out.push_back(rigid_body_problem(m));
  if (const Subjects m = having(&Integrator<double>::manakov_step); !m.empty()) out.push_back(manakov_problem(m));
  if (const Subjects m = having(&Integrator<double>::clebsch_step); !m.empty()) out.push_back(clebsch_problem(m));
  if (const Subjects m = having(&Integrator<double>::manakov_clebsch_step); !m.empty())
    out.push_back(manakov_clebsch_problem(m));
  return out;
}

std::string run_work_precision(const Subject<double>& s, const std::vector<std::string>& names) {
  Verdict v;
  v.property = "work-precision";
  v.scalar = "double";
  v.title = "work-precision diagram and long-time energy, against the suite's methods";
  std::vector<std::string> cheapest, cut, failed;
  for (const Problem& p : problems_for(s, names)) draw(p, v, cheapest, cut, failed);
  std::ostringstream msg;
  msg << "error at t = 4 against steps, vector-field evaluations and wall time (figures/work-precision.csv); the "
         "cheapest run of each method reaching an error of 1e-6:";
  for (const auto& c : cheapest) msg << " " << c << ";";
  if (cheapest.empty()) msg << " none;";
  msg << " long-time energy over " << kLongSteps << " steps on log-log axes";
  if (!cut.empty()) {
    msg << " (stopped at the " << kLongBudget << " s budget:";
    for (const auto& c : cut) msg << " " << c << ";";
    msg << ")";
  }
  if (!failed.empty()) {
    msg << "; points left out because the step threw:";
    for (const auto& f : failed) msg << " " << f << ";";
  }
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
    if (cfg.integrator.empty() || in.name == cfg.integrator) names.push_back(in.name);
  if (names.empty()) return std::nullopt;
  const Subject<double>* sub = s.d.get();
  PortraitTask t;
  t.scalar = "double";
  t.property = "work-precision";
  t.run = [sub, names]() { return run_work_precision(*sub, names); };
  return t;
}

std::string work_precision_csv(const CheckResult& r) {
  const Verdict* wp = nullptr;
  for (const auto& p : r.portraits)
    if (p.property == "work-precision") wp = &p;
  if (!wp) return {};
  // The steps series fix the rows; evaluations and times are matched by figure, method and position.
  const std::string head = "work-precision, ", steps = ": error against steps";
  std::map<std::string, const Series*> by_figure_and_name;
  for (const auto& s : wp->series) by_figure_and_name[s.figure + "\n" + s.name] = &s;
  std::ostringstream csv;
  csv << "problem,method,source,steps,vector_field_evaluations,seconds,error_at_t4\n";
  auto quoted = [](const std::string& x) {
    std::string q = "\"";
    for (char ch : x) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
  };
  char buf[64];
  auto num = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return std::string(buf);
  };
  for (const auto& s : wp->series) {
    if (s.figure.rfind(head, 0) != 0 || s.figure.size() < steps.size() ||
        s.figure.compare(s.figure.size() - steps.size(), steps.size(), steps) != 0)
      continue;
    const std::string problem = s.figure.substr(head.size(), s.figure.size() - head.size() - steps.size());
    const auto colon = s.name.find(": ");
    const std::string source = s.name.substr(0, colon), method = s.name.substr(colon + 2);
    auto find = [&](const char* what) {
      const auto it = by_figure_and_name.find(head + problem + ": error against " + what + "\n" + s.name);
      return it == by_figure_and_name.end() ? nullptr : it->second;
    };
    const Series* e = find("vector-field evaluations");
    const Series* t = find("wall time");
    for (std::size_t i = 0; i < s.points.size(); ++i)
      csv << quoted(problem) << "," << quoted(method) << "," << source << "," << static_cast<long>(s.points[i].first)
          << "," << (e && i < e->points.size() ? std::to_string(static_cast<long>(e->points[i].first)) : "") << ","
          << (t && i < t->points.size() ? num(t->points[i].first) : "") << "," << num(s.points[i].second) << "\n";
  }
  return csv.str();
}

}  // namespace gm::harness
