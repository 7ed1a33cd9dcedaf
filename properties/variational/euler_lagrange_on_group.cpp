// Theorem 1.1 (ii) <=> (iv), and Theorem 2.3, for a family of Lagrangians that are neither
// quadratic nor diagonal.
//
// (ii) says that g(t) satisfies the Euler-Lagrange equations of L(g, dg/dt) = l(g^-1 dg/dt) on G
// itself. They are written here in a chart, as one would by hand: g = cay(X(q)) =
// (Id - X)^-1 (Id + X) with X(q) = sum q_k E_k, E_k the subject's hat of the k-th basis vector, so
// that (the derivative of the Cayley transform is 2 (Id - X)^-1 dX (Id - X)^-1)
//   xi(q, dq/dt) = vee(g^-1 dg/dt) = vee(2 (Id + X)^-1 X(dq/dt) (Id - X)^-1)      (subject's vee)
// and L(q, dq/dt) = l(xi(q, dq/dt)). The Euler-Lagrange expression
//   EL_k = d/dt dL/d(dq_k/dt) - dL/dq_k
// comes from exact first and mixed second derivatives of L (hyper-dual numbers): along a curve
// whose (q, dq/dt) moves with velocity (dq/dt, d2q/dt2), d/dt dL/d(dq_k/dt) is the mixed derivative
// of L in the directions (0, e_k) and (dq/dt, d2q/dt2).
//
// At a drawn state (q, dq/dt), the acceleration is the one for which mu = dl/dxi follows the
// reduced equation: dxi/dt = (d2l/dxi2)^-1 dmu/dt, then d2q/dt2 from dxi/dt = dxi/dq dq/dt +
// dxi/d(dq/dt) d2q/dt2. The reduced equation is
//   Theorem 1.1 (iv): dmu/dt = ad*_xi mu, the subject's ad*, on so(3), so(4) and sl(2, R);
//   Theorem 2.3 (2.35): dM/dt = [M, Omega], M the element of g representing mu in the pairing
//     tr(A B) (spec/catalogue.json, s2.matrix-euler-poincare), on the same algebras and on so(n),
//     n = 3..6 (3..5 in rationals), through hat_n and vee_n (on so(n) the pairing (2.15) gives the
//     same equation).
// Checked: EL = 0 along it ((iv) => (ii)); and a curve through the same state whose mu changes at
// dmu/dt + delta, delta != 0, is not a solution: EL = B^T delta, B = dxi/d(dq/dt), clearly non-zero
// (not (iv) => not (ii)). Once the first check has passed, this second one holds for any subject:
// it checks the construction (the Euler-Lagrange system is non-degenerate and misses exactly by
// B^T delta), so that a chart or an l for which EL vanishes identically cannot pass unnoticed.
//
// The Lagrangian: l(xi) = a . xi + s / 2 + c s^2 / 8, s = xi . K xi, K symmetric and in general
// not diagonal (support/general_lagrangian.hpp), its gradient and Hessian taken by hyper-dual
// numbers. q is drawn with |q| <= 1/2, so Id +- X is far from singular on all four algebras (on
// sl(2, R), det(Id +- X) = 1 + det X >= 1/2).
#include "properties/registry.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/lie_groups.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"
#include "properties/variational/support/general_lagrangian.hpp"

#include <Eigen/LU>

#include <cstdio>
#include <functional>

