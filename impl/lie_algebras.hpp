// Matrix Lie algebras in coordinates: hat/vee, structure constants, ad and ad* (section 1).
//
// Structure constants: [e_j, e_k] = c^l_jk e_l.
// ad*   (exercise "Components of ad*_xi mu", section 1): (ad*_xi mu)_k = xi^j mu_i c^i_jk,
// the coordinate form of the definition <ad*_xi mu, eta> = <mu, [xi, eta]> (Theorem 1.1 (iv)),
// with <mu, xi> = mu_i xi^i the pairing of a basis with its dual basis.
#pragma once

#include "core/lie_algebra_id.hpp"
#include "impl/son.hpp"

#include <array>
#include <vector>

namespace gm::ref {

inline int lie_dim(LieAlgebraId a) {
  switch (a) {
    case LieAlgebraId::so3:
      return 3;
    case LieAlgebraId::so4:
      return 6;
    case LieAlgebraId::sl2:
      return 3;
  }
  return 0;
}

inline int lie_matrix_size(LieAlgebraId a) {
  switch (a) {
    case LieAlgebraId::so3:
      return 3;
    case LieAlgebraId::so4:
      return 4;
    case LieAlgebraId::sl2:
      return 2;
  }
  return 0;
}

// sl(2, R): traceless real 2 x 2 matrices, coordinates (a, b, c) -> [[a, b], [c, -a]].
template <class T>
MatX<T> hat_sl2(const VecX<T>& x) {
  MatX<T> m(2, 2);
  m << x(0), x(1), x(2), -x(0);
  return m;
}

template <class T>
VecX<T> vee_sl2(const MatX<T>& m) {
  VecX<T> x(3);
  x << m(0, 0), m(0, 1), m(1, 0);
  return x;
}

template <class T>
MatX<T> lie_hat(LieAlgebraId a, const VecX<T>& x) {
  switch (a) {
    case LieAlgebraId::so3:
      return hat_n<T>(x, 3);
    case LieAlgebraId::so4:
      return hat_n<T>(x, 4);
    case LieAlgebraId::sl2:
      return hat_sl2<T>(x);
  }
  throw std::invalid_argument("lie_hat: unknown algebra");
}

template <class T>
VecX<T> lie_vee(LieAlgebraId a, const MatX<T>& m) {
  switch (a) {
    case LieAlgebraId::so3:
    case LieAlgebraId::so4:
      return vee_n<T>(m);
    case LieAlgebraId::sl2:
      return vee_sl2<T>(m);
  }
  throw std::invalid_argument("lie_vee: unknown algebra");
}

// ad_xi eta = [xi, eta] in coordinates, through the matrix commutator.
template <class T>
VecX<T> lie_bracket(LieAlgebraId a, const VecX<T>& xi, const VecX<T>& eta) {
  MatX<T> x = lie_hat<T>(a, xi), y = lie_hat<T>(a, eta);
  return lie_vee<T>(a, commutator(x, y));
}

// c[l][j][k] = c^l_jk, computed from the matrix commutator of basis elements.
template <class T>
std::vector<std::vector<std::vector<T>>> structure_constants(LieAlgebraId a) {
  const int d = lie_dim(a);
  std::vector<std::vector<std::vector<T>>> c(d, std::vector<std::vector<T>>(d, std::vector<T>(d, T(0))));
  for (int j = 0; j < d; ++j)
    for (int k = 0; k < d; ++k) {
      VecX<T> ej = VecX<T>::Zero(d), ek = VecX<T>::Zero(d);
      ej(j) = T(1);
      ek(k) = T(1);
      VecX<T> b = lie_bracket<T>(a, ej, ek);
      for (int l = 0; l < d; ++l) c[l][j][k] = b(l);
    }
  return c;
}

// (ad*_xi mu)_k = xi^j mu_i c^i_jk (exercise in section 1).
template <class T>
VecX<T> ad_star(LieAlgebraId a, const VecX<T>& xi, const VecX<T>& mu) {
  const int d = lie_dim(a);
  // The structure constants of each algebra, computed once (flows call ad* thousands of times).
  static const std::array<std::vector<std::vector<std::vector<T>>>, 3> constants = {
      structure_constants<T>(LieAlgebraId::so3), structure_constants<T>(LieAlgebraId::so4),
      structure_constants<T>(LieAlgebraId::sl2)};
  const auto& c = constants[a == LieAlgebraId::so3 ? 0 : a == LieAlgebraId::so4 ? 1 : 2];
  VecX<T> out = VecX<T>::Zero(d);
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < d; ++j)
      for (int i = 0; i < d; ++i) out(k) += xi(j) * mu(i) * c[i][j][k];
  return out;
}

// so(3): ad*_xi mu = mu x xi (so that Euler's equation dPi/dt = Pi x Omega is
// d/dt (dl/dOmega) = ad*_Omega (dl/dOmega), Theorem 1.1 (iv)).
template <class T>
Vec3<T> ad_star_so3(const Vec3<T>& xi, const Vec3<T>& mu) {
  return cross<T>(mu, xi);
}

// so(4) = R^6 (SO(4) exercise). With x = (u, v) and hat_4 of son.hpp,
//   [x1, x2] = (u1 x u2 + v1 x v2,  u1 x v2 - u2 x v1),
// which follows from hat(a x b) = b a^T - a b^T; and, for the dot-product pairing (= (2.15)),
//   ad*_xi mu = (mu_u x xi_u + mu_v x xi_v,  mu_u x xi_v + mu_v x xi_u).
template <class T>
Vec6<T> so4_bracket_R6(const Vec6<T>& a, const Vec6<T>& b) {
  const Vec3<T> u1 = a.template head<3>(), v1 = a.template tail<3>();
  const Vec3<T> u2 = b.template head<3>(), v2 = b.template tail<3>();
  Vec6<T> out;
  out.template head<3>() = cross<T>(u1, u2) + cross<T>(v1, v2);
  out.template tail<3>() = cross<T>(u1, v2) - cross<T>(u2, v1);
  return out;
}

template <class T>
Vec6<T> ad_star_so4_R6(const Vec6<T>& xi, const Vec6<T>& mu) {
  const Vec3<T> xu = xi.template head<3>(), xv = xi.template tail<3>();
  const Vec3<T> mu_u = mu.template head<3>(), mu_v = mu.template tail<3>();
  Vec6<T> out;
  out.template head<3>() = cross<T>(mu_u, xu) + cross<T>(mu_v, xv);
  out.template tail<3>() = cross<T>(mu_u, xv) + cross<T>(mu_v, xu);
  return out;
}

}  // namespace gm::ref
