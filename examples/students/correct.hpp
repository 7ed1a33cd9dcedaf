// A correct student implementation of the rigid body of the notes, written as a student would:
// one struct of static function templates named after the slots (`geomech slots`), plus two
// integrators that declare what they claim. Check it with
//
//   ./geomech check examples/students/correct.cpp
//
// The buggy examples next to it derive from this struct and replace one function, the way a real
// mistake sits in otherwise working code.
#pragma once

#include <geomech/student.hpp>

#include <cmath>

namespace course {

using namespace gm;

struct RigidBody {
  static constexpr const char* description = "a correct implementation (examples/students/correct.hpp)";

  // ---- so(3) -----------------------------------------------------------------------------
  // (2.11): hat(v) w = v x w.
  template <class T>
  static Mat3<T> hat(const Vec3<T>& v) {
    Mat3<T> m;
    m << T(0), -v.z(), v.y(),  //
        v.z(), T(0), -v.x(),   //
        -v.y(), v.x(), T(0);
    return m;
  }

  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }

  // (2.15): <A, B> = (1/2) tr(A^T B).
  template <class T>
  static T pairing(const MatX<T>& a, const MatX<T>& b) {
    return a.cwiseProduct(b).sum() / T(2);
  }

  // ---- Euler's equations -------------------------------------------------------------------
  // (2.1): I1 dOmega1/dt = (I2 - I3) Omega2 Omega3 and cyclically.
  template <class T>
  static Vec3<T> euler_2_1(const Vec3<T>& I, const Vec3<T>& W) {
    Vec3<T> d;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      d(i) = (I(j) - I(k)) * W(j) * W(k) / I(i);
    }
    return d;
  }

  // (2.2): I dOmega/dt = I Omega x Omega.
  template <class T>
  static Vec3<T> euler_2_2(const Vec3<T>& I, const Vec3<T>& W) {
    const Vec3<T> IW = I.cwiseProduct(W);
    return IW.cross(W).cwiseQuotient(I);
  }

  // (3.7): dPi1/dt = (1/I3 - 1/I2) Pi2 Pi3 and cyclically.
  template <class T>
  static Vec3<T> euler_3_7(const Vec3<T>& I, const Vec3<T>& P) {
    Vec3<T> d;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      d(i) = (T(1) / I(k) - T(1) / I(j)) * P(j) * P(k);
    }
    return d;
  }

  // (3.8): dPi/dt = Pi x I^-1 Pi.
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& P) {
    return P.cross(P.cwiseQuotient(I));
  }

  // (2.12): dPi/dt = -[Omega_hat, Pi] with Omega = I^-1 vee(Pi).
  template <class T>
  static Mat3<T> euler_matrix_2_12(const Vec3<T>& I, const Mat3<T>& Pi_hat) {
    const Mat3<T> W = hat<T>(vee<T>(Pi_hat).cwiseQuotient(I));
    return Pi_hat * W - W * Pi_hat;
  }

  // ---- Lagrangian and Hamiltonian ------------------------------------------------------------
  template <class T>
  static T lagrangian_2_5(const Vec3<T>& I, const Vec3<T>& W) {
    return W.dot(I.cwiseProduct(W)) / T(2);
  }

  // (2.13): l = (1/2) <I Omega_hat, Omega_hat>, with (I Omega)^ for the body's inertia.
  template <class T>
  static T lagrangian_2_13(const Vec3<T>& I, const Mat3<T>& W_hat) {
    const MatX<T> IW = hat<T>(I.cwiseProduct(vee<T>(W_hat)));
    return pairing<T>(IW, MatX<T>(W_hat)) / T(2);
  }

  template <class T>
  static Vec3<T> legendre_3_1(const Vec3<T>& I, const Vec3<T>& W) {
    return I.cwiseProduct(W);
  }

  template <class T>
  static Vec3<T> omega_3_5(const Vec3<T>& I, const Vec3<T>& P) {
    return P.cwiseQuotient(I);
  }

  // (3.3): h = Pi . Omega - l(Omega).
  template <class T>
  static T hamiltonian_3_3(const Vec3<T>& I, const Vec3<T>& P) {
    const Vec3<T> W = omega_3_5<T>(I, P);
    return P.dot(W) - lagrangian_2_5<T>(I, W);
  }

  // (2.27): the Casimir c(Pi) = |Pi|^2 / 2 of the bracket (3.6).
  template <class T>
  static T casimir(const Vec3<T>& P) {
    return P.dot(P) / T(2);
  }

  // (3.4): h = (1/2) Pi . I^-1 Pi.
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& P) {
    return P.dot(P.cwiseQuotient(I)) / T(2);
  }

  // (2.21): h = <Pi, Omega_hat> - l(Omega_hat).
  template <class T>
  static T hamiltonian_2_21(const Vec3<T>& I, const Mat3<T>& Pi_hat) {
    const Mat3<T> W_hat = hat<T>(vee<T>(Pi_hat).cwiseQuotient(I));
    return pairing<T>(MatX<T>(Pi_hat), MatX<T>(W_hat)) - lagrangian_2_13<T>(I, W_hat);
  }

  // ---- brackets ----------------------------------------------------------------------------
  template <class T>
  static T lie_poisson_2_23(const Mat3<T>& Pi_hat, const Mat3<T>& df, const Mat3<T>& dh) {
    return -pairing<T>(MatX<T>(Pi_hat), MatX<T>(df * dh - dh * df));
  }

  template <class T>
  static T lie_poisson_3_6(const Vec3<T>& P, const Vec3<T>& df, const Vec3<T>& dh) {
    return -P.dot(df.cross(dh));
  }

  template <class T>
  static T nambu_3_13(const Vec3<T>& dc, const Vec3<T>& df, const Vec3<T>& dh) {
    return -dc.dot(df.cross(dh));
  }

  template <class T>
  static Vec3<T> nambu_motion_3_14(const Vec3<T>& dc, const Vec3<T>& dh) {
    return dc.cross(dh);
  }

  // ---- momentum map, Clebsch, reconstruction ---------------------------------------------------
  template <class T>
  static Vec3<T> momentum_map(const Vec3<T>& q, const Vec3<T>& p) {
    return p.cross(q);
  }

  // (3.21): Pi = P x Q, dQ/dt = -Omega x Q, dP/dt = -Omega x P.
  template <class T>
  static std::pair<Vec3<T>, Vec3<T>> clebsch_3_21(const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) {
    const Vec3<T> W = P.cross(Q).cwiseQuotient(I);
    return {Q.cross(W), P.cross(W)};
  }

  // (2.10): dO/dt = O Omega_hat.
  template <class T>
  static Mat3<T> reconstruction_2_10(const Mat3<T>& O, const Vec3<T>& W) {
    return O * hat<T>(W);
  }

  // Theorem 2.2: the spatial angular momentum pi = O Pi.
  template <class T>
  static Vec3<T> spatial_momentum(const Mat3<T>& O, const Vec3<T>& P) {
    return O * P;
  }

  template <class T>
  static Mat3<T> inertia_space(const Mat3<T>& O, const Vec3<T>& I) {
    return O * I.asDiagonal() * O.transpose();
  }

  // ---- Manakov's SO(n) rigid body --------------------------------------------------------------
  template <class T>
  static MatX<T> manakov_M(const MatX<T>& A, const MatX<T>& W) {
    return A * W + W * A;
  }

  // Solves A Omega + Omega A = M in the eigenbasis of the symmetric A:
  // with A = V diag(a) V^T, (V^T Omega V)_ij = (V^T M V)_ij / (a_i + a_j).
  // For a diagonal A (the usual case) V is the identity and no eigen-decomposition is needed,
  // which keeps exact rationals exact.
  template <class T>
  static MatX<T> manakov_Omega(const MatX<T>& A, const MatX<T>& M) {
    const Eigen::Index n = A.rows();
    if (A.isDiagonal(T(0))) {
      MatX<T> W(n, n);
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) W(i, j) = M(i, j) / (A(i, i) + A(j, j));
      return W;
    }
    // Not diagonal: solve the n^2 linear equations for the entries of Omega.
    const Eigen::Index N = n * n;
    MatX<T> K = MatX<T>::Zero(N, N);
    VecX<T> m(N);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const Eigen::Index row = i * n + j;  // equation for entry (i, j)
        m(row) = M(i, j);
        for (Eigen::Index k = 0; k < n; ++k) {
          K(row, k * n + j) += A(i, k);  // (A Omega)_ij
          K(row, i * n + k) += A(k, j);  // (Omega A)_ij
        }
      }
    const VecX<T> w = K.partialPivLu().solve(m);
    MatX<T> W(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) W(i, j) = w(i * n + j);
    return W;
  }

  template <class T>
  static MatX<T> manakov_2_34(const MatX<T>& A, const MatX<T>& M) {
    const MatX<T> W = manakov_Omega<T>(A, M);
    return M * W - W * M;
  }

  template <class T>
  static T manakov_lagrangian(const MatX<T>& A, const MatX<T>& W) {
    return -(W * A * W).trace() / T(2);
  }
};