namespace gm {
namespace properties_euler_lagrange_on_group {
namespace {

template <class T>
using HD = deriv::HyperDual<T>;

// A matrix of hyper-dual numbers kept as its four real parts: a + b e1 + c e2 + d e1 e2.
template <class T>
struct HDMat {
  MatX<T> a, b, c, d;
};

template <class T>
HDMat<T> operator*(const HDMat<T>& x, const HDMat<T>& y) {
  return {(x.a * y.a).eval(), (x.a * y.b + x.b * y.a).eval(), (x.a * y.c + x.c * y.a).eval(),
          (x.a * y.d + x.b * y.c + x.c * y.b + x.d * y.a).eval()};
}

// m^-1 for m = a + b e1 + c e2 + d e1 e2, given n0 = a^-1 (a itself is not needed): the e1, e2
// and e1 e2 parts follow from m m^-1 = Id part by part.
template <class T>
HDMat<T> inverse_given(const MatX<T>& n0, const MatX<T>& b, const MatX<T>& c, const MatX<T>& d) {
  const MatX<T> n1 = -n0 * b * n0, n2 = -n0 * c * n0;
  const MatX<T> n12 = -n0 * (d * n0 + b * n2 + c * n1);
  return {n0, n1, n2, n12};
}

// The chart q -> cay(X(q)) of a matrix group near the identity, read back by the subject's vee.
template <class T>
struct CayleyChart {
  std::vector<MatX<T>> E;                      // the subject's hat of the basis vectors
  std::function<VecX<T>(const MatX<T>&)> vee;  // the subject's vee
  MatX<T> X(const VecX<T>& q) const {
    MatX<T> x = MatX<T>::Zero(E[0].rows(), E[0].cols());
    for (std::size_t k = 0; k < E.size(); ++k) x += q(static_cast<Eigen::Index>(k)) * E[k];
    return x;
  }
  int dim() const { return static_cast<int>(E.size()); }
};

// One state (q, dq/dt) of the chart with the inverses of Id +- X(q), shared by every evaluation.
template <class T>
struct ChartState {
  const CayleyChart<T>& chart;
  const GeneralLagrangian<T>& l;
  VecX<T> q, qd;
  MatX<T> plus_inv, minus_inv;  // (Id + X)^-1, (Id - X)^-1

  ChartState(const CayleyChart<T>& c, const GeneralLagrangian<T>& lag, VecX<T> q_, VecX<T> qd_)
      : chart(c), l(lag), q(std::move(q_)), qd(std::move(qd_)) {
    const MatX<T> Xq = chart.X(q), Id = MatX<T>::Identity(Xq.rows(), Xq.cols());
    plus_inv = (Id + Xq).fullPivLu().inverse();
    minus_inv = (Id - Xq).fullPivLu().inverse();
  }

  // xi(q + e1 uq + e2 wq, dq/dt + e1 uqd + e2 wqd), part by part: vee is linear.
  std::vector<HD<T>> xi_seeded(const VecX<T>& uq, const VecX<T>& uqd, const VecX<T>& wq, const VecX<T>& wqd) const {
    // Id +- X(q + e1 uq + e2 wq) = (Id +- X(q)) +- X(uq) e1 +- X(wq) e2: X is linear, no e1 e2 part.
    const MatX<T> Z = MatX<T>::Zero(plus_inv.rows(), plus_inv.cols());
    const MatX<T> Xu = chart.X(uq), Xw = chart.X(wq);
    const HDMat<T> P = inverse_given<T>(plus_inv, Xu, Xw, Z);
    const HDMat<T> M = inverse_given<T>(minus_inv, (-Xu).eval(), (-Xw).eval(), Z);
    const HDMat<T> V{chart.X(qd), chart.X(uqd), chart.X(wqd), Z};
    const HDMat<T> xi_hat = P * V * M;
    const VecX<T> a = chart.vee((T(2) * xi_hat.a).eval()), b = chart.vee((T(2) * xi_hat.b).eval());
    const VecX<T> c = chart.vee((T(2) * xi_hat.c).eval()), d = chart.vee((T(2) * xi_hat.d).eval());
    std::vector<HD<T>> xi;
    for (Eigen::Index i = 0; i < a.size(); ++i) xi.emplace_back(a(i), b(i), c(i), d(i));
    return xi;
  }
  HD<T> L_seeded(const VecX<T>& uq, const VecX<T>& uqd, const VecX<T>& wq, const VecX<T>& wqd) const {
    return l(xi_seeded(uq, uqd, wq, wqd));
  }
  VecX<T> zero() const { return VecX<T>::Zero(chart.dim()); }
  VecX<T> unit(int k) const { return VecX<T>::Unit(chart.dim(), k); }

