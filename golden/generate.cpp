// The 70-digit generation of golden trajectories. The only translation unit that instantiates
// the Taylor oracle and the extrapolation solver on Real70.
#include "golden/generate.hpp"
#include "golden/certify.hpp"

#include "golden/arguments.hpp"

#include "golden/condition.hpp"
#include "golden/elliptic_check.hpp"
#include "golden/extrapolation.hpp"
#include "golden/fields_geometric.hpp"
#include "oracle/fields.hpp"
#include "oracle/taylor.hpp"

#include <chrono>
#include <optional>

namespace gm::golden {

namespace {

using R = Real70;

// Settings of the methods (written into every fixture).
const char* const kTaylorTolerance = "1e-62";
const int kExtrapolationColumns = 14;
const char* const kExtrapolationTolerance = "1e-60";
// Bounds that stop a runaway integration: a state beyond 1e20 (the largest magnitude a fixture
// may hold), or more steps than any sensible request needs.
const char* const kMaxNorm = "1e20";
const long kMaxTaylorSteps = 200000;
const long kMaxExtrapolationSteps = 2000000;

using Samples = std::vector<std::vector<R>>;

struct MethodRun {
  MethodRecord record;
  Samples values;
  double seconds = 0;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class Field>
MethodRun run_taylor(const Field& f, int dim, const std::vector<R>& x0, const std::vector<R>& times) {
  const auto t0 = std::chrono::steady_clock::now();
  oracle::TaylorSolver<R, Field> solver(f, dim, R(kTaylorTolerance));
  solver.set_limits(kMaxTaylorSteps, R(kMaxNorm));
  MethodRun run;
  run.values = solver.sample(x0, R(0), times);
  run.seconds = seconds_since(t0);
  run.record.method = "taylor";
  run.record.settings = {{"source", "oracle/taylor.hpp"},
                         {"field", "oracle/fields.hpp"},
                         {"order", std::to_string(solver.order())},
                         {"tolerance", kTaylorTolerance},
                         {"steps", std::to_string(solver.stats().steps)}};
  return run;
}

template <class Field>
MethodRun run_extrapolation(const Field& f, const std::vector<R>& x0, const std::vector<R>& times) {
  const auto t0 = std::chrono::steady_clock::now();
  ExtrapolationSettings<R> settings;
  settings.columns = kExtrapolationColumns;
  settings.tolerance = R(kExtrapolationTolerance);
  settings.max_steps = kMaxExtrapolationSteps;
  settings.max_norm = R(kMaxNorm);
  ExtrapolationSolver<R, const Field&> solver(f, f.dim, settings);
  MethodRun run;
  run.values = solver.sample(x0, R(0), times);
  run.seconds = seconds_since(t0);
  run.record.method = "extrapolation";
  run.record.settings = {{"source", "golden/extrapolation.hpp"},
                         {"field", "golden/fields_geometric.hpp"},
                         {"columns", std::to_string(kExtrapolationColumns)},
                         {"tolerance", kExtrapolationTolerance},
                         {"steps", std::to_string(solver.stats().steps)},
                         {"rejected", std::to_string(solver.stats().rejected)}};
  return run;
}

// A free rigid body with two equal moments, I_i = I_j with j = i + 1 (mod 3), k the third axis:
// Pi_k is constant and (Pi_i, Pi_j) rotates with nu = (1/I_k - 1/I_i) Pi_k:
//   Pi_i(t) = Pi_i cos(nu t) + Pi_j sin(nu t),  Pi_j(t) = Pi_j cos(nu t) - Pi_i sin(nu t).
std::optional<MethodRun> symmetric_top(const std::vector<Rational>& I, const std::vector<R>& x0,
                                       const std::vector<R>& times) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (I[i] != I[j]) continue;
    const auto t0 = std::chrono::steady_clock::now();
    const R nu = (R(1) / convert<R>(I[k]) - R(1) / convert<R>(I[i])) * x0[k];
    MethodRun run;
    for (const R& t : times) {
      const R c = cos(nu * t), s = sin(nu * t);
      std::vector<R> x(3);
      x[i] = x0[i] * c + x0[j] * s;
      x[j] = x0[j] * c - x0[i] * s;
      x[k] = x0[k];
      run.values.push_back(std::move(x));
    }
    run.seconds = seconds_since(t0);
    run.record.method = "closed-form";
    run.record.settings = {{"source", "golden/generate.cpp"},
                           {"case", "symmetric_top_I" + std::to_string(i + 1) + "=I" + std::to_string(j + 1)}};
    return run;
  }
  return std::nullopt;
}

R max_abs_diff(const Samples& a, const Samples& b) {
  R m(0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k < a[i].size(); ++k) {
      const R d = abs(R(a[i][k] - b[i][k]));
      if (d > m) m = d;
    }
  return m;
}

std::string two_digits(const R& x) {
  if (x == 0) return "0";
  return format_significant(convert<Rational>(x), 2);
}

}  // namespace

