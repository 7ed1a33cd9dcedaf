// Manakov's SO(n) rigid body and the matrix Euler-Poincare equations (section 2.2-2.4, the
// closing exercise): isospectrality, coadjoint similarity, the eigenvector equations, the
// Clebsch-type form (3.23) and its momentum, Theorem 2.3 beyond so(n).
//
// Flows are those of the subject's slots (GBS, support/flow.hpp): every statement here is about
// the subject's equations. A = diag(a) with a_i in [1/2, 2]; n from 3 to 6.
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/lie_groups.hpp"
#include "properties/support/spectrum.hpp"
#include "properties/support/tolerance.hpp"

#include <Eigen/LU>

#include <cstdio>

namespace gm {
namespace properties_manakov_flow {
namespace {

// The horizon t = 10, in 50 digits too (a 50-digit run on [0, 1] said little about a
// flow's long-time accuracy).
template <class T>
T horizon() {
  return T(10);
}

template <class T>
int draw_n() {
  return dyn::pick<T>(rc::gen::inRange(3, 7), "n");
}

// s2.isospectral: along the subject's (2.36), tr(M^k) for k = 1..n (which fix the characteristic
// polynomial, hence tr(M^k) for every k) and the eigenvalues +-i lambda_j of M are constant.
template <class T>
void manakov_flow_is_isospectral(const Subject<T>& s) {
  const int n = draw_n<T>();
  const auto a = dyn::draw_manakov_a<T>(n);
  const MatX<T> M0 = dyn::draw_skew<T>(n, 32);
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto Ms = dyn::subject_manakov_M(s, dyn::diag_of(a), M0, times);
  const T lambda = dyn::manakov_rate(a, M0);
  const T size = dyn::at_least_one(T(M0.norm()));
  const auto tr0 = spectral::power_traces<T>(M0, n);
  const VecX<T> ev0 = spectral::skew_spectrum<T>(M0);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const T g = dyn::growth(lambda, times[i]);
    const auto tr = spectral::power_traces<T>(Ms[i], n);
    T sk(1);
    for (int k = 1; k <= n; ++k) {
      sk *= size;
      char what[96];
      std::snprintf(what, sizeof what, "tr(M(t)^%d) = tr(M(0)^%d) along the subject's (2.36), n = %d", k, k, n);
      // An invariant of degree k: k_tol = 64 k (support/dynamics.hpp), on the scale |M|^k.
      require_close(what, tr[k - 1], tr0[k - 1], T(sk * g), 64.0 * k);
    }
    require_close("eigenvalues lambda_j^2 of -M(t)^2 = those of -M(0)^2", spectral::skew_spectrum<T>(Ms[i]), ev0,
                  T(size * size * g), 128 * n);
  }
}

// s2.isospectral: M(t) = O(t)^-1 M(0) O(t) with dO/dt = O Omega, O(0) = Id.
template <class T>
void manakov_coadjoint_similarity(const Subject<T>& s) {
  const int n = draw_n<T>();
  const auto a = dyn::draw_manakov_a<T>(n);
  const ManakovState<T> x0{dyn::draw_skew<T>(n, 32), MatX<T>::Identity(n, n)};
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto xs = dyn::subject_manakov(s, dyn::diag_of(a), x0, times);
  const T lambda = dyn::manakov_rate(a, x0.M);
  const T size = dyn::at_least_one(norm_inf(x0.M));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const MatX<T>& O = xs[i].O;
    // O^T M0 O - M = O^T (M0 - O M O^T) O: the drift of the degree-2 invariant O M O^T.
    require_close("M(t) = O(t)^-1 M(0) O(t) along the subject's (2.36) with dO/dt = O Omega", xs[i].M,
                  (O.transpose() * x0.M * O).eval(), T(size * n * dyn::growth(lambda, times[i])), 128);
  }
}

// s2.eigenvectors, Proposition 2.5: psi(t) = O(t)^-1 psi(0), equivalently dpsi/dt = -Omega psi,
// keeps M psi = lambda psi. M is skew, so lambda = i mu and psi = v - (i/mu) M v for v in the
// eigenspace of -M^2 for mu^2; the complex equation M psi = i mu psi is the real pair
// M psi_r = -mu psi_i, M psi_i = mu psi_r. psi is integrated with M and O by its own equation.
template <class T>
void manakov_eigenvectors_follow(const Subject<T>& s) {
  using std::sqrt;
  const int n = draw_n<T>();
  const auto a = dyn::draw_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  const MatX<T> M0 = dyn::draw_skew<T>(n, 32);
  const auto eig = spectral::symmetric_eigen<T>((M0.transpose() * M0).eval());
  const T mu = sqrt(eig.values.back());
  RC_PRE(mu > T(0));
  const VecX<T> pr0 = eig.vectors.col(n - 1), pi0 = (-M0 * pr0 / mu).eval();
  const int nn = n * n;
  VecX<T> x0(2 * nn + 2 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) x0(n * i + j) = M0(i, j), x0(nn + n * i + j) = i == j ? T(1) : T(0);
  x0.segment(2 * nn, n) = pr0;
  x0.segment(2 * nn + n, n) = pi0;
  auto unpack = [n, nn](const VecX<T>& v, MatX<T>& M, MatX<T>& O) {
    M.resize(n, n);
    O.resize(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = v(n * i + j), O(i, j) = v(nn + n * i + j);
  };
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    MatX<T> M, O;
    unpack(v, M, O);
    const MatX<T> W = s.manakov_Omega(A, M), dM = s.manakov_2_34(A, M), dO = O * W;
    VecX<T> d(v.size());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) d(n * i + j) = dM(i, j), d(nn + n * i + j) = dO(i, j);
    d.segment(2 * nn, n) = -W * v.segment(2 * nn, n);
    d.segment(2 * nn + n, n) = -W * v.segment(2 * nn + n, n);
    return d;
  });
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto xs = g.sample(x0, T(0), times);
  const T lambda = dyn::manakov_rate(a, M0);
  const T size = dyn::at_least_one(T(M0.norm()));
  for (std::size_t i = 0; i < times.size(); ++i) {
    MatX<T> M, O;
    unpack(xs[i], M, O);
    const VecX<T> pr = xs[i].segment(2 * nn, n), pi = xs[i].segment(2 * nn + n, n);
    const T gr = dyn::growth(lambda, times[i]);
    // Residuals of degree 2 in (M, psi), transported by the flow: k = 128 n (n-term products).
    require_close("Re(M psi - i mu psi) = M psi_r + mu psi_i = 0 (Proposition 2.5)", (M * pr).eval(), (-mu * pi).eval(),
                  T(size * gr), 128 * n);
    require_close("Im(M psi - i mu psi) = M psi_i - mu psi_r = 0", (M * pi).eval(), (mu * pr).eval(), T(size * gr),
                  128 * n);
    require_close("psi(t) = O(t)^-1 psi(0), dpsi/dt = -Omega psi", pr, (O.transpose() * pr0).eval(), gr, 128 * n);
  }
}

