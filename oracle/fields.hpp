// The polynomial vector fields integrated by the Taylor oracle (oracle/taylor.hpp), written
// from the notes' equations directly on arrays (independently of impl/). Each field has `dim`
// and a function template operator()(const S* x, S* dxdt) using only +, -, *, and constants.
#pragma once

#include <stdexcept>
#include <vector>

namespace gm::oracle {

// Free rigid body, (3.7): state Pi (3).
// dPi1/dt = (1/I3 - 1/I2) Pi2 Pi3, dPi2/dt = (1/I1 - 1/I3) Pi3 Pi1, dPi3/dt = (1/I2 - 1/I1) Pi1 Pi2.
template <class T>
struct FreeRigidBodyField {
  int dim = 3;
  T c1, c2, c3;
  FreeRigidBodyField(const T& I1, const T& I2, const T& I3)
      : c1(T(1) / I3 - T(1) / I2), c2(T(1) / I1 - T(1) / I3), c3(T(1) / I2 - T(1) / I1) {}
  template <class S>
  void operator()(const S* x, S* dx) const {
    dx[0] = (x[1] * x[2]) * c1;
    dx[1] = (x[2] * x[0]) * c2;
    dx[2] = (x[0] * x[1]) * c3;
  }
};

// Rigid body with attitude, (2.20): state (Pi, O) with O row-major: x[3 + 3 i + j] = O_ij.
// dPi/dt = Pi x Omega (as (3.7)), dO/dt = O hat(Omega), Omega = I^-1 Pi.
template <class T>
struct RigidBodyAttitudeField {
  int dim = 12;
  T c1, c2, c3, inv1, inv2, inv3;
  RigidBodyAttitudeField(const T& I1, const T& I2, const T& I3)
      : c1(T(1) / I3 - T(1) / I2),
        c2(T(1) / I1 - T(1) / I3),
        c3(T(1) / I2 - T(1) / I1),
        inv1(T(1) / I1),
        inv2(T(1) / I2),
        inv3(T(1) / I3) {}
  template <class S>
  void operator()(const S* x, S* dx) const {
    dx[0] = (x[1] * x[2]) * c1;
    dx[1] = (x[2] * x[0]) * c2;
    dx[2] = (x[0] * x[1]) * c3;
    const S W1 = x[0] * inv1, W2 = x[1] * inv2, W3 = x[2] * inv3;
    const S* O = x + 3;
    S* dO = dx + 3;
    // hat(W) = [[0, -W3, W2], [W3, 0, -W1], [-W2, W1, 0]]
    for (int i = 0; i < 3; ++i) {
      dO[3 * i + 0] = O[3 * i + 1] * W3 - O[3 * i + 2] * W2;
      dO[3 * i + 1] = O[3 * i + 2] * W1 - O[3 * i + 0] * W3;
      dO[3 * i + 2] = O[3 * i + 0] * W2 - O[3 * i + 1] * W1;
    }
  }
};

// Clebsch system (3.21): state (Q, P), Pi = P x Q, Omega = I^-1 Pi, dQ/dt = -Omega x Q,
// dP/dt = -Omega x P.
template <class T>
struct ClebschField {
  int dim = 6;
  T inv1, inv2, inv3;
  ClebschField(const T& I1, const T& I2, const T& I3) : inv1(T(1) / I1), inv2(T(1) / I2), inv3(T(1) / I3) {}
  template <class S>
  void operator()(const S* x, S* dx) const {
    const S* Q = x;
    const S* P = x + 3;
    const S W1 = (P[1] * Q[2] - P[2] * Q[1]) * inv1;
    const S W2 = (P[2] * Q[0] - P[0] * Q[2]) * inv2;
    const S W3 = (P[0] * Q[1] - P[1] * Q[0]) * inv3;
    // -W x V = V x W
    auto minus_w_cross = [&](const S* V, S* out) {
      out[0] = V[1] * W3 - V[2] * W2;
      out[1] = V[2] * W1 - V[0] * W3;
      out[2] = V[0] * W2 - V[1] * W1;
    };
    minus_w_cross(Q, dx);
    minus_w_cross(P, dx + 3);
  }
};

// Manakov's SO(n) rigid body with attitude, (2.34) and section 2.4, for A = diag(a):
// state (M, O), both n x n row-major; Omega_ij = M_ij / (a_i + a_j); dM/dt = [M, Omega],
// dO/dt = O Omega. M is kept skew: only i < j is computed, dM_ji = -dM_ij.
template <class T>
struct ManakovField {
  int n;
  int dim;
  std::vector<T> inv_sum;  // 1 / (a_i + a_j)
  explicit ManakovField(const std::vector<T>& a) : n(static_cast<int>(a.size())), dim(2 * n * n), inv_sum(n * n) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (a[i] + a[j] == T(0)) throw std::invalid_argument("ManakovField: a_i + a_j = 0");
        inv_sum[i * n + j] = T(1) / (a[i] + a[j]);
      }
  }
  template <class S>
  void operator()(const S* x, S* dx) const {
    const S* M = x;
    const S* O = x + n * n;
    std::vector<S> W(n * n);
    std::vector<bool> nonzero(n * n, false);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) {
          W[i * n + j] = M[i * n + j] * inv_sum[i * n + j];
          nonzero[i * n + j] = true;
        }
    for (int i = 0; i < n; ++i) {
      dx[i * n + i] = M[i * n + i] * T(0);
      for (int j = i + 1; j < n; ++j) {
        S s{};
        bool first = true;
        for (int k = 0; k < n; ++k) {
          if (nonzero[k * n + j]) {
            const S term = M[i * n + k] * W[k * n + j];
            s = first ? term : S(s + term);
            first = false;
          }
          if (nonzero[i * n + k]) {
            const S term = W[i * n + k] * M[k * n + j];
            s = first ? S(-term) : S(s - term);
            first = false;
          }
        }
        dx[i * n + j] = s;
        dx[j * n + i] = -s;
      }
    }
    S* dO = dx + n * n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        S s{};
        bool first = true;
        for (int k = 0; k < n; ++k)
          if (nonzero[k * n + j]) {
            const S term = O[i * n + k] * W[k * n + j];
            s = first ? term : S(s + term);
            first = false;
          }
        dO[i * n + j] = s;
      }
  }
};

// The system (3.16): dx1/dt = -a1 a3 x2 x3, dx2/dt = -a2 a3 x3 x1, dx3/dt = a1 a2 x1 x2.
template <class T>
struct Nambu316Field {
  int dim = 3;
  T k1, k2, k3;
  Nambu316Field(const T& a1, const T& a2, const T& a3) : k1(-a1 * a3), k2(-a2 * a3), k3(a1 * a2) {}
  template <class S>
  void operator()(const S* x, S* dx) const {
    dx[0] = (x[1] * x[2]) * k1;
    dx[1] = (x[2] * x[0]) * k2;
    dx[2] = (x[0] * x[1]) * k3;
  }
};

}  // namespace gm::oracle
