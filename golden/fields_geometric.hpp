// The vector fields once more, for the golden trajectories' second integrator: written in the
// notes' vector and matrix forms (cross products, commutators, the Nambu form), where the Taylor
// oracle's oracle/fields.hpp writes each component out. Two transcriptions of each system, two
// integrators: a slip in either shows as a disagreement when a fixture is generated.
//
// Each field: dim, and operator()(const std::vector<T>& x, std::vector<T>& dxdt) in the column
// order of golden/systems.cpp.
#pragma once

#include <array>
#include <vector>

namespace gm::golden::geometric {

template <class T>
using V3 = std::array<T, 3>;

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
V3<T> load3(const std::vector<T>& x, int at) {
  return {x[at], x[at + 1], x[at + 2]};
}

template <class T>
void store3(const V3<T>& v, std::vector<T>& x, int at) {
  x[at] = v[0];
  x[at + 1] = v[1];
  x[at + 2] = v[2];
}

// (3.8): dPi/dt = Pi x Omega, Omega = I^-1 Pi.
template <class T>
struct FreeRigidBody {
  int dim = 3;
  V3<T> I;
  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    const V3<T> Pi = load3(x, 0);
    const V3<T> W = {Pi[0] / I[0], Pi[1] / I[1], Pi[2] / I[2]};
    store3(cross(Pi, W), dx, 0);
  }
};

// (2.20): dPi/dt = Pi x Omega, dO/dt = O hat(Omega), with the hat matrix of (2.11)
// (hat(W) v = W x v) built explicitly and multiplied: (O hat(W))_ij = sum_k O_ik hat(W)_kj.
template <class T>
struct RigidBodyAttitude {
  int dim = 12;
  V3<T> I;
  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    const V3<T> Pi = load3(x, 0);
    const V3<T> W = {Pi[0] / I[0], Pi[1] / I[1], Pi[2] / I[2]};
    store3(cross(Pi, W), dx, 0);
    const T zero(0);
    const T hat[3][3] = {{zero, T(-W[2]), W[1]}, {W[2], zero, T(-W[0])}, {T(-W[1]), W[0], zero}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T s = x[3 + 3 * i] * hat[0][j];
        for (int k = 1; k < 3; ++k) s += x[3 + 3 * i + k] * hat[k][j];
        dx[3 + 3 * i + j] = s;
      }
  }
};

// (3.21): Pi = P x Q, Omega = I^-1 Pi, dQ/dt = -Omega x Q, dP/dt = -Omega x P.
template <class T>
struct Clebsch {
  int dim = 6;
  V3<T> I;
  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    const V3<T> Q = load3(x, 0), P = load3(x, 3);
    const V3<T> Pi = cross(P, Q);
    const V3<T> W = {Pi[0] / I[0], Pi[1] / I[1], Pi[2] / I[2]};
    V3<T> dQ = cross(W, Q), dP = cross(W, P);
    for (int i = 0; i < 3; ++i) dQ[i] = -dQ[i], dP[i] = -dP[i];
    store3(dQ, dx, 0);
    store3(dP, dx, 3);
  }
};

// (2.34) with attitude: Omega solves A Omega + Omega A = M (A = diag(a): Omega_ij = M_ij/(a_i+a_j)),
// dM/dt = M Omega - Omega M, dO/dt = O Omega; full n x n matrix products.
template <class T>
struct Manakov {
  int n = 0;
  int dim = 0;
  std::vector<T> a;
  explicit Manakov(std::vector<T> diag) : n(static_cast<int>(diag.size())), dim(2 * n * n), a(std::move(diag)) {}
  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    const std::size_t nn = static_cast<std::size_t>(n * n);
    std::vector<T> W(nn);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) W[i * n + j] = x[i * n + j] / (a[i] + a[j]);
    auto product = [&](const T* A, const T* B, int i, int j) {
      T s = A[i * n] * B[j];
      for (int k = 1; k < n; ++k) s += A[i * n + k] * B[k * n + j];
      return s;
    };
    const T* M = x.data();
    const T* O = x.data() + nn;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        dx[i * n + j] = product(M, W.data(), i, j) - product(W.data(), M, i, j);
        dx[nn + i * n + j] = product(O, W.data(), i, j);
      }
  }
};

// (3.16) in the Nambu form (3.14): dx/dt = grad C x grad H / 4 with C = a2 x1^2 + a3 x3^2 and
// H = a1 x2^2 + a3 x3^2. (The notes' answer prints C = a1 x1^2 + a3 x3^2, H = a2 x2^2 + a3 x3^2,
// which generate (3.16) with a1 and a2 exchanged: catalogue entry s3.nambu-3.16.)
template <class T>
struct Nambu316 {
  int dim = 3;
  V3<T> a;
  void operator()(const std::vector<T>& x, std::vector<T>& dx) const {
    const V3<T> gradC = {T(T(2) * a[1] * x[0]), T(0), T(T(2) * a[2] * x[2])};
    const V3<T> gradH = {T(0), T(T(2) * a[0] * x[1]), T(T(2) * a[2] * x[2])};
    V3<T> v = cross(gradC, gradH);
    for (auto& c : v) c /= T(4);
    store3(v, dx, 0);
  }
};

}  // namespace gm::golden::geometric