// ---------------------------------------------------------------------------------------------
// mm.manakov-clebsch, the closing exercise: dQ/dt = Q Omega, dP/dt = P Omega (3.23).

template <class T>
struct QP {
  int n;
  std::vector<T> a;
  MatX<T> A, Q, P;
};

// n from 3 to 5 (a flow of (Q, P) has 2 n^2 coordinates).
template <class T>
QP<T> draw_qp() {
  QP<T> d;
  d.n = dyn::pick<T>(rc::gen::inRange(3, 6), "n");
  d.a = dyn::draw_manakov_a<T>(d.n);
  d.A = dyn::diag_of(d.a);
  d.Q = dyn::pick<T>(gen::rotation<T>(d.n), "Q");
  d.P = dyn::pick<T>(gen::rotation<T>(d.n), "P");
  return d;
}

template <class T>
std::vector<std::pair<MatX<T>, MatX<T>>> subject_qp_flow(const Subject<T>& s, const QP<T>& d,
                                                         const std::vector<T>& times) {
  const int n = d.n, nn = n * n;
  auto pack = [&](const MatX<T>& Q, const MatX<T>& P) {
    VecX<T> v(2 * nn);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) v(n * i + j) = Q(i, j), v(nn + n * i + j) = P(i, j);
    return v;
  };
  auto unpack = [&](const VecX<T>& v) {
    MatX<T> Q(n, n), P(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) Q(i, j) = v(n * i + j), P(i, j) = v(nn + n * i + j);
    return std::make_pair(Q, P);
  };
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    const auto [Q, P] = unpack(v);
    const auto dqp = s.manakov_clebsch_3_23(d.A, Q, P);
    return pack(dqp.first, dqp.second);
  });
  std::vector<std::pair<MatX<T>, MatX<T>>> out;
  for (const auto& v : g.sample(pack(d.Q, d.P), T(0), times)) out.push_back(unpack(v));
  return out;
}

