// Manakov's commutator form of the rigid body on SO(n) (section 2.2, 2.4, closing exercise).
// M and Omega are skew n x n matrices, A is a constant symmetric n x n matrix.
#pragma once

#include "impl/so3.hpp"

#include <Eigen/LU>
#include <stdexcept>
#include <utility>

namespace gm::ref {

// (2.34): M = A Omega + Omega A.
template <class T>
MatX<T> manakov_M(const MatX<T>& A, const MatX<T>& Omega) {
  return A * Omega + Omega * A;
}

// Omega recovered from M by solving A Omega + Omega A = M. For diagonal A = diag(a) the
// solution is Omega_ij = M_ij / (a_i + a_j); otherwise the n^2 x n^2 linear system
// (I (x) A + A (x) I) vec(Omega) = vec(M) is solved. Requires a_i + a_j != 0 (for a positive
// definite A this always holds).
template <class T>
MatX<T> manakov_Omega(const MatX<T>& A, const MatX<T>& M) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n || M.rows() != n || M.cols() != n)
    throw std::invalid_argument("manakov_Omega: A and M must be square of the same size");
  bool diagonal = true;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      if (i != j && A(i, j) != T(0)) diagonal = false;
  if (diagonal) {
    MatX<T> W(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const T s = A(i, i) + A(j, j);
        if (s == T(0)) throw std::domain_error("manakov_Omega: a_i + a_j = 0, Omega is not determined by M");
        W(i, j) = M(i, j) / s;
      }
    return W;
  }
  // The factorisation depends on A only, and a flow calls this with one A many times: it is kept
  // (per thread) for the last A seen, so a call costs one solve with the kept factors, O(n^4)
  // operations, instead of a full-pivot LU of the n^2 x n^2 system, O(n^6).
  struct Factorised {
    MatX<T> A;
    Eigen::FullPivLU<MatX<T>> lu;
  };
  thread_local Factorised last;
  if (last.A.rows() != n || last.A != A) {
    const Eigen::Index N = n * n;
    MatX<T> K = MatX<T>::Zero(N, N);
    // vec stacks columns: vec(X)(i + n j) = X(i, j).
    // (A X)(i, j) = sum_k A(i, k) X(k, j);  (X A)(i, j) = sum_k X(i, k) A(k, j).
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index k = 0; k < n; ++k) {
          K(i + n * j, k + n * j) += A(i, k);
          K(i + n * j, i + n * k) += A(k, j);
        }
    last.lu.compute(K);
    last.A = A;
  }
  const Eigen::FullPivLU<MatX<T>>& lu = last.lu;
  if (!lu.isInvertible()) throw std::domain_error("manakov_Omega: A Omega + Omega A = M is singular");
  VecX<T> m(n * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) m(i + n * j) = M(i, j);
  const VecX<T> w = lu.solve(m);
  MatX<T> W(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) W(i, j) = w(i + n * j);
  return W;
}

// (2.34)/(2.36): dM/dt = [M, Omega].
template <class T>
MatX<T> manakov_2_34(const MatX<T>& A, const MatX<T>& M) {
  const MatX<T> W = manakov_Omega<T>(A, M);
  return commutator(M, W);
}

// Lagrangian of the proof of Proposition 2.4: l(Omega) = -(1/2) tr(Omega A Omega).
template <class T>
T manakov_lagrangian(const MatX<T>& A, const MatX<T>& Omega) {
  return -(Omega * A * Omega).trace() / T(2);
}

// Manakov with attitude: dM/dt = [M, Omega], dO/dt = O Omega (section 2.4, Omega = O^-1 dO/dt).
template <class T>
std::pair<MatX<T>, MatX<T>> manakov_with_attitude(const MatX<T>& A, const MatX<T>& M, const MatX<T>& O) {
  const MatX<T> W = manakov_Omega<T>(A, M);
  return {commutator(M, W), O * W};
}

// Closing exercise: the momentum M = dl/dOmega that Hamilton's principle for
//     S = int l(Omega) + tr(P^T (dQ/dt - Q Omega)) dt
// identifies, in the pairing (2.15) in which Manakov's M = A Omega + Omega A is dl/dOmega for
// l = -tr(Omega A Omega)/2 (Proposition 2.4). Varying Omega,
//     <dl/dOmega, dOmega> = tr(P^T Q dOmega) = <Q^T P - P^T Q, dOmega>   for skew dOmega,
// so M = Q^T P - P^T Q: the formula printed in the notes, M = (1/2)(P^T Q - Q^T P), has the
// opposite sign and half the size (it is the identification for the pairing tr(A B)). See the
// erratum of mm.manakov-clebsch in spec/catalogue.json; the motion equation dM/dt = [M, Omega] is
// linear in M and holds for both.
template <class T>
MatX<T> manakov_clebsch_M(const MatX<T>& Q, const MatX<T>& P) {
  return Q.transpose() * P - P.transpose() * Q;
}

// Closing exercise, (3.23): dQ/dt = Q Omega, dP/dt = P Omega, Omega from M(Q, P) through
// M = A Omega + Omega A. Returns (dQ/dt, dP/dt).
template <class T>
std::pair<MatX<T>, MatX<T>> manakov_clebsch_3_23(const MatX<T>& A, const MatX<T>& Q, const MatX<T>& P) {
  const MatX<T> W = manakov_Omega<T>(A, manakov_clebsch_M<T>(Q, P));
  return {Q * W, P * W};
}

}  // namespace gm::ref
