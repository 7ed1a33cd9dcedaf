// The cotangent-lift momentum map of a second action: SO(n) acting on Q in R^{n x n}
// on the right, Q -> Q g, the action behind the closing exercise's (3.23). Its cotangent lift is
// P -> P g, and with the pairing (2.15) the definition of the momentum-map section,
//     J^xi(Q, P) = <<P, xi_M(Q)>> = tr(P^T Q xi) = <J(Q, P), xi>,
// gives J(Q, P) = Q^T P - P^T Q (the corrected M of the closing exercise, erratum mm.manakov-clebsch).
//   - Proposition (J^xi is the Hamiltonian of the cotangent-lifted action): with the canonical
//     bracket of T*R^{n x n}, {Q, J^xi} = Q xi and {P, J^xi} = P xi, for n = 3..6.
//   - Theorem (infinitesimal equivariance): along Q' = Q xi, P' = P xi, J' = -[xi, J] = ad*_xi J,
//     on so(3) and so(4), the algebras the subject's ad* covers.
// J itself is the suite's formula (no slot computes it); what the subject supplies is the pairing
// that turns J into J^xi, the canonical bracket, and ad* with its basis (lie_hat).
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"

#include <cstdio>

namespace gm {
namespace properties_momentum_map_right_action {
namespace {

template <class T>
MatX<T> J_right(const MatX<T>& Q, const MatX<T>& P) {
  return (Q.transpose() * P - P.transpose() * Q).eval();
}

// The entries of an n x n matrix, row by row, padded with zeros to a multiple of 3: coordinates on
// R^{n x n} in blocks of three, so that T*R^{n x n} is a product of copies of T*R^3.
template <class T>
VecX<T> blocks_of(const MatX<T>& X) {
  const Eigen::Index n = X.rows(), m = n * n, padded = (m + 2) / 3 * 3;
  VecX<T> v = VecX<T>::Zero(padded);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) v(n * i + j) = X(i, j);
  return v;
}

// The canonical bracket of T*R^{n x n} from gradients, as the sum over the factors T*R^3 of the
// subject's canonical_bracket (the bracket of a product is the sum of the factors' brackets).
template <class T>
T canonical_bracket_nn(const Subject<T>& s, const MatX<T>& dF_dQ, const MatX<T>& dF_dP, const MatX<T>& dG_dQ,
                       const MatX<T>& dG_dP) {
  const VecX<T> fq = blocks_of(dF_dQ), fp = blocks_of(dF_dP), gq = blocks_of(dG_dQ), gp = blocks_of(dG_dP);
  T sum(0);
  for (Eigen::Index b = 0; b < fq.size(); b += 3)
    sum += s.canonical_bracket(Vec3<T>(fq.template segment<3>(b)), Vec3<T>(fp.template segment<3>(b)),
                               Vec3<T>(gq.template segment<3>(b)), Vec3<T>(gp.template segment<3>(b)));
  return sum;
}

// Gradient of a function bilinear in (Q, P), in one of its matrix arguments: exact central
// differences with unit steps, (f(X + E_ij) - f(X - E_ij)) / 2.
template <class T, class F>
MatX<T> gradient_of_bilinear(const F& f, const MatX<T>& X) {
  MatX<T> g(X.rows(), X.cols());
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
      MatX<T> up = X, down = X;
      up(i, j) += T(1);
      down(i, j) -= T(1);
      g(i, j) = (f(up) - f(down)) / T(2);
    }
  return g;
}

// Proposition of the momentum-map section for Q -> Q g: J^xi = <J(Q, P), xi> with the subject's
// pairing, its gradients by exact differences, and {Q_ij, J^xi}, {P_ij, J^xi} with the subject's
// canonical bracket. Sizes: J^xi has n^2-term sums of |xi| (|Q| + 1) (|P| + 1) (the unit steps), the
// gradients and the brackets add sums of n^2 terms: scale n^2 |xi| (|Q| + 1) (|P| + 1), k = 8 n^2.
template <class T>
void momentum_map_right_action_generates_lift(const Subject<T>& s) {
  const int n = dyn::pick<T>(rc::gen::inRange(3, 7), "n");
  const MatX<T> Q = dyn::pick<T>(gen::mat<T>(n, n, 32, 6), "Q");
  const MatX<T> P = dyn::pick<T>(gen::mat<T>(n, n, 32, 6), "P");
  const MatX<T> xi = dyn::draw_skew<T>(n, 32);
  auto J_xi = [&](const MatX<T>& q, const MatX<T>& p) { return s.pairing(J_right<T>(q, p), xi); };
  const MatX<T> dJ_dQ = gradient_of_bilinear<T>([&](const MatX<T>& q) { return J_xi(q, P); }, Q);
  const MatX<T> dJ_dP = gradient_of_bilinear<T>([&](const MatX<T>& p) { return J_xi(Q, p); }, P);
  const MatX<T> zero = MatX<T>::Zero(n, n);
  MatX<T> Q_dot(n, n), P_dot(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      MatX<T> E = zero;
      E(i, j) = T(1);
      Q_dot(i, j) = canonical_bracket_nn(s, E, zero, dJ_dQ, dJ_dP);
      P_dot(i, j) = canonical_bracket_nn(s, zero, E, dJ_dQ, dJ_dP);
    }
  const T scale = T(n * n) * norm_inf(xi) * (norm_inf(Q) + T(1)) * (norm_inf(P) + T(1));
  require_close("momentum-map Proposition, right action Q -> Q g: Q' = {Q, J^xi} = Q xi, J = Q^T P - P^T Q", Q_dot,
                MatX<T>(Q * xi), scale, 8.0 * n * n);
  require_close("momentum-map Proposition, right action, cotangent lift: P' = {P, J^xi} = P xi", P_dot, MatX<T>(P * xi),
                scale, 8.0 * n * n);
}

// Theorem of the momentum-map section for Q -> Q g, on so(3) and so(4): J' = J(Q xi, P) + J(Q, P xi)
// (J bilinear) is ad*_xi J, read in the subject's coordinates: mu_k = <J, E_k> with E_k its
// lie_hat of e_k, and (ad*_xi mu)_k = <J', E_k> for xi = its lie_hat of x. Sizes: J' and the
// pairings are sums of n^3 terms of |x| |Q| |P| (|E_k| <= 1): scale 4 n^3 |x| |Q| |P|, k = 16.
template <class T>
void momentum_map_right_action_equivariance(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4}) {
    const int n = g == LieAlgebraId::so3 ? 3 : 4, d = g == LieAlgebraId::so3 ? 3 : 6;
    const MatX<T> Q = dyn::pick<T>(gen::mat<T>(n, n, 32, 6), "Q");
    const MatX<T> P = dyn::pick<T>(gen::mat<T>(n, n, 32, 6), "P");
    const VecX<T> x = dyn::pick<T>(gen::vec<T>(d, 32, 6), "x");
    const MatX<T> xi = s.lie_hat(g, x);
    const MatX<T> J = J_right<T>(Q, P),
                  J_dot = (J_right<T>((Q * xi).eval(), P) + J_right<T>(Q, (P * xi).eval())).eval();
    VecX<T> mu(d), mu_dot(d);
    for (int k = 0; k < d; ++k) {
      VecX<T> e = VecX<T>::Zero(d);
      e(k) = T(1);
      const MatX<T> E = s.lie_hat(g, e);
      mu(k) = (J.transpose() * E).trace() / T(2);
      mu_dot(k) = (J_dot.transpose() * E).trace() / T(2);
    }
    char what[160];
    std::snprintf(what, sizeof what,
                  "momentum-map Theorem, right action on %s: along Q' = Q xi, P' = P xi, J' = ad*_xi J "
                  "(J = Q^T P - P^T Q)",
                  lie_algebra_name(g));
    const T scale = T(4 * n * n * n) * norm_inf(x) * dyn::at_least_one(norm_inf(Q)) * dyn::at_least_one(norm_inf(P));
    require_close(what, mu_dot, s.ad_star(g, x, mu), scale, 16);
  }
}

}  // namespace

GM_PROPERTY(
    momentum_map_right_action_generates_lift, all_scalars,
    {.spec = "mm.second-action",
     .title = "SO(n) on R^{n x n} by Q -> Q g, n = 3..6: J^xi = <Q^T P - P^T Q, xi> generates Q' = Q xi, P' = P xi",
     .tolerance = ToleranceClass::Exact,
     .needs = {"pairing", "canonical_bracket"},
     .negative_controls = {"pairing_without_half", "canonical_bracket_sign_flipped"},
     .cases = {.d = 100, .mp = 10, .q = 5}});

GM_PROPERTY(momentum_map_right_action_equivariance, all_scalars,
            {.spec = "mm.second-action",
             .title = "SO(3), SO(4) on R^{n x n} by Q -> Q g: along Q' = Q xi, P' = P xi, J' = ad*_xi J",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_hat", "ad_star"},
             .negative_controls = {"ad_star_is_ad", "ad_star_sign_flipped"},
             .cases = {.d = 100, .mp = 25, .q = 10}});

}  // namespace properties_momentum_map_right_action
}  // namespace gm
