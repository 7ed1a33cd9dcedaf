// What stays constant along a trajectory of each system, evaluated at one state in any floating
// scalar T. The fixture consistency test requires every one of them to take the same value at
// every sample (to <= 1e-40 for 50-digit fixtures); the harness may use them on students'
// trajectory files in double.
//
//   free_rigid_body      |Pi|^2 (Casimir), Pi . I^-1 Pi (twice the energy)
//   rigid_body_attitude  the above, the spatial angular momentum pi = O Pi (Theorem 2.2; the
//                        printed (2.30) is inverted, erratum sec2.noether-2.30), (O^T O)_ij, det O
//   clebsch              |Q|^2, |P|^2, P . Q (Q and P rotate together), |Pi|^2, Pi . I^-1 Pi
//                        with Pi = P x Q
//   manakov              tr(M^k), k even (the spectrum of M), tr((M + A^2)^k), k = 2..n
//                        (Manakov's integrals from the Lax pair d/dt(M + l A^2) = [M + l A^2,
//                        Omega + l A], at l = 1), tr(M Omega) (energy), the spatial momentum
//                        O M O^T, (O^T O)_ij, det O, and M_ij + M_ji (skew)
//   nambu_3_16           a2 x1^2 + a3 x3^2 and a1 x2^2 + a3 x3^2 (the Nambu functions: (3.16) is
//                        x' = grad of the first x grad of the second / 4), and |x|^2 when
//                        1/a1 + 1/a2 = 1/a3 holds exactly (then (3.16) is a rigid body)
#pragma once

#include "golden/systems.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace gm::golden {

template <class T>
struct InvariantValue {
  std::string name;
  T value;
};

namespace detail {

template <class T>
std::vector<T> matmul(const std::vector<T>& a, const std::vector<T>& b, int n) {
  std::vector<T> c(static_cast<std::size_t>(n * n), T(0));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const T aik = a[i * n + k];
      for (int j = 0; j < n; ++j) c[i * n + j] += aik * b[k * n + j];
    }
  return c;
}

template <class T>
T trace(const std::vector<T>& a, int n) {
  T s(0);
  for (int i = 0; i < n; ++i) s += a[i * n + i];
  return s;
}

template <class T>
T abs_of(const T& x) {
  return x < T(0) ? T(-x) : x;
}

// det by elimination with partial pivoting (the matrices here are rotations: well conditioned).
template <class T>
T determinant(std::vector<T> a, int n) {
  T det(1);
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (abs_of(a[r * n + c]) > abs_of(a[piv * n + c])) piv = r;
    if (a[piv * n + c] == T(0)) return T(0);
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(a[c * n + k], a[piv * n + k]);
      det = -det;
    }
    det *= a[c * n + c];
    for (int r = c + 1; r < n; ++r) {
      const T f = a[r * n + c] / a[c * n + c];
      for (int k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
    }
  }
  return det;
}

template <class T>
void orthogonality(const std::vector<T>& O, int n, std::vector<InvariantValue<T>>& out) {
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      T s(0);
      for (int k = 0; k < n; ++k) s += O[k * n + i] * O[k * n + j];
      out.push_back({"(O^T O)_" + std::to_string(i + 1) + std::to_string(j + 1), s});
    }
  out.push_back({"det O", determinant(O, n)});
}

}  // namespace detail