// Implicit midpoint for Pi (a fixed-point iteration), with the attitude advanced by the Cayley
// transform of the midpoint angular velocity: O_{n+1} = O_n cay(h hat(Omega_mid)), which keeps O
// orthogonal. The step is the midpoint rule on (Pi, O) (O's equation is linear, and its midpoint
// solution is the Cayley factor), so every quadratic invariant is kept: |Pi|^2, the energy, O^T O
// and the spatial momentum O Pi (Noether); the energy kept exactly is a fortiori bounded. O is
// multiplied on the right only and the Pi-part ignores O: rotating O0 rotates O1 (equivariant).
struct Midpoint {
  static constexpr const char* name = "midpoint";
  static constexpr gm::student::Claims claims{.order = 2,
                                              .symmetric = true,
                                              .casimir = true,
                                              .energy = true,
                                              .orthogonality = true,
                                              .noether = true,
                                              .equivariant = true,
                                              .bounded_energy = true};

  template <class T>
  static Mat3<T> cayley(const Mat3<T>& A) {
    const Mat3<T> Id = Mat3<T>::Identity();
    return (Id - A / T(2)).inverse() * (Id + A / T(2));
  }

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    using std::abs;
    Vec3<T> next = x.Pi;
    for (int it = 0; it < 200; ++it) {
      const Vec3<T> mid = (x.Pi + next) / T(2);
      const Vec3<T> again = x.Pi + h * RigidBody::euler_3_8<T>(I, mid);
      const T change = (again - next).cwiseAbs().maxCoeff();
      next = again;
      // Relative to |Pi|: the same step in any units (an absolute part such as eps (1 + |Pi|) stops a
      // slowly turning body's iteration at once, and the step falls to first order).
      if (change <= T(8) * std::numeric_limits<T>::epsilon() * x.Pi.cwiseAbs().maxCoeff()) break;
    }
    const Vec3<T> W_mid = ((x.Pi + next) / T(2)).cwiseQuotient(I);
    return {next, x.O * cayley<T>(h * RigidBody::hat<T>(W_mid))};
  }
};

