// The condition of a trajectory: how much an error in the state at time 0 can grow by time t,
// kappa(t) = |dx(t)/dx(0)|_inf (the induced infinity norm of the flow's Jacobian, max row sum).
// An error e in x(0) becomes at most kappa(t) |e|_inf at time t, so kappa sets the scale of the
// tolerance a lower-precision reproduction of a fixture can be held to (golden/regression.hpp).
//
// Computed with the Taylor oracle on the variational equations: each state variable becomes a
// jet (value, d value / d x(0)_j for every j), so any polynomial field written for the oracle
// yields its tangent field unchanged; the full Jacobian is integrated alongside the state. Only
// two or three digits of kappa matter, so it is computed in double.
#pragma once

#include "oracle/taylor.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gm::golden {

// A first-order jet over S: a value and its derivatives along k directions.
template <class S>
struct Jet {
  S v{};
  std::vector<S> d;

  friend Jet operator+(const Jet& a, const Jet& b) {
    Jet r{S(a.v + b.v), {}};
    r.d.resize(a.d.size());
    for (std::size_t j = 0; j < a.d.size(); ++j) r.d[j] = a.d[j] + b.d[j];
    return r;
  }
  friend Jet operator-(const Jet& a, const Jet& b) {
    Jet r{S(a.v - b.v), {}};
    r.d.resize(a.d.size());
    for (std::size_t j = 0; j < a.d.size(); ++j) r.d[j] = a.d[j] - b.d[j];
    return r;
  }
  friend Jet operator-(const Jet& a) {
    Jet r{S(-a.v), {}};
    r.d.resize(a.d.size());
    for (std::size_t j = 0; j < a.d.size(); ++j) r.d[j] = -a.d[j];
    return r;
  }
  friend Jet operator*(const Jet& a, const Jet& b) {
    Jet r{S(a.v * b.v), {}};
    r.d.resize(a.d.size());
    for (std::size_t j = 0; j < a.d.size(); ++j) r.d[j] = a.v * b.d[j] + a.d[j] * b.v;
    return r;
  }
  template <class C>
  friend Jet operator*(const Jet& a, const C& c) {
    Jet r{S(a.v * c), {}};
    r.d.resize(a.d.size());
    for (std::size_t j = 0; j < a.d.size(); ++j) r.d[j] = a.d[j] * c;
    return r;
  }
  Jet& operator+=(const Jet& b) { return *this = *this + b; }
  Jet& operator-=(const Jet& b) { return *this = *this - b; }
};

// The field together with its variational equations: state (x, Y) with Y = dx/dx(0) (dim x dim,
// row-major), dY/dt = Df(x) Y.
template <class Field>
struct TangentField {
  const Field& f;
  int n;    // dimension of the underlying field
  int dim;  // n + n * n
  TangentField(const Field& field, int base_dim) : f(field), n(base_dim), dim(base_dim + base_dim * base_dim) {}

  template <class S>
  void operator()(const S* x, S* dx) const {
    std::vector<Jet<S>> xs(n), dxs(n);
    for (int i = 0; i < n; ++i) {
      xs[i].v = x[i];
      xs[i].d.assign(x + n + i * n, x + n + (i + 1) * n);
    }
    f(xs.data(), dxs.data());
    for (int i = 0; i < n; ++i) {
      dx[i] = dxs[i].v;
      if (dxs[i].d.empty()) {
        // A component the field set from constants alone: derivative zero.
        for (int j = 0; j < n; ++j) dx[n + i * n + j] = x[i] * 0.0;
      } else {
        for (int j = 0; j < n; ++j) dx[n + i * n + j] = dxs[i].d[j];
      }
    }
  }
};

// max over the sample times of |dx(t)/dx(0)|_inf, for an oracle field over double.
template <class Field>
double trajectory_condition(const Field& f, int n, const std::vector<double>& x0, const std::vector<double>& times) {
  TangentField<Field> tf(f, n);
  std::vector<double> y0(static_cast<std::size_t>(tf.dim), 0.0);
  std::copy(x0.begin(), x0.end(), y0.begin());
  for (int i = 0; i < n; ++i) y0[n + i * n + i] = 1.0;
  oracle::TaylorSolver<double, TangentField<Field>> solver(tf, tf.dim, 1e-13);
  solver.set_limits(1000000, 1e100);
  const auto samples = solver.sample(y0, 0.0, times);
  double kappa = 1.0;
  for (const auto& y : samples)
    for (int i = 0; i < n; ++i) {
      double row = 0.0;
      for (int j = 0; j < n; ++j) row += std::abs(y[n + i * n + j]);
      kappa = std::max(kappa, row);
    }
  return kappa;
}

}  // namespace gm::golden
