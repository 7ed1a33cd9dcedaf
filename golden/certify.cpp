#include "golden/certify.hpp"

#include "golden/generate.hpp"
#include "oracle/fields.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace gm::golden {

namespace {

using Op = oracle::Tape<Ball>::Op;

// The Taylor coefficients 0..K of every node of the tape, for the solution through X:
// coef[n][k]. Variables take c_0 = X and c_{k+1} = [f]_k / (k + 1).
class Sweep {
 public:
  Sweep(const oracle::Tape<Ball>& tape, const std::vector<int>& out) : tape_(tape), out_(out) {
    for (std::size_t n = 0; n < tape.nodes().size(); ++n)
      if (tape.nodes()[n].op == Op::Var) vars_.push_back(static_cast<int>(n));
  }

  // Computes orders 0..K; returns the variables' coefficients: c[i][k].
  const std::vector<std::vector<Ball>>& run(const std::vector<Ball>& X, int K) {
    const auto& nodes = tape_.nodes();
    if (coef_.size() != nodes.size() || static_cast<int>(coef_[0].size()) < K + 1)
      coef_.assign(nodes.size(), std::vector<Ball>(K + 1));
    for (int k = 0; k <= K; ++k) {
      for (std::size_t v = 0; v < vars_.size(); ++v) {
        Ball& c = coef_[vars_[v]][k];
        if (k == 0) {
          c = X[v];
        } else {
          arb_div_si(c.raw(), coef_[out_[v]][k - 1].raw(), k, Ball::bits());
        }
      }
      for (std::size_t n = 0; n < nodes.size(); ++n) {
        const auto& nd = nodes[n];
        Ball& c = coef_[n][k];
        switch (nd.op) {
          case Op::Var:
            break;
          case Op::Const:
            c = k == 0 ? nd.c : Ball(0L);
            break;
          case Op::Add:
            c = coef_[nd.a][k] + coef_[nd.b][k];
            break;
          case Op::Sub:
            c = coef_[nd.a][k] - coef_[nd.b][k];
            break;
          case Op::Neg:
            c = -coef_[nd.a][k];
            break;
          case Op::Scale:
            c = coef_[nd.a][k] * nd.c;
            break;
          case Op::Mul: {
            const auto& a = coef_[nd.a];
            const auto& b = coef_[nd.b];
            c = a[0] * b[k];
            for (int j = 1; j <= k; ++j) c.add_product(a[j], b[k - j]);
            break;
          }
        }
      }
    }
    vars_coef_.assign(vars_.size(), {});
    for (std::size_t v = 0; v < vars_.size(); ++v)
      vars_coef_[v].assign(coef_[vars_[v]].begin(), coef_[vars_[v]].begin() + K + 1);
    return vars_coef_;
  }

 private:
  const oracle::Tape<Ball>& tape_;
  const std::vector<int>& out_;
  std::vector<int> vars_;
  std::vector<std::vector<Ball>> coef_;
  std::vector<std::vector<Ball>> vars_coef_;
};

double largest_magnitude(const std::vector<Ball>& x) {
  double m = 0;
  for (const auto& b : x) m = std::max(m, b.magnitude_bound());
  return m;
}

std::string short_number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

}  // namespace