  VecX<T> xi() const {
    const auto x = xi_seeded(zero(), zero(), zero(), zero());
    VecX<T> v(chart.dim());
    for (int i = 0; i < chart.dim(); ++i) v(i) = x[static_cast<std::size_t>(i)].a;
    return v;
  }
  // dxi/dt for the acceleration qdd: dxi/dq dq/dt + dxi/d(dq/dt) qdd, the e1 part along (dq/dt, qdd).
  VecX<T> xi_rate(const VecX<T>& qdd) const {
    const auto x = xi_seeded(qd, qdd, zero(), zero());
    VecX<T> v(chart.dim());
    for (int i = 0; i < chart.dim(); ++i) v(i) = x[static_cast<std::size_t>(i)].b;
    return v;
  }
  // B = dxi/d(dq/dt). xi_rate is affine in qdd (a directional derivative is linear in its
  // direction), with matrix B.
  MatX<T> velocity_matrix() const {
    MatX<T> B(chart.dim(), chart.dim());
    for (int j = 0; j < chart.dim(); ++j) B.col(j) = xi_rate(unit(j)) - xi_rate(zero());
    return B;
  }
  // The acceleration that makes dxi/dt equal to xi_dot.
  VecX<T> acceleration_for(const VecX<T>& xi_dot) const {
    return velocity_matrix().fullPivLu().solve((xi_dot - xi_rate(zero())).eval());
  }