Fixture generate(const Request& rq, GenerationReport* report) {
  const auto start = std::chrono::steady_clock::now();
  const Problem& pr = rq.problem;
  if (!pr.info) throw std::logic_error("generate: request without a validated problem");
  if (rq.digits < kMinDigits || rq.digits > kMaxDigits)
    throw InputError("digits", 0,
                     "digits " + std::to_string(rq.digits) + " outside [" + std::to_string(kMinDigits) + ", " +
                         std::to_string(kMaxDigits) + "]");
  validate_times(rq.times, "times");

  std::vector<R> x0, times, p;
  std::vector<double> x0d, timesd, pd;
  for (const auto& v : pr.x0) x0.push_back(convert<R>(v)), x0d.push_back(to_double(v));
  for (const auto& t : rq.times) times.push_back(convert<R>(t)), timesd.push_back(to_double(t));
  for (const auto& v : pr.p) p.push_back(convert<R>(v)), pd.push_back(to_double(v));
  const int dim = pr.dim();

  MethodRun generator;
  std::vector<MethodRun> checks;
  double condition = 1.0;
  double condition_seconds = 0;
  auto timed_condition = [&](auto&& compute) {
    const auto t0 = std::chrono::steady_clock::now();
    condition = compute();
    condition_seconds = seconds_since(t0);
  };

  try {
    switch (pr.info->id) {
      case SystemId::FreeRigidBody: {
        generator = run_taylor(oracle::FreeRigidBodyField<R>(p[0], p[1], p[2]), dim, x0, times);
        checks.push_back(run_extrapolation(geometric::FreeRigidBody<R>{3, {p[0], p[1], p[2]}}, x0, times));
        if (auto top = symmetric_top(pr.p, x0, times)) checks.push_back(std::move(*top));
        if (auto exact = exact_free_rigid_body({p[0], p[1], p[2]}, {x0[0], x0[1], x0[2]}, times)) {
          MethodRun run;
          run.record.method = exact->method;
          run.record.settings = exact->settings;
          run.values = std::move(exact->values);
          if (run.values.size() != times.size())
            throw std::logic_error("exact_free_rigid_body: wrong number of samples");
          checks.push_back(std::move(run));
        }
        timed_condition([&] {
          return trajectory_condition(oracle::FreeRigidBodyField<double>(pd[0], pd[1], pd[2]), dim, x0d, timesd);
        });
        break;
      }
      case SystemId::RigidBodyAttitude:
        generator = run_taylor(oracle::RigidBodyAttitudeField<R>(p[0], p[1], p[2]), dim, x0, times);
        checks.push_back(run_extrapolation(geometric::RigidBodyAttitude<R>{12, {p[0], p[1], p[2]}}, x0, times));
        timed_condition([&] {
          return trajectory_condition(oracle::RigidBodyAttitudeField<double>(pd[0], pd[1], pd[2]), dim, x0d, timesd);
        });
        break;
      case SystemId::Clebsch:
        generator = run_taylor(oracle::ClebschField<R>(p[0], p[1], p[2]), dim, x0, times);
        checks.push_back(run_extrapolation(geometric::Clebsch<R>{6, {p[0], p[1], p[2]}}, x0, times));
        timed_condition(
            [&] { return trajectory_condition(oracle::ClebschField<double>(pd[0], pd[1], pd[2]), dim, x0d, timesd); });
        break;
      case SystemId::Manakov:
        generator = run_taylor(oracle::ManakovField<R>(p), dim, x0, times);
        checks.push_back(run_extrapolation(geometric::Manakov<R>(p), x0, times));
        timed_condition([&] { return trajectory_condition(oracle::ManakovField<double>(pd), dim, x0d, timesd); });
        break;
      case SystemId::Nambu316:
        generator = run_taylor(oracle::Nambu316Field<R>(p[0], p[1], p[2]), dim, x0, times);
        checks.push_back(run_extrapolation(geometric::Nambu316<R>{3, {p[0], p[1], p[2]}}, x0, times));
        timed_condition(
            [&] { return trajectory_condition(oracle::Nambu316Field<double>(pd[0], pd[1], pd[2]), dim, x0d, timesd); });
        break;
    }
  } catch (const std::runtime_error& e) {
    throw VerificationError("trajectory '" + rq.name + "' cannot be generated: " + e.what());
  }

  // The values, exactly rounded to `digits` significant digits; the sample at t = 0 is the
  // exact initial state rounded (not its 70-digit image).
  Fixture f;
  f.name = rq.name;
  f.system = pr.info->name;
  f.title = rq.title.empty() ? pr.info->title : rq.title;
  f.equations = pr.info->equations;
  f.parameters = pr.parameters;
  f.initial = pr.initial;
  f.columns = pr.columns;
  f.digits = rq.digits;
  f.working_precision = kWorkingDigits;
  R largest(0);
  Rational largest_half_ulp(0);
  for (std::size_t i = 0; i < times.size(); ++i) {
    f.times.push_back(format_exact(rq.times[i]));
    std::vector<std::string> row;
    for (int k = 0; k < dim; ++k) {
      const Rational v = rq.times[i] == 0 ? pr.x0[k] : convert<Rational>(generator.values[i][k]);
      row.push_back(format_significant(v, rq.digits));
      const Rational h = half_ulp_decimal(v, rq.digits);
      if (h > largest_half_ulp) largest_half_ulp = h;
      const R a = abs(generator.values[i][k]);
      if (a > largest) largest = a;
    }
    f.rows.push_back(std::move(row));
  }

  // Verification: every check must agree with the generator.
  R allowed = R("1e-40");
  const R digit_bound = convert<R>(pow10(-(rq.digits + 2))) * (largest > R(1) ? largest : R(1));
  if (digit_bound < allowed) allowed = digit_bound;
  R worst(0);
  std::string failures;
  for (auto& c : checks) {
    const R d = max_abs_diff(generator.values, c.values);
    if (d > worst) worst = d;
    c.record.settings.emplace_back("max_abs_diff", two_digits(d));
    if (!(d <= allowed))
      failures += "\n  " + c.record.method + " disagrees with the Taylor series by " + two_digits(d) + " > " +
                  two_digits(allowed);
  }
  if (report) {
    report->timings.clear();
    report->timings.push_back({generator.record.method, generator.seconds});
    for (const auto& c : checks) report->timings.push_back({c.record.method, c.seconds});
    report->timings.push_back({"condition", condition_seconds});
    report->max_abs_diff = two_digits(worst);
    report->allowed = two_digits(allowed);
  }
  if (!failures.empty())
    throw VerificationError("trajectory '" + rq.name + "' cannot be verified to " + std::to_string(rq.digits) +
                            " digits:" + failures);

  f.generator = generator.record;
  for (auto& c : checks) f.checks.push_back(std::move(c.record));
  // Every printed value is within (largest disagreement + half a unit in its last digit) of the
  // generator's, and the generator within the largest disagreement of every check.
  f.accuracy = round_up_1digit(convert<Rational>(worst) + largest_half_ulp);
  f.condition = format_significant(Rational(condition), 2);
  if (rq.certify) {
    const auto t0 = std::chrono::steady_clock::now();
    Certificate cert;
    try {
      cert = certify_rows(pr, rq.times, f.rows);
    } catch (const std::runtime_error& e) {
      throw VerificationError("trajectory '" + rq.name + "' cannot be certified: " + e.what());
    }
    // The first row whose radius leaves fewer digits than asked, if any: refused, saying when.
    for (std::size_t i = 0; i < f.rows.size(); ++i) {
      Rational scale(1);
      for (const auto& v : f.rows[i]) scale = std::max(scale, abs(parse_decimal(v)));
      if (parse_decimal(cert.row_radius[i]) > pow10(-rq.certified_digits) * scale)
        throw VerificationError("trajectory '" + rq.name + "' cannot be certified to " +
                                std::to_string(rq.certified_digits) + " digits: at t = " + f.times[i] +
                                " the proved radius is " + cert.row_radius[i] + " (the enclosure grew from " +
                                "the exact initial data through the wrapping effect of ball arithmetic; a shorter time "
                                "span or fewer digits can be certified)");
    }
    f.certified = true;
    f.certificate = cert.record;
    f.certified_radius = cert.row_radius;
    if (report) report->timings.push_back({"certificate", seconds_since(t0)});
  }
  if (report) report->seconds = seconds_since(start);
  return f;
}

}  // namespace gm::golden