// The motion equation, which is linear in M and holds for the printed M and the variational one
// alike: Q(t) = Q(0) U(t), P(t) = P(0) U(t) with one U (dU/dt = U Omega), so that
// M(t) = U^T M(0) U, i.e. dM/dt = [M, Omega] = ad*_Omega M.
template <class T>
void manakov_clebsch_momentum_is_coadjoint(const Subject<T>& s) {
  const QP<T> d = draw_qp<T>();
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto qp = subject_qp_flow(s, d, times);
  auto printed_M = [](const MatX<T>& Q, const MatX<T>& P) {
    return ((P.transpose() * Q - Q.transpose() * P) / T(2)).eval();
  };
  const MatX<T> M0 = printed_M(d.Q, d.P);
  const T lambda = dyn::manakov_rate(d.a, (d.Q.transpose() * d.P - d.P.transpose() * d.Q).eval());
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto& [Q, P] = qp[i];
    const T g = dyn::growth(lambda, times[i]);
    const MatX<T> U = d.Q.transpose() * Q;
    // U is read off Q; the flow is accurate to round-off per step, and U, P have size 1.
    require_close("Q(0)^-1 Q(t) = P(0)^-1 P(t) (one U for both, (3.23))", U, (d.P.transpose() * P).eval(),
                  T(T(d.n) * g), 128);
    require_close("M(t) = U^T M(0) U for M = (P^T Q - Q^T P)/2: dM/dt = [M, Omega]", printed_M(Q, P),
                  (U.transpose() * M0 * U).eval(), T(T(d.n) * g), 128);
  }
}

// The identification M = dl/dOmega: Hamilton's principle for
//   S = int l(Omega) + tr(P^T (dQ/dt - Q Omega)) dt,   l = -tr(Omega A Omega)/2,
// is stationary in Omega at the Omega of the subject's (3.23) field: for every skew E,
//   d/de l(Omega + e E) = tr(P^T Q E).
// Exact in rationals (Q, P rational rotations; l quadratic, so the central difference with unit
// step is its exact derivative). This holds when Omega solves A Omega + Omega A = Q^T P - P^T Q;
// the printed M = (P^T Q - Q^T P)/2 gives -Omega/2 and fails.
template <class T>
void manakov_clebsch_momentum_is_dl_dOmega(const Subject<T>& s) {
  const QP<T> d = draw_qp<T>();
  const int n = d.n;
  const auto dqp = s.manakov_clebsch_3_23(d.A, d.Q, d.P);
  const MatX<T> W = d.Q.transpose() * dqp.first;  // Omega = Q^-1 dQ/dt
  const MatX<T> PQ = d.P.transpose() * d.Q;
  T scale = dyn::at_least_one(T(norm_inf(W) + T(1)));
  scale = scale * scale * T(n * n) * T(2);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      MatX<T> E = MatX<T>::Zero(n, n);
      E(i, j) = T(1);
      E(j, i) = T(-1);
      const T dl = (s.manakov_lagrangian(d.A, (W + E).eval()) - s.manakov_lagrangian(d.A, (W - E).eval())) / T(2);
      const T dc = (PQ * E).trace();
      char what[160];
      std::snprintf(
          what, sizeof what,
          "dS/dOmega = 0 along E_%d%d: d/de l(Omega + e E) = tr(P^T Q E) at the Omega of the subject's (3.23)", i + 1,
          j + 1);
      require_close(what, dl, dc, scale, 64);
    }
}

