// First variations of actions along curves, by Gauss-Legendre quadrature refined until round-off
// (Theorems 1.1 (iii), 2.1, Propositions 2.3, 2.4, 3.1 and the exercise (2.24)).
//
// Along a true solution the first variation delta S = int_0^T f(t) dt of the action, for
// variations vanishing at the end points, is zero; numerically it is zero up to the quadrature
// error (which falls geometrically with the number n of Gauss points, f being analytic) and the
// round-off of f. The property samples the flow once at the nodes of the rules n = 4, 8, 16, 32
// on [0, T] (and 64 in 50 digits, where the Euler-Poincare flows of sl(2, R), whose solutions
// have complex singularities closer to the real axis, need it to reach 1e-48), and checks:
//   - along a perturbed curve (the same flow plus a smooth bump) the finest rule gives a value at
//     least 10^3 times the round-off bound, so the check can tell a solution from a non-solution
//     (otherwise the case is discarded);
//   - the finest value is at round-off: |delta S| <= k eps scale;
//   - the values converge: each one above that bound is smaller than the previous one.
// The values are recorded as a series (|delta S| against n) for the report.
#pragma once

#include "core/linalg.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/variational/support/quadrature.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace gm::var {

template <class T>
struct GaussGrid {
  std::vector<int> ns;                                        // points of each rule
  std::vector<T> times;                                       // all nodes, ascending
  std::vector<std::vector<std::pair<std::size_t, T>>> rules;  // per rule: (index in times, weight)
};

template <class T>
std::vector<int> default_rules() {
  if (std::is_same_v<T, double>) return {4, 8, 16, 32};
  return {4, 8, 16, 32, 64, 128};
}

template <class T>
GaussGrid<T> gauss_grid(const T& t_end, const std::vector<int>& ns = default_rules<T>()) {
  GaussGrid<T> g;
  g.ns = ns;
  std::vector<std::pair<T, std::pair<int, T>>> all;  // (time, (rule, weight))
  for (std::size_t r = 0; r < ns.size(); ++r) {
    const auto rule = quad::composite<T>(T(0), t_end, ns[r], 1);
    for (std::size_t i = 0; i < rule.x.size(); ++i) all.push_back({rule.x[i], {static_cast<int>(r), rule.w[i]}});
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  g.rules.resize(ns.size());
  for (const auto& [t, rw] : all) {
    if (g.times.empty() || g.times.back() != t) g.times.push_back(t);
    g.rules[rw.first].push_back({g.times.size() - 1, rw.second});
  }
  return g;
}

template <class T>
T integrate(const GaussGrid<T>& g, std::size_t rule, const std::vector<T>& f) {
  T s(0);
  for (const auto& [i, w] : g.rules[rule]) s += w * f[i];
  return s;
}

// The checks described above. `f` and `f_perturbed` are the integrand at g.times along the
// solution and along the perturbed curve; `scale` the size of the integral's round-off (the
// property says how it is made). A case whose perturbed curve does not give a clearly non-zero
// delta S cannot tell a solution from a non-solution (a degenerate draw: a variation parallel to
// the perturbation, a body at rest): it is discarded, not failed, so that shrinking a real
// failure never ends on such a case.
template <class T>
void require_vanishing_and_convergence(const std::string& what, const GaussGrid<T>& g, const std::vector<T>& f,
                                       const T& scale, double k) {
  const T allowed = T(k) * eps<T>() * scale;
  std::vector<T> values;
  for (std::size_t r = 0; r < g.rules.size(); ++r) values.push_back(integrate(g, r, f));
  Series ser{"first variation: " + what,
             std::string("|delta S| (") + ScalarInfo<T>::name + ")",
             "Gauss points",
             "|delta S|",
             true,
             true,
             {},
             0};
  for (std::size_t r = 0; r < values.size(); ++r) ser.points.emplace_back(g.ns[r], to_double(abs_value(values[r])));
  record_series(ser);
  std::string table;
  for (std::size_t r = 0; r < values.size(); ++r) {
    char line[120];
    std::snprintf(line, sizeof line, "    %2d Gauss points: delta S = %.6g\n", g.ns[r], to_double(values[r]));
    table += line;
  }
  require_close(what + ": delta S = 0 along the solution (finest quadrature)", values.back(), T(0), scale, k);
  for (std::size_t r = 1; r < values.size(); ++r)
    if (abs_value(values[r - 1]) > allowed && abs_value(values[r]) > allowed)
      require(what + ": the first variation converges as the quadrature is refined",
              abs_value(values[r]) < abs_value(values[r - 1]), "it does not:\n" + table);
}

template <class T>
void require_first_variation_vanishes(const std::string& what, const GaussGrid<T>& g, const std::vector<T>& f,
                                      const std::vector<T>& f_perturbed, const T& scale, double k) {
  const T allowed = T(k) * eps<T>() * scale;
  const T perturbed = integrate(g, g.rules.size() - 1, f_perturbed);
  if (!(abs_value(perturbed) > T(1000) * allowed))
    RC_DISCARD("the perturbed curve's first variation is not clearly non-zero: this case cannot tell a solution");
  require_vanishing_and_convergence(what, g, f, scale, k);
}

// Both directions of an "if and only if" between the equations and stationarity (Theorem 1.1
// (iii) <=> (iv), Proposition 2.4): along the solution delta S = 0 for the variation of `f` (as
// above), and the perturbed curve, which does not solve the equations, is not stationary: for
// some variation among those of `f_perturbed` (the drawn one and the coordinate bumps
// t (T - t) e_j, t^2 (T - t) e_j, which no non-zero continuous residual of the equations can be
// orthogonal to all at once unless it is degenerate), delta S is clearly non-zero (> 1000 times
// the round-off bound). A failing assertion, not a discard: a subject for which a non-solution is
// stationary (e.g. a Lagrangian that does not depend on the velocity) fails it.
template <class T>
void require_first_variation_vanishes_iff(const std::string& what, const GaussGrid<T>& g, const std::vector<T>& f,
                                          const std::vector<std::vector<T>>& f_perturbed, const T& scale, double k) {
  const T allowed = T(k) * eps<T>() * scale;
  T best(0);
  for (const auto& fp : f_perturbed) best = std::max(best, abs_value(integrate(g, g.rules.size() - 1, fp)));
  char detail[200];
  std::snprintf(detail, sizeof detail, "max |delta S| over %zu variations = %.6g, round-off bound %.6g",
                f_perturbed.size(), to_double(best), to_double(allowed));
  require(what + ": converse: a curve that does not solve the equations has a non-zero first variation",
          best > T(1000) * allowed, detail);
  require_vanishing_and_convergence(what, g, f, scale, k);
}

}  // namespace gm::var
