// regress<T> (golden/regression.hpp), included once per scalar by regression_<scalar>.cpp.
#pragma once

#include "golden/extrapolation.hpp"
#include "golden/regression.hpp"

#include <cmath>
#include <sstream>

namespace gm::golden {

namespace regression_detail {

template <class T>
struct SubjectField {
  const Subject<T>* s;
  const Problem* pr;
  std::vector<T> p;
  int n;

  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    switch (pr->info->id) {
      case SystemId::FreeRigidBody: {
        const Vec3<T> I(p[0], p[1], p[2]), Pi(x[0], x[1], x[2]);
        const Vec3<T> d = s->euler_3_8(I, Pi);
        for (int i = 0; i < 3; ++i) dx[i] = d(i);
        break;
      }
      case SystemId::RigidBodyAttitude: {
        const Vec3<T> I(p[0], p[1], p[2]), Pi(x[0], x[1], x[2]);
        Mat3<T> O;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) O(i, j) = x[3 + 3 * i + j];
        const Vec3<T> dPi = s->euler_3_8(I, Pi);
        const Mat3<T> dO = s->reconstruction_2_10(O, s->omega_3_5(I, Pi));
        for (int i = 0; i < 3; ++i) dx[i] = dPi(i);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) dx[3 + 3 * i + j] = dO(i, j);
        break;
      }
      case SystemId::Clebsch: {
        const Vec3<T> I(p[0], p[1], p[2]), Q(x[0], x[1], x[2]), P(x[3], x[4], x[5]);
        const auto [dQ, dP] = s->clebsch_3_21(I, Q, P);
        for (int i = 0; i < 3; ++i) dx[i] = dQ(i), dx[3 + i] = dP(i);
        break;
      }
      case SystemId::Manakov: {
        MatX<T> A = MatX<T>::Zero(n, n), M(n, n), O(n, n);
        for (int i = 0; i < n; ++i) A(i, i) = p[i];
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) M(i, j) = x[i * n + j], O(i, j) = x[n * n + i * n + j];
        const MatX<T> dM = s->manakov_2_34(A, M);
        const MatX<T> W = s->manakov_Omega(A, M);
        if (dM.rows() != n || dM.cols() != n || W.rows() != n || W.cols() != n)
          throw std::runtime_error("manakov_2_34 or manakov_Omega returned a matrix of the wrong size");
        const MatX<T> dO = O * W;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) dx[i * n + j] = dM(i, j), dx[n * n + i * n + j] = dO(i, j);
        break;
      }
      case SystemId::Nambu316: {
        const Vec3<T> a(p[0], p[1], p[2]), X(x[0], x[1], x[2]);
        const Vec3<T> d = s->nambu_3_16(a, X);
        for (int i = 0; i < 3; ++i) dx[i] = d(i);
        break;
      }
    }
  }
};

template <class T>
std::string show(const T& v) {
  return to_string_full(v);
}

}  // namespace regression_detail

template <class T>
RegressionResult regress(const Fixture& f, const Problem& pr, const Subject<T>& subject) {
  RegressionResult r;
  r.fixture = f.name;
  r.scalar = ScalarInfo<T>::name;
  for (const auto& slot : pr.info->slots)
    if (!subject.provides(slot)) r.missing_slots.push_back(slot);
  if (!r.missing_slots.empty()) return r;

  const bool is_double = std::is_same_v<T, double>;
  ExtrapolationSettings<T> settings;
  settings.columns = is_double ? 8 : 12;
  settings.tolerance = is_double ? from_decimal<T>("1e-14") : from_decimal<T>("1e-44");
  settings.max_steps = 200000;

  regression_detail::SubjectField<T> field{&subject, &pr, {}, pr.n};
  for (const auto& v : pr.p) field.p.push_back(convert<T>(v));
  std::vector<T> x0;
  for (const auto& v : pr.x0) x0.push_back(convert<T>(v));
  const std::vector<T> times = f.times_as<T>();
  const std::vector<std::vector<T>> expected = f.values_as<T>();

  std::vector<std::vector<T>> got;
  ExtrapolationSolver<T, regression_detail::SubjectField<T>> solver(field, pr.dim(), settings);
  try {
    got = solver.sample(x0, T(0), times);
  } catch (const std::exception& e) {
    r.failure = std::string("the integration of the subject's field failed: ") + e.what();
    r.steps = solver.stats().steps;
    return r;
  }
  r.steps = solver.stats().steps;
  r.evaluations = solver.stats().evaluations;

  T largest(1);
  for (const auto& row : expected)
    for (const auto& v : row)
      if (abs_value(v) > largest) largest = abs_value(v);
  const double kappa = to_double(parse_decimal(f.condition));
  const double eps = eps_double<T>();
  const double scale = to_double(largest) * kappa;
  if (is_double) {
    const double k = 16.0 * static_cast<double>(r.steps + 1);
    r.tolerance = k * eps * scale;
    std::ostringstream rule;
    rule.precision(3);
    rule << "k eps scale, k = 16 (steps + 1) = " << k << ", scale = max(1,|x|) kappa = " << to_double(largest) << " * "
         << kappa;
    r.tolerance_rule = rule.str();
  } else {
    r.tolerance = 1e-35;
    r.tolerance_rule = "1e-35 absolute (50-digit regression)";
  }

  double sum_sq = 0;
  long count = 0;
  T worst(-1);
  bool finite_all = true;
  for (std::size_t i = 0; i < got.size(); ++i)
    for (std::size_t k = 0; k < got[i].size(); ++k) {
      if (!is_finite(got[i][k])) finite_all = false;
      const T err = abs_value(T(got[i][k] - expected[i][k]));
      const double e = to_double(err);
      const double units = e / (eps * scale);
      sum_sq += units * units;
      ++count;
      if (!(err <= worst)) {
        worst = err;
        r.max_error = e;
        r.max_eps_units = units;
        r.worst = "t = " + f.times[i] + ", column " + f.columns[k] + ": subject " + regression_detail::show(got[i][k]) +
                  ", fixture " + f.rows[i][k];
      }
    }
  r.rms_eps_units = count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0;
  if (!finite_all) {
    r.failure = "the subject's trajectory has a non-finite value (NaN or Inf); a NaN is never a pass";
    return r;
  }
  r.pass = r.max_error <= r.tolerance;
  if (!r.pass) r.failure = "error above the tolerance";
  return r;
}

}  // namespace gm::golden
