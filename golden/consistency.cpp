#include "golden/consistency.hpp"

#include "golden/invariants.hpp"

namespace gm::golden {

ConsistencyReport check_consistency(const Fixture& f, const Problem& pr) {
  using R = Real70;
  ConsistencyReport rep;
  const int dim = pr.dim();
  // t = 0 row: the exact initial data rounded.
  if (!f.times.empty() && f.times.front() == "0") {
    for (int k = 0; k < dim; ++k) {
      const std::string expect = format_significant(pr.x0[k], f.digits);
      if (f.rows[0][k] != expect)
        rep.problems.push_back(f.source + ":" + std::to_string(f.row_lines.empty() ? 0 : f.row_lines[0]) + ": column " +
                               f.columns[k] + " at t = 0 is " + f.rows[0][k] + ", the initial data rounded is " +
                               expect);
    }
  }
  std::vector<R> x0;
  for (const auto& v : pr.x0) x0.push_back(convert<R>(v));
  const auto reference = invariants<R>(pr, x0);
  const auto values = f.values_as<R>();
  const R room = convert<R>(pow10(10 - f.digits));
  for (const auto& inv : reference) {
    InvariantDrift d;
    d.name = inv.name;
    d.value = format_significant(convert<Rational>(inv.value), 6);
    const R a = abs(inv.value);
    const R allowed = room * (a > R(1) ? a : R(1));
    d.allowed = allowed.convert_to<double>();
    rep.invariants.push_back(d);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto at = invariants<R>(pr, values[i]);
    for (std::size_t k = 0; k < at.size(); ++k) {
      const R drift = abs(R(at[k].value - reference[k].value));
      InvariantDrift& d = rep.invariants[k];
      const double dd = drift.convert_to<double>();
      if (dd > d.max_drift || d.worst_time.empty()) {
        d.max_drift = dd;
        d.worst_time = f.times[i];
      }
      if (!(dd <= d.allowed))
        rep.problems.push_back(f.source + ":" + std::to_string(i < f.row_lines.size() ? f.row_lines[i] : 0) +
                               ": invariant " + d.name + " drifts by " +
                               format_significant(convert<Rational>(drift), 2) + " at t = " + f.times[i] +
                               " (allowed " + format_significant(Rational(d.allowed), 2) + ")");
    }
  }
  for (const auto& d : rep.invariants)
    if (d.max_drift > rep.max_drift) rep.max_drift = d.max_drift;
  return rep;
}

}  // namespace gm::golden
