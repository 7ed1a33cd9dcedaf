// Coordinates on a Lie algebra are a choice the notes leave open. The SO(4) exercise
// asks for "the analogue of the hat map" and its R^6 representation, and section 1's generic
// statements hold in any basis of so(3), so(4) or sl(2, R): the order and signs of so(n)
// coordinates, and the basis of sl(2, R), are the student's. So the definition checks of the slots
// that take coordinates (definitions_algebra.cpp) learn the student's choice from the student's own
// hat (hat_n for so(n), lie_hat for the generic algebras) and compare every coordinate slot with the
// notes' formula transported to that basis: a wrong formula still fails alone, a different basis
// does not. A slot given without its hat is checked in the documented coordinates (`geomech slots`),
// and when a failure would go away in the coordinates another slot of the same file uses, the
// failure says so (basis_hint).
//
// A basis is the list of matrices E_k = hat(e_k). Accepted bases:
//   so(n), n = 2..6 (hat_n, and lie_hat on so(3), so(4)): each E_k is plus or minus one
//     elementary skew matrix e_i e_j^T - e_j e_i^T, each pair i < j used once: "coordinates",
//     their order and signs free. (A scaled or mixed basis would change the structure constants
//     the exercises' formulas are written in; the notes' coordinates are entries of the matrix.)
//   sl(2, R) (lie_hat): any three traceless 2 x 2 matrices that form a basis (the E, F, H of a
//     textbook in any order, the Pauli-like (sigma_z, sigma_x, i sigma_y), ...).
// Coordinates are read back through the d free entries of a matrix of the algebra (the entries
// above the diagonal for so(n); m_00, m_01, m_10 for sl(2)): c = S^-1 f(m), S the d x d matrix of
// the free entries of the E_k. For a signed permutation S^-1 is exact in every scalar; for another
// sl(2) basis its rounding is part of the tolerance (`condition`).
#pragma once

#include "core/lie_algebra_id.hpp"
#include "core/subject.hpp"
#include "properties/support/show.hpp"
#include "properties/support/truth.hpp"

#include <Eigen/LU>

#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gm::coords {

// The free entries of a matrix of so(n) (above the diagonal, row by row) or of sl(2).
inline std::vector<std::pair<int, int>> free_entries(int n, bool skew) {
  std::vector<std::pair<int, int>> out;
  if (!skew) return {{0, 0}, {0, 1}, {1, 0}};
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) out.emplace_back(i, j);
  return out;
}

template <class T>
struct Basis {
  int n = 0;         // matrix size
  bool skew = true;  // so(n) (true) or sl(2, R)
  std::vector<MatX<T>> E;
  MatX<T> S_inverse;   // free entries -> coordinates
  T condition = T(1);  // |S|_inf |S^-1|_inf: 1 for a signed permutation
  bool documented = true;
  std::string origin;  // "the documented coordinates", "your hat_n", ...

  int dimension() const { return static_cast<int>(E.size()); }

  // For check titles: "the documented coordinates" or "your coordinates (from hat_n(e_k, 4))".
  std::string name() const {
    return documented ? std::string("the documented coordinates") : "your coordinates (from " + origin + ")";
  }

  MatX<T> matrix(const VecX<T>& v) const {
    MatX<T> m = MatX<T>::Zero(n, n);
    for (int k = 0; k < dimension(); ++k) m += v(k) * E[k];
    return m;
  }

  VecX<T> coordinates(const MatX<T>& m) const {
    const auto entries = free_entries(n, skew);
    VecX<T> f(dimension());
    for (int k = 0; k < dimension(); ++k) f(k) = m(entries[k].first, entries[k].second);
    return S_inverse * f;
  }

  // "v1 = m(3,2), v2 = m(1,3), ..." (1-based entries where each coordinate appears with sign +) for
  // so(n); the matrices themselves for sl(2).
  std::string describe() const {
    std::string out;
    for (int k = 0; k < dimension(); ++k) {
      if (k) out += ", ";
      if (skew) {
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            if (E[k](i, j) == T(1))
              out += "v" + std::to_string(k + 1) + " = m(" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")";
      } else {
        out += "e" + std::to_string(k + 1) + " = " + show_value(E[k]);
      }
    }
    return out;
  }
};