// Strang splitting of h = sum Pi_i^2 / (2 I_i) into three rotations, each solved exactly:
// the flow of Pi_i^2 / (2 I_i) turns Pi about e_i by the angle -t Pi_i / I_i, and O by +t Pi_i / I_i.
// A composition of exact Hamiltonian flows: a Poisson map that keeps |Pi| and O^T O exactly
// (up to round-off), and O Pi (each rotation turns Pi one way and O the other: Noether); the
// energy is not conserved, but its error stays bounded (a Poisson map close to the flow of a
// modified energy, by backward error analysis). Right multiplication of O only: equivariant.
struct Splitting {
  static constexpr const char* name = "lie_poisson_splitting";
  static constexpr gm::student::Claims claims{.order = 2,
                                              .symmetric = true,
                                              .casimir = true,
                                              .orthogonality = true,
                                              .poisson = true,
                                              .noether = true,
                                              .equivariant = true,
                                              .bounded_energy = true};

  template <class T>
  static Mat3<T> rotation(int axis, const T& angle) {
    using std::cos;
    using std::sin;
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    Mat3<T> R = Mat3<T>::Identity();
    const T c = cos(angle), s = sin(angle);
    R(j, j) = c;
    R(j, k) = -s;
    R(k, j) = s;
    R(k, k) = c;
    return R;
  }