// The M that Hamilton's principle identifies, M = Q^T P - P^T Q, evolves by Manakov's equations
// (2.34) with its own Omega: along the subject's (3.23) flow it is the oracle's Manakov flow.
template <class T>
void manakov_clebsch_momentum_follows_manakov(const Subject<T>& s) {
  const QP<T> d = draw_qp<T>();
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto qp = subject_qp_flow(s, d, times);
  auto M_of = [](const MatX<T>& Q, const MatX<T>& P) { return (Q.transpose() * P - P.transpose() * Q).eval(); };
  const MatX<T> M0 = M_of(d.Q, d.P);
  const auto exact = dyn::oracle_manakov(d.a, ManakovState<T>{M0, MatX<T>::Identity(d.n, d.n)}, times);
  const T lambda = dyn::manakov_rate(d.a, M0);
  const T size = dyn::at_least_one(norm_inf(M0));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const T g = dyn::growth(lambda, times[i]);
    // Two flows compared: k = 64 (1 + lambda t)^2 (support/dynamics.hpp).
    require_close("M = Q^T P - P^T Q along the subject's (3.23) = Manakov's flow (2.34) of M(0)",
                  M_of(qp[i].first, qp[i].second), exact[i].M, T(size * T(d.n) * g * g), 64);
  }
}

// ---------------------------------------------------------------------------------------------
// s2.matrix-euler-poincare, Theorem 2.3 and Remark 2.8, on so(3), so(4) and sl(2, R).
//
// For l(xi) = xi . K xi / 2 the Euler-Poincare equation (Theorem 1.1 (iv)) in the subject's
// coordinates is dmu/dt = ad*_xi mu, mu = K xi. Its matrix form: with M the element of g that
// represents mu through a pairing B (B(M, X) = mu . vee(X) for all X in g), the claim is
//   rep(ad*_xi mu) = [M, hat(xi)].
// With B(A, C) = tr(A C), which is ad-invariant on every matrix Lie algebra, this holds; with the
// transpose pairing (2.15), (1/2) tr(A^T C), it holds on so(n) (where it equals -tr(A C)/2) and
// fails on sl(2, R) (not ad-invariant there). Exact in rationals.
template <class T>
void matrix_euler_poincare_trace_pairing(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2}) {
    const int d = g == LieAlgebraId::so4 ? 6 : 3;
    const VecX<T> xi = *gen::vec<T>(d).as("xi");
    VecX<T> K(d);
    for (int k = 0; k < d; ++k) K(k) = *gen::positive<T>(64, 2).as("K_k (l = xi . K xi / 2)");
    const VecX<T> mu = K.cwiseProduct(xi);
    const VecX<T> dmu = s.ad_star(g, xi, mu);
    std::vector<MatX<T>> E;
    for (int k = 0; k < d; ++k) {
      VecX<T> e = VecX<T>::Zero(d);
      e(k) = T(1);
      E.push_back(s.lie_hat(g, e));
    }
    const MatX<T> X = s.lie_hat(g, xi);
    const MatX<T> M = lie::representative(E, mu, false);
    const MatX<T> dM = lie::representative(E, dmu, false);
    const MatX<T> rhs = M * X - X * M;
    require_close(std::string("Theorem 2.3 on ") + lie_algebra_name(g) +
                      ": dM/dt = [M, Omega] for M = dl/dOmega in the pairing tr(A B)",
                  dM, rhs, T(norm_inf(xi) * norm_inf(mu) * T(d * 8)), 64);
    if (g == LieAlgebraId::sl2) {
      const MatX<T> MT = lie::representative(E, mu, true);
      const MatX<T> dMT = lie::representative(E, dmu, true);
      const T r = max_abs((dMT - (MT * X - X * MT)).eval());
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "with the transpose pairing (2.15) the matrix form fails on sl(2,R): |dM/dt - [M, Omega]| = %.6g "
                    "(|M| = %.3g); it holds on so(n), where (2.15) = -tr(A B)/2",
                    to_double(r), to_double(norm_inf(MT)));
      record_note(buf);
    }
  }
}

}  // namespace