template <class T>
std::vector<InvariantValue<T>> invariants(const Problem& pr, const std::vector<T>& x) {
  std::vector<T> p;
  for (const auto& v : pr.p) p.push_back(convert<T>(v));
  std::vector<InvariantValue<T>> out;
  auto rigid = [&](const T* Pi) {
    out.push_back({"|Pi|^2", Pi[0] * Pi[0] + Pi[1] * Pi[1] + Pi[2] * Pi[2]});
    out.push_back({"Pi.I^-1 Pi", Pi[0] * Pi[0] / p[0] + Pi[1] * Pi[1] / p[1] + Pi[2] * Pi[2] / p[2]});
  };
  switch (pr.info->id) {
    case SystemId::FreeRigidBody:
      rigid(x.data());
      break;
    case SystemId::RigidBodyAttitude: {
      rigid(x.data());
      const T* O = x.data() + 3;
      for (int i = 0; i < 3; ++i)
        out.push_back({"pi" + std::to_string(i + 1) + " = (O Pi)_" + std::to_string(i + 1),
                       O[3 * i] * x[0] + O[3 * i + 1] * x[1] + O[3 * i + 2] * x[2]});
      detail::orthogonality(std::vector<T>(x.begin() + 3, x.begin() + 12), 3, out);
      break;
    }
    case SystemId::Clebsch: {
      const T* Q = x.data();
      const T* P = x.data() + 3;
      out.push_back({"|Q|^2", Q[0] * Q[0] + Q[1] * Q[1] + Q[2] * Q[2]});
      out.push_back({"|P|^2", P[0] * P[0] + P[1] * P[1] + P[2] * P[2]});
      out.push_back({"P.Q", P[0] * Q[0] + P[1] * Q[1] + P[2] * Q[2]});
      const T Pi[3] = {P[1] * Q[2] - P[2] * Q[1], P[2] * Q[0] - P[0] * Q[2], P[0] * Q[1] - P[1] * Q[0]};
      rigid(Pi);
      break;
    }
    case SystemId::Manakov: {
      const int n = pr.n;
      const std::size_t nn = static_cast<std::size_t>(n * n);
      const std::vector<T> M(x.begin(), x.begin() + nn), O(x.begin() + nn, x.begin() + 2 * nn);
      std::vector<T> Mk = M;
      for (int k = 2; k <= n; ++k) {
        Mk = detail::matmul(Mk, M, n);
        if (k % 2 == 0) out.push_back({"tr(M^" + std::to_string(k) + ")", detail::trace(Mk, n)});
      }
      std::vector<T> L = M;
      for (int i = 0; i < n; ++i) L[i * n + i] += p[i] * p[i];
      std::vector<T> Lk = L;
      for (int k = 2; k <= n; ++k) {
        Lk = detail::matmul(Lk, L, n);
        out.push_back({"tr((M + A^2)^" + std::to_string(k) + ")", detail::trace(Lk, n)});
      }
      std::vector<T> W(nn);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) W[i * n + j] = M[i * n + j] / (p[i] + p[j]);
      out.push_back({"tr(M Omega)", detail::trace(detail::matmul(M, W, n), n)});
      std::vector<T> Ot(nn);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) Ot[i * n + j] = O[j * n + i];
      const std::vector<T> m = detail::matmul(detail::matmul(O, M, n), Ot, n);
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          out.push_back({"(O M O^T)_" + std::to_string(i + 1) + std::to_string(j + 1), m[i * n + j]});
      detail::orthogonality(O, n, out);
      for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j)
          out.push_back({"M_" + std::to_string(i + 1) + std::to_string(j + 1) + " + M_" + std::to_string(j + 1) +
                             std::to_string(i + 1),
                         M[i * n + j] + M[j * n + i]});
      break;
    }
    case SystemId::Nambu316: {
      out.push_back({"a2 x1^2 + a3 x3^2", p[1] * x[0] * x[0] + p[2] * x[2] * x[2]});
      out.push_back({"a1 x2^2 + a3 x3^2", p[0] * x[1] * x[1] + p[2] * x[2] * x[2]});
      const Rational& a1 = pr.p[0];
      const Rational& a2 = pr.p[1];
      const Rational& a3 = pr.p[2];
      if (Rational(1) / a1 + Rational(1) / a2 == Rational(1) / a3)
        out.push_back({"|x|^2", x[0] * x[0] + x[1] * x[1] + x[2] * x[2]});
      break;
    }
  }
  return out;
}

}  // namespace gm::golden