  template <class T>
  static void flow(int axis, const Vec3<T>& I, RigidBodyState<T>& x, const T& t) {
    const T angle = t * x.Pi(axis) / I(axis);
    x.Pi = rotation<T>(axis, -angle) * x.Pi;
    x.O = x.O * rotation<T>(axis, angle);
  }

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x0, const T& h) {
    RigidBodyState<T> x = x0;
    flow<T>(0, I, x, h / T(2));
    flow<T>(1, I, x, h / T(2));
    flow<T>(2, I, x, h);
    flow<T>(1, I, x, h / T(2));
    flow<T>(0, I, x, h / T(2));
    return x;
  }
};

// The implicit midpoint rule in the canonical Clebsch variables: (3.21) on (Q, P) in R^3 x R^3,
// and (3.23) on (Q, P) in R^{n x n} x R^{n x n} with M = Q^T P - P^T Q. Both systems are canonical
// Hamiltonian systems, and the midpoint rule is symplectic for every one of them; it is symmetric
// and of order 2. It does not keep the energy here: H is of degree 4 in (Q, P).
struct ClebschMidpoint {
  static constexpr const char* name = "clebsch_midpoint";
  static constexpr gm::student::Claims claims{.order = 2, .symmetric = true, .symplectic = true};

  // z_mid = z + (h/2) f(z_mid) by fixed-point iteration to round-off; z_{n+1} = 2 z_mid - z.
  template <class T, class Z, class F>
  static Z midpoint(const Z& z, const T& h, const F& f) {
    Z mid = z;
    for (int it = 0; it < 200; ++it) {
      const auto [dq, dp] = f(mid.first, mid.second);
      const Z again{z.first + h / T(2) * dq, z.second + h / T(2) * dp};
      const T change = std::max((again.first - mid.first).cwiseAbs().maxCoeff(), (again.second - mid.second).cwiseAbs().maxCoeff());
      const T size = std::max(T(1), std::max(z.first.cwiseAbs().maxCoeff(), z.second.cwiseAbs().maxCoeff()));
      mid = again;
      if (change <= T(4) * std::numeric_limits<T>::epsilon() * size) break;
    }
    return {T(2) * mid.first - z.first, T(2) * mid.second - z.second};
  }

  template <class T>
  static Vec3Pair<T> clebsch_step(const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
    return midpoint<T>(z, h, [&](const Vec3<T>& Q, const Vec3<T>& P) {
      const Vec3<T> W = P.cross(Q).cwiseQuotient(I);
      return Vec3Pair<T>{-W.cross(Q), -W.cross(P)};
    });
  }

  template <class T>
  static MatXPair<T> manakov_clebsch_step(const MatX<T>& A, const MatXPair<T>& z, const T& h) {
    return midpoint<T>(z, h, [&](const MatX<T>& Q, const MatX<T>& P) {
      const MatX<T> W = RigidBody::manakov_Omega<T>(A, (Q.transpose() * P - P.transpose() * Q).eval());
      return MatXPair<T>{Q * W, P * W};
    });
  }
};

}  // namespace course