// A basis from its matrices, or the reason it is not an accepted one (see the top of this file).
template <class T>
std::optional<Basis<T>> make_basis(int n, bool skew, std::vector<MatX<T>> E, const std::string& origin,
                                   std::string* why) {
  auto refuse = [&](const std::string& reason) -> std::optional<Basis<T>> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const auto entries = free_entries(n, skew);
  const int d = static_cast<int>(entries.size());
  if (static_cast<int>(E.size()) != d) return refuse("expected " + std::to_string(d) + " basis matrices");
  MatX<T> S(d, d);
  std::vector<bool> used(d, false);
  for (int k = 0; k < d; ++k) {
    const MatX<T>& e = E[k];
    const std::string which = origin + " of the unit vector e" + std::to_string(k + 1);
    if (e.rows() != n || e.cols() != n)
      return refuse(which + " is " + std::to_string(e.rows()) + " x " + std::to_string(e.cols()) + ", not " +
                    std::to_string(n) + " x " + std::to_string(n));
    for (int c = 0; c < d; ++c) S(c, k) = e(entries[c].first, entries[c].second);
    if (skew) {
      // plus or minus one elementary skew matrix: one entry +-1 above the diagonal, its negative below
      int found = -1, count = 0;
      for (int c = 0; c < d; ++c)
        if (S(c, k) != T(0)) found = c, ++count;
      const bool unit = count == 1 && (S(found, k) == T(1) || S(found, k) == T(-1));
      bool skew_ok = unit;
      for (int i = 0; i < n && skew_ok; ++i)
        for (int j = 0; j < n && skew_ok; ++j) skew_ok = e(i, j) == -e(j, i);
      if (!skew_ok)
        return refuse(
            which + " is " + show_value(e) + ": not plus or minus one elementary skew matrix e_i e_j^T - e_j e_i^T " +
            "(the order and signs of the coordinates of so(" + std::to_string(n) + ") are yours to choose, but " +
            "each coordinate is one entry of the matrix above the diagonal, with its negative below)");
      if (used[found])
        return refuse(origin + " gives two coordinates the same entry (" + std::to_string(entries[found].first + 1) +
                      "," + std::to_string(entries[found].second + 1) + "): not a basis of so(" + std::to_string(n) +
                      ")");
      used[found] = true;
    } else if (e(0, 0) + e(1, 1) != T(0)) {
      return refuse(which + " is " + show_value(e) + ": not traceless, so not in sl(2, R)");
    }
  }
  Basis<T> b;
  b.n = n;
  b.skew = skew;
  b.E = std::move(E);
  b.origin = origin;
  if (!skew) {
    const T det = S(0, 0) * (S(1, 1) * S(2, 2) - S(1, 2) * S(2, 1)) -
                  S(0, 1) * (S(1, 0) * S(2, 2) - S(1, 2) * S(2, 0)) + S(0, 2) * (S(1, 0) * S(2, 1) - S(1, 1) * S(2, 0));
    if (det == T(0))
      return refuse(origin + ": the matrices of e1, e2, e3 are linearly dependent, not a basis of sl(2, R)");
  }
  b.S_inverse = Eigen::FullPivLU<MatX<T>>(S).inverse();
  b.condition = max_abs(S) * max_abs(b.S_inverse) * T(d);
  return b;
}

// The documented coordinates (`geomech slots`): truth::so_n_matrix, truth::algebra_matrix.
template <class T>
Basis<T> documented_so_n(int n) {
  std::vector<MatX<T>> E;
  const int d = truth::so_dimension(n);
  for (int k = 0; k < d; ++k) {
    VecX<T> e = VecX<T>::Zero(d);
    e(k) = T(1);
    E.push_back(truth::so_n_matrix<T>(e, n));
  }
  return *make_basis<T>(n, true, std::move(E), "the documented coordinates", nullptr);
}

template <class T>
Basis<T> documented_algebra(LieAlgebraId g) {
  if (g == LieAlgebraId::so3) return documented_so_n<T>(3);
  if (g == LieAlgebraId::so4) return documented_so_n<T>(4);
  std::vector<MatX<T>> E;
  for (int k = 0; k < 3; ++k) {
    VecX<T> e = VecX<T>::Zero(3);
    e(k) = T(1);
    E.push_back(truth::algebra_matrix<T>(g, e));
  }
  return *make_basis<T>(2, false, std::move(E), "the documented basis", nullptr);
}

inline int matrix_size(LieAlgebraId g) { return g == LieAlgebraId::so4 ? 4 : g == LieAlgebraId::so3 ? 3 : 2; }

// The basis a hat function defines: hat(e_k) for every unit vector. An exception from the
// student's function, or a basis that is not an accepted one, gives nothing (and `why`).
template <class T, class Hat>
std::optional<Basis<T>> basis_of_hat(int n, bool skew, int d, Hat&& hat, const std::string& origin, std::string* why) {
  std::vector<MatX<T>> E;
  try {
    for (int k = 0; k < d; ++k) {
      VecX<T> e = VecX<T>::Zero(d);
      e(k) = T(1);
      E.push_back(hat(e));
    }
  } catch (const std::exception& x) {
    if (why) *why = origin + " throws: " + x.what();
    return std::nullopt;
  }
  auto b = make_basis<T>(n, skew, std::move(E), origin, why);
  if (b) {
    const Basis<T> doc = skew ? documented_so_n<T>(n) : documented_algebra<T>(LieAlgebraId::sl2);
    b->documented = true;
    for (int k = 0; k < d; ++k) b->documented = b->documented && b->E[k] == doc.E[k];
  }
  return b;
}

// The student's so(n) coordinates, learned from hat_n; nullopt when hat_n is not provided or does
// not define accepted coordinates (its own definition check says why).
template <class T>
std::optional<Basis<T>> learned_so_n(const Subject<T>& s, int n, std::string* why = nullptr) {
  if (!s.hat_n) return std::nullopt;
  return basis_of_hat<T>(
      n, true, truth::so_dimension(n), [&](const VecX<T>& e) { return MatX<T>(s.hat_n(e, n)); },
      "hat_n(e_k, " + std::to_string(n) + ")", why);
}