  // The two terms of EL_k = d/dt dL/d(dq_k/dt) - dL/dq_k along the acceleration qdd.
  struct Terms {
    VecX<T> rate_of_momentum, force;
  };
  Terms euler_lagrange(const VecX<T>& qdd) const {
    Terms t{VecX<T>(chart.dim()), VecX<T>(chart.dim())};
    for (int k = 0; k < chart.dim(); ++k) {
      t.rate_of_momentum(k) = L_seeded(zero(), unit(k), qd, qdd).d;
      t.force(k) = L_seeded(unit(k), zero(), zero(), zero()).b;
    }
    return t;
  }
};

// The reduced equation's dmu/dt at (xi, mu).
template <class T>
using ReducedRate = std::function<VecX<T>(const VecX<T>& xi, const VecX<T>& mu)>;

// Theorem 2.3's right-hand side: the coordinates of [M, Omega], M representing mu in tr(A B).
template <class T>
ReducedRate<T> matrix_commutator_rate(const CayleyChart<T>& chart) {
  return [&chart](const VecX<T>& xi, const VecX<T>& mu) {
    const MatX<T> M = lie::representative(chart.E, mu), Omega = chart.X(xi);
    const MatX<T> dM = M * Omega - Omega * M;
    VecX<T> r(chart.dim());
    for (int k = 0; k < chart.dim(); ++k) r(k) = (dM * chart.E[static_cast<std::size_t>(k)]).trace();
    return r;
  };
}

// Round-off. The two terms of EL_k are sums of products of mu, the Hessian, xi, dq/dt, d2q/dt2 and
// entries of (Id +- X)^-1 (of moderate size for |q| <= 1/2) over four to six matrix products,
// linear in d2q/dt2; scale = (|mu| + |d2l/dxi2| (|xi| + |dxi/dt|)) (1 + |dq/dt|)
// (1 + |dq/dt| + |d2q/dt2|) d bounds their sizes (the two solves behind d2q/dt2 are well
// conditioned by the draw, see the file comment).
// The converse is quantitative: exactly, EL = B^T (dmu/dt - ad*_xi mu) with B = dxi/d(dq/dt) (the
// Euler-Lagrange expression is the reduced one read through the chart), so a curve that misses the
// reduced equation by delta misses the Euler-Lagrange equations by B^T delta, which is not zero
// (B is invertible: the chart is one).
// k = 8 for both; the worst residuals measured are in the catalogue note of s1.ep-euler-lagrange.
template <class T>
void check_euler_lagrange(const std::string& where, const CayleyChart<T>& chart, const ReducedRate<T>& rate) {
  const int d = chart.dim();
  const GeneralLagrangian<T> l = draw_lagrangian<T>(d);
  const ChartState<T> st(chart, l, *gen::vec<T>(d, 2, 2).as("q (chart coordinates)"),
                         *gen::vec<T>(d, 16, 3).as("dq/dt"));
  // delta, relative to the size of dmu/dt: a miss of the reduced equation that is not lost in
  // its round-off; never zero, or the converse would test nothing.
  VecX<T> delta = *gen::vec<T>(d, 8, 3).as("delta");
  if (max_abs(delta) == T(0)) delta(0) = T(1);
  const VecX<T> xi = st.xi(), mu = l.gradient(xi);
  const MatX<T> H = l.hessian(xi);
  const VecX<T> mu_dot = rate(xi, mu);
  delta *= T(1) + norm_inf(mu_dot);
  const VecX<T> xi_dot = H.fullPivLu().solve(mu_dot);
  const VecX<T> qdd = st.acceleration_for(xi_dot);
  const auto el = st.euler_lagrange(qdd);
  const auto size_for = [&](const VecX<T>& x_dot, const VecX<T>& q_dd) {
    return T(T(norm_inf(mu) + norm_inf(H) * (norm_inf(xi) + norm_inf(x_dot))) * (T(1) + norm_inf(st.qd)) *
             (T(1) + norm_inf(st.qd) + norm_inf(q_dd)) * T(d));
  };
  const T size = size_for(xi_dot, qdd);
  showing_inputs(
      [&] {
        return named("q (g = cay(X(q)))", st.q) + named("dq/dt", st.qd) + named("xi = vee(g^-1 dg/dt)", xi) +
               named("mu = dl/dxi", mu) + named("dmu/dt of the reduced equation", mu_dot) +
               named("l: linear term a", l.a) + named("l: K", l.K) + named("l: quartic coefficient c", l.c);
      },
      [&] {
        require_close(where +
                          ": the Euler-Lagrange equations of L(q, dq/dt) = l(xi) hold, "
                          "d/dt dL/d(dq/dt) = dL/dq",
                      el.rate_of_momentum, el.force, size, 8);
        // Not a solution: mu changes at dmu/dt + delta.
        const VecX<T> xi_dot_off = H.fullPivLu().solve((mu_dot + delta).eval());
        const VecX<T> qdd_off = st.acceleration_for(xi_dot_off);
        const auto off = st.euler_lagrange(qdd_off);
        const VecX<T> el_off = off.rate_of_momentum - off.force;
        const T size_off = size_for(xi_dot_off, qdd_off);
        require_close(where +
                          ": converse: a curve whose dmu/dt misses the reduced equation by delta misses the "
                          "Euler-Lagrange equations by B^T delta, B = dxi/d(dq/dt)",
                      el_off, (st.velocity_matrix().transpose() * delta).eval(), size_off, 8);
        const T residual = max_abs(el_off);
        const T allowed = T(8) * eps<T>() * size_off;
        char detail[200];
        std::snprintf(detail, sizeof detail, "|EL| = %.6g, round-off bound %.6g, |delta| = %.6g", to_double(residual),
                      to_double(allowed), to_double(max_abs(delta)));
        require(where +
                    ": converse: a curve whose dmu/dt misses the reduced equation by delta != 0 "
                    "does not satisfy the Euler-Lagrange equations",
                residual > T(1000) * allowed, detail);
      });
}

template <class T>
CayleyChart<T> chart_of(const Subject<T>& s, LieAlgebraId g) {
  CayleyChart<T> c;
  const int d = truth::algebra_dimension(g);
  for (int k = 0; k < d; ++k) c.E.push_back(s.lie_hat(g, VecX<T>::Unit(d, k)));
  c.vee = [&s, g](const MatX<T>& m) { return s.lie_vee(g, m); };
  return c;
}

template <class T>
void euler_lagrange_on_group_iff_euler_poincare(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2}) {
    const CayleyChart<T> chart = chart_of(s, g);
    check_euler_lagrange<T>(
        std::string("Theorem 1.1 (iv) <=> (ii) on ") + lie_algebra_name(g) + " with dmu/dt = ad*_xi mu (subject's ad*)",
        chart, [&](const VecX<T>& xi, const VecX<T>& mu) { return s.ad_star(g, xi, mu); });
  }
}

template <class T>
void matrix_euler_poincare_any_lagrangian(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2}) {
    const CayleyChart<T> chart = chart_of(s, g);
    check_euler_lagrange<T>(
        std::string("Theorem 2.3 on ") + lie_algebra_name(g) + " with dM/dt = [M, Omega], M representing mu in tr(A B)",
        chart, matrix_commutator_rate(chart));
  }
}