Enclosure enclose_tape(const oracle::Tape<Ball>& tape, const std::vector<int>& out, int dim,
                       const std::vector<Rational>& x0, const std::vector<Rational>& times, const EnclosureOptions& o) {
  const Ball::Precision precision(o.precision_bits);
  Enclosure e;
  e.precision_bits = o.precision_bits;
  int N = o.order;
  if (N <= 0) N = static_cast<int>(std::ceil(-std::log(o.tolerance) / 2)) + 1;
  e.order = N;
  Sweep sweep(tape, out);
  std::vector<Ball> X;
  for (const auto& v : x0) X.emplace_back(v);
  Rational t(0);
  std::size_t next = 0;
  auto record = [&] {
    e.values.push_back(X);
    for (const auto& b : X) e.largest_radius = std::max(e.largest_radius, b.radius_bound());
    ++next;
  };
  while (next < times.size() && times[next] == t) record();
  while (next < times.size()) {
    const double scale = std::max(1.0, largest_magnitude(X));
    const std::vector<std::vector<Ball>> c = sweep.run(X, N);  // a copy: the sweeps of B reuse the buffers
    // Jorba-Zou: the last terms kept fall below the tolerance.
    double h_est = 1e300;
    for (int m : {N - 1, N}) {
      double cm = 0;
      for (int i = 0; i < dim; ++i) cm = std::max(cm, c[i][m].magnitude_bound());
      if (cm > 0) h_est = std::min(h_est, std::pow(o.tolerance * scale / cm, 1.0 / m));
    }
    if (!(h_est > 0) || !std::isfinite(h_est)) h_est = 1.0;
    // A dyadic step (exact), cut to end on the next sample time.
    Rational h(std::ldexp(std::floor(std::ldexp(h_est, 30)), -30));
    if (h <= 0) h = Rational(1, 1 << 30);
    bool done = false;
    for (int attempt = 0; attempt < 40 && !done; ++attempt) {
      bool hits = false;
      if (t + h >= times[next]) h = times[next] - t, hits = true;
      const Ball H(h);
      const Ball span = H.times_unit_interval();  // [0, h]
      // 2. The a-priori enclosure B over [0, h].
      std::vector<Ball> B(dim), T(dim);
      for (int i = 0; i < dim; ++i) {
        B[i] = X[i] + span * c[i][1];
        B[i] = B[i].inflated(0.5 * B[i].radius_bound() + 1e-30 * scale);
      }
      // B and the remainder are wide or tiny: their sweeps need a valid enclosure, not the
      // working precision's digits, and run at 96 bits (Arb's balls stay rigorous at any
      // precision; about half the certificate's time went here at 320 bits, measured).
      std::optional<Ball::Precision> coarse(std::in_place, 96);
      bool valid = false;
      for (int round = 0; round < 8 && !valid; ++round) {
        const auto& fB = sweep.run(B, 1);
        valid = true;
        for (int i = 0; i < dim; ++i) {
          T[i] = X[i] + span * fB[i][1];
          if (!B[i].contains(T[i])) valid = false;
        }
        if (!valid)
          for (int i = 0; i < dim; ++i) {
            B[i] = B[i].hull(T[i]);
            B[i] = B[i].inflated(B[i].radius_bound() + 1e-30 * scale);
          }
      }
      if (!valid) {
        coarse.reset();
        h /= 2;
        continue;
      }
      // 3. The remainder over B, then the new enclosure.
      const auto& cB = sweep.run(B, N + 1);
      Ball Hpow(1L);
      for (int k = 0; k <= N; ++k) Hpow = Hpow * H;  // h^{N+1}
      std::vector<Ball> R(dim);
      double remainder = 0;
      for (int i = 0; i < dim; ++i) {
        R[i] = cB[i][N + 1] * Hpow;
        remainder = std::max(remainder, R[i].magnitude_bound());
      }
      coarse.reset();
      if (!(remainder <= 1e3 * o.tolerance * scale)) {  // B too wide for this step: a shorter one
        h /= 2;
        continue;
      }
      for (int i = 0; i < dim; ++i) {
        Ball sum = c[i][N];
        for (int k = N - 1; k >= 0; --k) sum = sum * H + c[i][k];
        X[i] = sum + R[i];
      }
      t += h;
      ++e.steps;
      done = true;
      for (const auto& b : X)
        if (!b.is_finite()) {
          e.failure = "the enclosure is no longer finite at t = " + short_number(static_cast<double>(t));
          return e;
        }
      if (hits) record();
    }
    if (!done) {
      double radius = 0;
      for (const auto& b : X) radius = std::max(radius, b.radius_bound());
      e.failure = "no step could be validated at t = " + short_number(static_cast<double>(t)) +
                  " (the step was halved 40 times): the enclosure's radius had grown to " + short_number(radius) +
                  " there (the wrapping effect of ball arithmetic over a long or fast motion); a shorter time span "
                  "can be certified";
      return e;
    }
  }
  return e;
}