template <class T>
std::optional<Basis<T>> learned_algebra(const Subject<T>& s, LieAlgebraId g, std::string* why = nullptr) {
  if (!s.lie_hat) return std::nullopt;
  return basis_of_hat<T>(
      matrix_size(g), g != LieAlgebraId::sl2, truth::algebra_dimension(g),
      [&](const VecX<T>& e) { return MatX<T>(s.lie_hat(g, e)); },
      std::string("lie_hat(") + lie_algebra_name(g) + ", e_k)", why);
}

// The coordinates a coordinate slot is checked in: the student's own (from hat_n / lie_hat) when
// they are given and accepted, else the documented ones.
template <class T>
Basis<T> so_n_for(const Subject<T>& s, int n) {
  auto b = learned_so_n(s, n);
  return b ? *b : documented_so_n<T>(n);
}

template <class T>
Basis<T> algebra_for(const Subject<T>& s, LieAlgebraId g) {
  auto b = learned_algebra(s, g);
  return b ? *b : documented_algebra<T>(g);
}

// ad*_xi mu of so(3) in the coordinates of the hat map (2.11), for the properties that compare it
// with cross products (momentum maps, (1.1)): the student's ad_star reads its arguments in the
// student's basis of so(3) (lie_hat's; the documented one, which is (2.11), without lie_hat). With
// v = P v' (P the signed permutation taking the student's coordinates to (2.11)'s, orthogonal), a
// covector transforms like a vector (mu' = P^T mu keeps mu . xi), so ad*(xi, mu) = P ad*'(P^T xi, P^T mu).
template <class T>
Vec3<T> ad_star_so3_in_hat_coordinates(const Subject<T>& s, const Vec3<T>& xi, const Vec3<T>& mu) {
  const Basis<T> b = algebra_for(s, LieAlgebraId::so3);
  if (b.documented) return Vec3<T>(s.ad_star(LieAlgebraId::so3, VecX<T>(xi), VecX<T>(mu)));
  Mat3<T> P;
  for (int k = 0; k < 3; ++k) P.col(k) = Vec3<T>(truth::so_n_coordinates<T>(b.E[k]));
  return Vec3<T>(P * Vec3<T>(s.ad_star(LieAlgebraId::so3, VecX<T>(P.transpose() * xi), VecX<T>(P.transpose() * mu))));
}

// The basis a coordinate reader (vee_n, lie_vee) reads: the matrices whose coordinates are the unit
// vectors, found by reading every elementary matrix of the algebra; nullopt unless the reader is
// a signed permutation of the free entries (so(n)). Used only to explain a failure.
template <class T, class Vee>
std::optional<Basis<T>> basis_of_vee(int n, Vee&& vee, const std::string& origin) {
  const auto entries = free_entries(n, true);
  const int d = static_cast<int>(entries.size());
  std::vector<MatX<T>> E(d);
  std::vector<bool> seen(d, false);
  try {
    for (int c = 0; c < d; ++c) {
      MatX<T> F = MatX<T>::Zero(n, n);
      F(entries[c].first, entries[c].second) = T(1);
      F(entries[c].second, entries[c].first) = T(-1);
      const VecX<T> v = vee(F);
      if (v.size() != d) return std::nullopt;
      int k = -1, count = 0;
      for (int i = 0; i < d; ++i)
        if (v(i) != T(0)) k = i, ++count;
      if (count != 1 || seen[k] || (v(k) != T(1) && v(k) != T(-1))) return std::nullopt;
      seen[k] = true;
      E[k] = v(k) == T(1) ? F : MatX<T>(-F);
    }
  } catch (const std::exception&) {
    return std::nullopt;
  }
  auto b = make_basis<T>(n, true, std::move(E), origin, nullptr);
  if (b) b->documented = false;
  return b;
}

// A check made in the documented coordinates, for a slot given without its hat, that
// holds in the coordinates of another slot of the same file (`alternatives`: a basis and the slot
// it comes from) is a different convention, not a wrong formula: say so, ahead of the failure.
// `holds_in(basis)` re-runs the comparison in that basis and returns whether it holds.
template <class T, class HoldsIn>
std::string basis_hint(const std::string& slot, const std::string& hat_slot, const std::string& algebra,
                       const Basis<T>& documented, const std::vector<std::optional<Basis<T>>>& alternatives,
                       HoldsIn&& holds_in) {
  for (const auto& alt : alternatives) {
    if (!alt || alt->documented) continue;
    bool holds = false;
    try {
      holds = holds_in(*alt);
    } catch (...) {}
    if (holds)
      return "your coordinates of " + algebra +
             " are ordered or signed differently from the suite's documented ones: in "
             "the coordinates " +
             alt->origin + " uses (" + alt->describe() + ") " + slot + " is right. Give " + hat_slot +
             " too, so that the suite checks " + slot + " in your coordinates, or use the documented ones (" +
             documented.describe() + ")\n";
  }
  return {};
}

}  // namespace gm::coords