template <class T>
void matrix_euler_poincare_any_lagrangian_so_n(const Subject<T>& s) {
  // In rationals n stops at 5: at n = 6 (d = 15) the d^2 hyper-dual evaluations of the quartic l's
  // Hessian on the chart's large denominators cost seconds per case.
  const int n_max = ScalarInfo<T>::exact ? 5 : 6;
  for (int n = 3; n <= n_max; ++n) {
    CayleyChart<T> chart;
    const int d = truth::so_dimension(n);
    for (int k = 0; k < d; ++k) chart.E.push_back(s.hat_n(VecX<T>::Unit(d, k), n));
    chart.vee = [&s](const MatX<T>& m) { return s.vee_n(m); };
    check_euler_lagrange<T>("Theorem 2.3 on so(" + std::to_string(n) + ") with dM/dt = [M, Omega] (hat_n, vee_n)",
                            chart, matrix_commutator_rate(chart));
  }
}

}  // namespace

GM_PROPERTY(euler_lagrange_on_group_iff_euler_poincare, all_scalars,
            {.spec = "s1.ep-euler-lagrange",
             .title = "Theorem 1.1 (ii)<=>(iv) on SO(3), SO(4), SL(2,R), l neither quadratic nor diagonal: in a Cayley "
                      "chart, the Euler-Lagrange equations on G hold iff dmu/dt = ad*_xi mu (subject's ad*)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"ad_star", "lie_hat", "lie_vee"},
             .negative_controls = {"ad_star_sign_flipped", "ad_star_minus_ad"},
             .cases = {.d = 100, .mp = 25, .q = 10}});

GM_PROPERTY(matrix_euler_poincare_any_lagrangian, all_scalars,
            {.spec = "s2.matrix-euler-poincare",
             .title = "Theorem 2.3 on SO(3), SO(4), SL(2,R), l neither quadratic nor diagonal: the Euler-Lagrange "
                      "equations on G in a Cayley chart hold iff dM/dt = [M, Omega] (tr(A B) pairing)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_hat", "lie_vee"},
             .negative_controls = {"lie_vee_sl2_transposed", "lie_hat_sl2_transposed"},
             .cases = {.d = 100, .mp = 25, .q = 10}});

GM_PROPERTY(
    matrix_euler_poincare_any_lagrangian_so_n, all_scalars,
    {.spec = "s2.matrix-euler-poincare",
     .title =
         "Theorem 2.3 on SO(n), n = 3..6 (3..5 exact), l neither quadratic nor diagonal: the Euler-Lagrange equations "
         "on SO(n) in a Cayley chart hold iff dM/dt = [M, Omega] (subject's hat_n, vee_n)",
     .tolerance = ToleranceClass::Exact,
     .needs = {"hat_n", "vee_n"},
     .negative_controls = {"hat_n_written_for_so4", "vee_n_written_for_so4"},
     .cases = {.d = 100, .mp = 25, .q = 5}});

}  // namespace properties_euler_lagrange_on_group
}  // namespace gm