Enclosure enclose_problem(const Problem& pr, const std::vector<Rational>& times, const EnclosureOptions& o) {
  const Ball::Precision precision(o.precision_bits);
  std::vector<Ball> p;
  for (const auto& v : pr.p) p.emplace_back(v);
  const int dim = pr.dim();
  switch (pr.info->id) {
    case SystemId::FreeRigidBody:
      return enclose_field(oracle::FreeRigidBodyField<Ball>(p[0], p[1], p[2]), dim, pr.x0, times, o);
    case SystemId::RigidBodyAttitude:
      return enclose_field(oracle::RigidBodyAttitudeField<Ball>(p[0], p[1], p[2]), dim, pr.x0, times, o);
    case SystemId::Clebsch:
      return enclose_field(oracle::ClebschField<Ball>(p[0], p[1], p[2]), dim, pr.x0, times, o);
    case SystemId::Manakov:
      return enclose_field(oracle::ManakovField<Ball>(p), dim, pr.x0, times, o);
    case SystemId::Nambu316:
      return enclose_field(oracle::Nambu316Field<Ball>(p[0], p[1], p[2]), dim, pr.x0, times, o);
  }
  throw std::logic_error("enclose_problem: unknown system");
}

Certificate certify_rows(const Problem& pr, const std::vector<Rational>& times,
                         const std::vector<std::vector<std::string>>& rows, const EnclosureOptions& o) {
  Certificate cert;
  cert.enclosure = enclose_problem(pr, times, o);
  const Enclosure& e = cert.enclosure;
  if (!e.failure.empty()) throw std::runtime_error("the certified enclosure fails: " + e.failure);
  const Ball::Precision precision(o.precision_bits);
  cert.certified_digits = 1e9;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Rational worst(0);
    double row_scale = 1;
    for (std::size_t j = 0; j < rows[i].size(); ++j) {
      const Rational v = parse_decimal(rows[i][j]);
      const double d = e.values[i][j].distance_bound(v);
      if (Rational(d) > worst) worst = Rational(d);
      row_scale = std::max(row_scale, std::abs(static_cast<double>(v)));
    }
    cert.row_radius.push_back(round_up_1digit(worst));
    const double r = static_cast<double>(parse_decimal(cert.row_radius.back()));
    cert.certified_digits = std::min(cert.certified_digits, r > 0 ? -std::log10(r / row_scale) : 99.0);
  }
  cert.record.method = "arb";
  cert.record.settings = {{"source", "golden/certify.cpp"},
                          {"method", "validated-taylor"},
                          {"order", std::to_string(e.order)},
                          {"precision_bits", std::to_string(e.precision_bits)},
                          {"steps", std::to_string(e.steps)},
                          {"largest_enclosure_radius", round_up_1digit(Rational(e.largest_radius))},
                          {"certified_digits", std::to_string(static_cast<int>(std::floor(cert.certified_digits)))}};
  return cert;
}

std::vector<std::string> verify_certificate(const Fixture& f, const Enclosure& e) {
  std::vector<std::string> problems;
  const std::string where = f.source.empty() ? f.name : f.source;
  if (!e.failure.empty()) return {where + ": the certified enclosure fails: " + e.failure};
  if (f.certified_radius.size() != f.rows.size())
    return {where + ": no certified radius for every row (" + std::to_string(f.certified_radius.size()) + " of " +
            std::to_string(f.rows.size()) + ")"};
  const Ball::Precision precision(e.precision_bits);
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    const Rational stated = parse_decimal(f.certified_radius[i]);
    for (std::size_t j = 0; j < f.rows[i].size(); ++j) {
      const double d = e.values[i][j].distance_bound(parse_decimal(f.rows[i][j]));
      if (!(Rational(d) <= stated))
        problems.push_back(where + ": " + f.columns[j] + " at t = " + f.times[i] + " (" + f.rows[i][j] +
                           ") is not within its certified radius " + f.certified_radius[i] +
                           " of the exact solution: the certified enclosure " + e.values[i][j].to_string(55) +
                           " puts it up to " + short_number(d) + " away");
    }
  }
  return problems;
}

}  // namespace gm::golden