GM_PROPERTY(
    manakov_flow_is_isospectral, float_scalars,
    {.spec = "s2.isospectral",
     .title = "(2.36), n = 3..6: tr(M^k) for k = 1..n and the eigenvalues of M are constant along the subject's "
              "Manakov flow",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"manakov_2_34"},
     .negative_controls = {"manakov_2_34_one_sided"},
     .cases = {.d = 20, .mp = 10, .q = 0}});

GM_PROPERTY(manakov_coadjoint_similarity, float_scalars,
            {.spec = "s2.isospectral",
             .title = "section 2.4: M(t) = O(t)^-1 M(0) O(t) with dO/dt = O Omega along the subject's Manakov flow",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"manakov_2_34", "manakov_Omega"},
             .negative_controls = {"manakov_commutator_reversed"},
             .cases = {.d = 20, .mp = 10, .q = 0}});

GM_PROPERTY(manakov_eigenvectors_follow, float_scalars,
            {.spec = "s2.eigenvectors",
             .title = "Proposition 2.5: psi(t) = O(t)^-1 psi(0), dpsi/dt = -Omega psi, keeps M psi = lambda psi",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"manakov_2_34", "manakov_Omega"},
             .negative_controls = {"manakov_commutator_reversed"},
             .cases = {.d = 20, .mp = 8, .q = 0}});

GM_PROPERTY(
    manakov_clebsch_momentum_is_coadjoint, float_scalars,
    {.spec = "mm.manakov-clebsch",
     .title = "closing exercise: under the subject's (3.23), M = (P^T Q - Q^T P)/2 satisfies dM/dt = [M, Omega]",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"manakov_clebsch_3_23"},
     .negative_controls = {"manakov_clebsch_P_left_multiplied"},
     .cases = {.d = 20, .mp = 4, .q = 0}});

GM_PROPERTY(manakov_clebsch_momentum_is_dl_dOmega, all_scalars,
            {.spec = "mm.manakov-clebsch",
             .title = "closing exercise: the action is stationary in Omega at the subject's (3.23), i.e. "
                      "dl/dOmega = Q^T P - P^T Q in (2.15) (not the printed (P^T Q - Q^T P)/2)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"manakov_clebsch_3_23", "manakov_lagrangian"},
             .negative_controls = {"manakov_clebsch_M_as_printed"},
             .cases = {.d = 50, .mp = 10, .q = 10}});

GM_PROPERTY(manakov_clebsch_momentum_follows_manakov, float_scalars,
            {.spec = "mm.manakov-clebsch",
             .title = "closing exercise: M = Q^T P - P^T Q along the subject's (3.23) evolves by Manakov's (2.34)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"manakov_clebsch_3_23"},
             .negative_controls = {"manakov_clebsch_M_as_printed"},
             .cases = {.d = 20, .mp = 6, .q = 0}});

GM_PROPERTY(matrix_euler_poincare_trace_pairing, all_scalars,
            {.spec = "s2.matrix-euler-poincare",
             .title = "Theorem 2.3 on so(3), so(4), sl(2,R): the EP equation is dM/dt = [M, Omega] for M = dl/dOmega "
                      "in the pairing tr(A B)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"ad_star", "lie_hat"},
             .negative_controls = {"ad_star_sl2_transpose_pairing", "ad_star_sign_flipped"}});

}  // namespace properties_manakov_flow
}  // namespace gm
