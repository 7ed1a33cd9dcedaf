// The variational statements: Proposition 2.1 (2.7)/(2.8); Theorems 1.1 (iii) and 2.1; the
// Hamilton-Pontryagin principle (2.16) on SO(3) and SO(n) and its Hamiltonian form (2.24); the Clebsch principle
// (3.17)-(3.18); Manakov's Lagrangian (Proposition 2.4); reconstruction from the reduced
// equations (section 1); the reduced equations on G x Y (the exercise of section 1).
//
// Each "first variation vanishes" property integrates the subject's equations (GBS,
// support/flow.hpp), evaluates the subject's Lagrangian (or Hamiltonian, pairing) along the
// result, and checks with support/variations.hpp that delta S = 0 up to quadrature error that is
// driven down to round-off, while a perturbed curve gives a clearly non-zero delta S. Derivatives
// of the quadratic Lagrangians are exact central differences with unit step,
// dl(x) . v = (l(x + v) - l(x - v)) / 2.
//
// Tolerances. Along the computed solution the integrand is zero up to the flow's error, which is
// ~64 eps |x| (1 + lambda t) kappa (support/dynamics.hpp), times the integrand's sensitivity to
// the state; scale = T * (size of the integrand's terms) * (1 + lambda T) * kappa, k = 64.
#include "properties/variational/support/variations.hpp"
#include "properties/registry.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"
#include "properties/variational/support/general_lagrangian.hpp"

namespace gm {
namespace properties_variations {
namespace {

// The time interval [0, kT] of the variational checks.
template <class T>
const T kT = T(2);

// A vector curve vanishing at 0 and T: Xi(t) = t (T - t) (c0 + c1 t), with its derivative.
template <class T, int N>
struct Bump {
  Eigen::Matrix<T, N, 1> c0, c1;
  Eigen::Matrix<T, N, 1> at(const T& t) const { return (t * (kT<T> - t) * (c0 + t * c1)).eval(); }
  Eigen::Matrix<T, N, 1> rate(const T& t) const {
    return ((kT<T> - T(2) * t) * (c0 + t * c1) + t * (kT<T> - t) * c1).eval();
  }
};

// Not zero (a zero variation or perturbation would make the check vacuous): a zero draw is nudged
// deterministically, so shrinking still ends on a simple value.
template <class T, int N>
Bump<T, N> draw_bump(int dim = N) {
  Bump<T, N> b;
  b.c0 = dyn::pick<T>(gen::vec<T>(dim, 32, 6), "c0 (the bump (T - 2t)(c0 + t c1) + t (T - t) c1)");
  b.c1 = dyn::pick<T>(gen::vec<T>(dim, 32, 6), "c1 (the bump)");
  if (b.c0.isZero() && b.c1.isZero()) {
    for (int i = 0; i < b.c0.size(); ++i) b.c0(i) = T(i % 2 ? -1 : 1) / T(4 << i);
    b.c1(0) = T(1) / T(8);
  }
  return b;
}

// The variations that test the converse of an "if and only if" (support/variations.hpp,
// require_first_variation_vanishes_iff): the drawn one and the coordinate bumps t (T - t) e_j and
// t^2 (T - t) e_j.
template <class T>
std::vector<Bump<T, Eigen::Dynamic>> converse_variations(const Bump<T, Eigen::Dynamic>& drawn, int dim) {
  std::vector<Bump<T, Eigen::Dynamic>> out{drawn};
  for (int j = 0; j < dim; ++j)
    for (int power = 0; power < 2; ++power) {
      Bump<T, Eigen::Dynamic> b;
      b.c0 = VecX<T>::Zero(dim);
      b.c1 = VecX<T>::Zero(dim);
      (power == 0 ? b.c0 : b.c1)(j) = T(1);
      out.push_back(b);
    }
  return out;
}

template <class T>
Vec3<T> vee3(const Mat3<T>& m) {
  return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
}

// ---------------------------------------------------------------------------------------------
// s2.restricted-variation, Proposition 2.1: for a two-parameter family O(t, s) in SO(3),
// Omega_hat = O^-1 dO/dt, Xi_hat = O^-1 dO/ds satisfy (2.7) dOmega_hat/ds - dXi_hat/dt =
// [Omega_hat, Xi_hat], and through the subject's vee (2.8) dOmega/ds - dXi/dt = Omega x Xi.
// O(t, s) = cay(W1(t, s)) cay(W2(t, s)), W_i the hat of a random quadratic polynomial in (t, s).
// O, dO/dt, dO/ds and d2O/dtds come exactly from hyper-dual arithmetic (support/derivatives.hpp),
// so the identity is checked exactly in rationals and to round-off in floats.
template <class T>
using HD = deriv::HyperDual<T>;

template <class T>
Eigen::Matrix<HD<T>, 3, 3> cayley_hd(const Eigen::Matrix<HD<T>, 3, 1>& w) {
  // (Id - hat w)^-1 (Id + hat w) = (Id + hat w + w w^T)(Id + hat w) / (1 + |w|^2).
  Eigen::Matrix<HD<T>, 3, 3> W, Id, Q;
  W << HD<T>(T(0)), -w(2), w(1), w(2), HD<T>(T(0)), -w(0), -w(1), w(0), HD<T>(T(0));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Id(i, j) = HD<T>(T(i == j ? 1 : 0));
  const HD<T> n2 = w(0) * w(0) + w(1) * w(1) + w(2) * w(2) + HD<T>(T(1));
  Eigen::Matrix<HD<T>, 3, 3> inv;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inv(i, j) = (Id(i, j) + W(i, j) + w(i) * w(j)) / n2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      HD<T> s(T(0));
      for (int k = 0; k < 3; ++k) s += inv(i, k) * (Id(k, j) + W(k, j));
      Q(i, j) = s;
    }
  return Q;
}

template <class T>
Eigen::Matrix<HD<T>, 3, 3> mul_hd(const Eigen::Matrix<HD<T>, 3, 3>& a, const Eigen::Matrix<HD<T>, 3, 3>& b) {
  Eigen::Matrix<HD<T>, 3, 3> c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      HD<T> s(T(0));
      for (int k = 0; k < 3; ++k) s += a(i, k) * b(k, j);
      c(i, j) = s;
    }
  return c;
}

template <class T>
void restricted_variation_2_8(const Subject<T>& s) {
  // w_i(t, s) = p0 + p1 t + p2 s + p3 t s + p4 t^2 + p5 s^2, for two vectors w_1, w_2.
  std::vector<Vec3<T>> p1, p2;
  for (int k = 0; k < 6; ++k)
    p1.push_back(*gen::vec3<T>(64, 6).as("p" + std::to_string(k) + " of w_1")),
        p2.push_back(*gen::vec3<T>(64, 6).as("p" + std::to_string(k) + " of w_2"));
  const T t0 = *gen::scalar<T>(64, 6).as("t0"), s0 = *gen::scalar<T>(64, 6).as("s0");
  const HD<T> t(t0, T(1), T(0), T(0)), sv(s0, T(0), T(1), T(0));
  auto w_of = [&](const std::vector<Vec3<T>>& p, bool inverse) {
    Eigen::Matrix<HD<T>, 3, 1> w;
    for (int i = 0; i < 3; ++i) {
      HD<T> x = HD<T>(p[0](i)) + HD<T>(p[1](i)) * t + HD<T>(p[2](i)) * sv + HD<T>(p[3](i)) * t * sv +
                HD<T>(p[4](i)) * t * t + HD<T>(p[5](i)) * sv * sv;
      w(i) = inverse ? -x : x;
    }
    return w;
  };
  const auto O = mul_hd<T>(cayley_hd<T>(w_of(p1, false)), cayley_hd<T>(w_of(p2, false)));
  // O^-1 = cay(-W2) cay(-W1), exactly, as hyper-dual numbers.
  const auto Oinv = mul_hd<T>(cayley_hd<T>(w_of(p2, true)), cayley_hd<T>(w_of(p1, true)));
  Mat3<T> Ov, Ot, Os, Ots, Iv, It, Is;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Ov(i, j) = O(i, j).a, Ot(i, j) = O(i, j).b, Os(i, j) = O(i, j).c, Ots(i, j) = O(i, j).d;
      Iv(i, j) = Oinv(i, j).a, It(i, j) = Oinv(i, j).b, Is(i, j) = Oinv(i, j).c;
    }
  const Mat3<T> Omega_hat = Iv * Ot, Xi_hat = Iv * Os;
  const Mat3<T> dOmega_ds = Is * Ot + Iv * Ots;  // d/ds (O^-1 dO/dt)
  const Mat3<T> dXi_dt = It * Os + Iv * Ots;     // d/dt (O^-1 dO/ds)
  const T scale = dyn::at_least_one(T(norm_inf(Ot) * norm_inf(Os) + norm_inf(Ots)));
  require_close("(2.7): dOmega_hat/ds - dXi_hat/dt = [Omega_hat, Xi_hat]", (dOmega_ds - dXi_dt).eval(),
                (Omega_hat * Xi_hat - Xi_hat * Omega_hat).eval(), scale, 64);
  const Vec3<T> Omega = s.vee(Omega_hat), Xi = s.vee(Xi_hat);
  require_close("(2.8) through the subject's vee: dOmega/ds - dXi/dt = Omega x Xi",
                (s.vee(dOmega_ds) - s.vee(dXi_dt)).eval(), truth::cross(Omega, Xi), scale, 64);
}

// ---------------------------------------------------------------------------------------------
// s2.euler-variational, Theorem 2.1: along the flow of the subject's (2.1), the first variation
// of S = int l(Omega) dt (the subject's (2.5)) under delta Omega = dXi/dt + Omega x Xi vanishes.
template <class T>
void euler_variational_principle(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const Vec3<T> Pi0 = dyn::draw_momentum<T>();
  const auto xi = draw_bump<T, 3>();
  const auto bump = draw_bump<T, 3>();
  const auto grid = var::gauss_grid<T>(kT<T>);
  flow::Gbs<T> g([&](const T&, const VecX<T>& W) { return VecX<T>(s.euler_2_1(I, Vec3<T>(W))); });
  const auto Ws = g.sample(VecX<T>(Pi0.cwiseQuotient(I)), T(0), grid.times);
  const long steps = g.stats().steps;
  auto integrand = [&](const Vec3<T>& W, const T& t) {
    const Vec3<T> dW = xi.rate(t) + truth::cross(W, xi.at(t));
    return T((s.lagrangian_2_5(I, (W + dW).eval()) - s.lagrangian_2_5(I, (W - dW).eval())) / T(2));
  };
  std::vector<T> f, fp;
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    const Vec3<T> W = Ws[i];
    f.push_back(integrand(W, t));
    fp.push_back(integrand((W + bump.at(t) / T(8)).eval(), t));
    big = std::max(big, T(norm_inf(W) * (norm_inf(xi.rate(t)) + norm_inf(W) * norm_inf(xi.at(t)))));
  }
  const T scale = kT<T> * I.maxCoeff() * dyn::at_least_one(big) *
                  dyn::growth(dyn::rigid_body_rate(I, Pi0), kT<T>, steps) * dyn::rigid_body_conditioning(I, Pi0, kT<T>);
  var::require_first_variation_vanishes<T>("Theorem 2.1, Euler's equations (2.1) and l (2.5)", grid, f, fp, scale, 64);
}

// The constrained variation delta xi = deta/dt + [xi, eta] of Theorem 1.1 (iii), with [xi, eta]
// the matrix commutator of the subject's hats read back by its vee.
template <class T>
VecX<T> constrained_variation(const Subject<T>& s, LieAlgebraId g, const VecX<T>& xi, const VecX<T>& eta,
                              const VecX<T>& deta_dt) {
  const MatX<T> X = s.lie_hat(g, xi), E = s.lie_hat(g, eta);
  return (deta_dt + s.lie_vee(g, (X * E - E * X).eval())).eval();
}

// (1 + lambda T)^2, the tolerance model's growth (support/dynamics.hpp) for two flows compared, the
// second counted with the steps the flow actually took.
template <class T>
T two_flow_growth(const T& lambda, long steps) {
  return dyn::growth(lambda, kT<T>) * dyn::growth(lambda, kT<T>, steps);
}

// ---------------------------------------------------------------------------------------------
// s1.ep-theorem, Theorem 1.1 (iii) <=> (iv), on so(3), so(4) and sl(2, R), for any Lagrangian: l
// from the family of support/general_lagrangian.hpp (linear, quadratic with K not diagonal, and
// quartic terms). Along the flow of the Euler-Poincare equation dmu/dt = ad*_xi mu, mu = dl/dxi
// (the subject's ad*), integrated in xi as
//   dxi/dt = (d2l/dxi2)^-1 ad*_xi dl/dxi,
// (with the closed forms of dl/dxi and d2l/dxi2), the first variation
//   delta int l dt = int dl(xi) . (deta/dt + [xi, eta]) dt
// vanishes for eta vanishing at the end points. dl(xi) . v is the exact derivative of l itself
// (hyper-dual), not the closed-form mu that drives the flow, so a flow that is not l's
// Euler-Poincare flow cannot pass.
// [xi, eta] is the matrix commutator read in the subject's coordinates.
//
// Along the flow the energy <mu, xi> - l = s / 2 + 3 c s^2 / 8 is conserved (the linear term
// cancels), so s = xi . K xi is constant and xi stays bounded on every algebra, sl(2, R) included.
template <class T>
void ep_first_variation_for(const Subject<T>& s, LieAlgebraId g) {
  const int d = truth::algebra_dimension(g);
  const GeneralLagrangian<T> l = draw_lagrangian<T>(d);
  const VecX<T> xi0 = dyn::pick<T>(gen::vec<T>(d, 32, 6), "xi0");
  const auto eta = draw_bump<T, Eigen::Dynamic>(d);
  const auto bump = draw_bump<T, Eigen::Dynamic>(d);
  // The rules start at 8 points: with the quartic term a 4-point rule can be pre-asymptotic, its
  // error smaller than the 8-point one's (seen on sl(2, R): 3.1e-6 at 4 points, 4.7e-6 at 8,
  // 7.6e-14 at 16), which the convergence check would take for divergence.
  std::vector<int> rules = var::default_rules<T>();
  rules.erase(rules.begin());
  const auto grid = var::gauss_grid<T>(kT<T>, rules);
  flow::Gbs<T> flow([&](const T&, const VecX<T>& xi) {
    return VecX<T>(l.hessian_closed_form(xi).ldlt().solve(s.ad_star(g, xi, l.gradient_closed_form(xi))));
  });
  const auto xis = flow.sample(xi0, T(0), grid.times);
  auto integrand = [&](const VecX<T>& xi, const T& t, const Bump<T, Eigen::Dynamic>& v) {
    return l.derivative(xi, constrained_variation(s, g, xi, v.at(t), v.rate(t)));
  };
  const auto variations = converse_variations(eta, d);
  std::vector<T> f;
  std::vector<std::vector<T>> fp(variations.size());
  T big(0), lam(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    const VecX<T>& xi = xis[i];
    f.push_back(integrand(xi, t, eta));
    for (std::size_t v = 0; v < variations.size(); ++v)
      fp[v].push_back(integrand((xi + bump.at(t) / T(8)).eval(), t, variations[v]));
    // The integrand's terms: dl ~ |mu| + |d2l| |xi| (an error in xi moves dl by |d2l| times it)
    // times |delta xi| <= |deta/dt| + 4 |xi| |eta|.
    const T dl = norm_inf(l.gradient_closed_form(xi)) + norm_inf(l.hessian_closed_form(xi)) * norm_inf(xi);
    big = std::max(big, T(dl * (norm_inf(eta.rate(t)) + T(4) * norm_inf(xi) * norm_inf(eta.at(t)))));
    lam = std::max(lam, T(T(4) * dl));
  }
  // No closed-form conditioning here: rates of at most ~4 |dl| (|(d2l)^-1|_inf <= sqrt(d) /
  // lambda_min(K) < 4 by the draw), and (1 + lambda T)^2 as for two flows compared.
  const T gr = two_flow_growth(dyn::at_least_one(lam), flow.stats().steps);
  var::require_first_variation_vanishes_iff<T>(std::string("Theorem 1.1 (iii) <=> (iv) on ") + lie_algebra_name(g) +
                                                   ", l = a . xi + s/2 + c s^2/8, s = xi . K xi",
                                               grid, f, fp, T(kT<T> * dyn::at_least_one(big) * gr), 64);
}

template <class T>
void ep_reduced_variation_vanishes(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2}) ep_first_variation_for(s, g);
}

// ---------------------------------------------------------------------------------------------
// The matrix forms (2.16) and (2.24) along the flow of the subject's (2.12) with (2.10).

template <class T>
struct HPFlow {
  Vec3<T> I;
  T lambda, kappa;
  long steps = 0;
  std::vector<Mat3<T>> Pi;  // Pi_hat(t)
  std::vector<Mat3<T>> O;
};

template <class T>
HPFlow<T> hp_flow(const Subject<T>& s, const std::vector<T>& times) {
  HPFlow<T> h;
  h.I = dyn::draw_inertia<T>();
  const Vec3<T> Pi0 = dyn::draw_momentum<T>();
  const Mat3<T> O0 = dyn::draw_rotation<T>();
  h.lambda = dyn::rigid_body_rate(h.I, Pi0);
  h.kappa = dyn::rigid_body_conditioning(h.I, Pi0, kT<T>);
  auto pack = [](const Mat3<T>& P, const Mat3<T>& O) {
    VecX<T> v(18);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) v(3 * i + j) = P(i, j), v(9 + 3 * i + j) = O(i, j);
    return v;
  };
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    Mat3<T> P, O;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P(i, j) = v(3 * i + j), O(i, j) = v(9 + 3 * i + j);
    return pack(s.euler_matrix_2_12(h.I, P), s.reconstruction_2_10(O, vee3(P).cwiseQuotient(h.I)));
  });
  const auto samples = g.sample(pack(truth::skew_of(Pi0), O0), T(0), times);
  h.steps = g.stats().steps;
  for (const auto& v : samples) {
    Mat3<T> P, O;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P(i, j) = v(3 * i + j), O(i, j) = v(9 + 3 * i + j);
    h.Pi.push_back(P);
    h.O.push_back(O);
  }
  return h;
}

// s2.hamilton-pontryagin, Proposition 2.3: S = int l(Omega_hat) + <Pi, O^-1 dO/dt - Omega_hat> dt
// is stationary along the subject's (2.20) for arbitrary delta Omega_hat, delta Pi and
// delta O = O Xi_hat with Xi vanishing at the ends, where delta(O^-1 dO/dt) is (2.17):
// dXi_hat/dt + [O^-1 dO/dt, Xi_hat]. dO/dt is the subject's (2.10); l its (2.13); <,> its (2.15).
template <class T>
void hamilton_pontryagin_variation(const Subject<T>& s) {
  const auto grid = var::gauss_grid<T>(kT<T>);
  const HPFlow<T> h = hp_flow(s, grid.times);
  const auto xi = draw_bump<T, 3>(), dW = draw_bump<T, 3>(), dP = draw_bump<T, 3>(), bump = draw_bump<T, 3>();
  auto pairing = [&](const Mat3<T>& a, const Mat3<T>& b) { return s.pairing(MatX<T>(a), MatX<T>(b)); };
  auto integrand = [&](const Mat3<T>& P, const Mat3<T>& O, const T& t) {
    const Vec3<T> W = vee3(P).cwiseQuotient(h.I);
    const Mat3<T> W_hat = truth::skew_of(W);
    const Mat3<T> body = O.transpose() * s.reconstruction_2_10(O, W);  // O^-1 dO/dt
    const Mat3<T> dW_hat = truth::skew_of(Vec3<T>(dW.at(t) + dW.c0));  // arbitrary, non-zero at the ends
    const Mat3<T> dP_hat = truth::skew_of(Vec3<T>(dP.at(t) + dP.c1));
    const Mat3<T> X = truth::skew_of(xi.at(t)), dX = truth::skew_of(xi.rate(t));
    const T dl =
        (s.lagrangian_2_13(h.I, (W_hat + dW_hat).eval()) - s.lagrangian_2_13(h.I, (W_hat - dW_hat).eval())) / T(2);
    return T(dl - pairing(P, dW_hat) + pairing(dP_hat, (body - W_hat).eval()) +
             pairing(P, (dX + body * X - X * body).eval()));
  };
  std::vector<T> f, fp;
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    f.push_back(integrand(h.Pi[i], h.O[i], t));
    fp.push_back(integrand((h.Pi[i] + truth::skew_of(Vec3<T>(bump.at(t) / T(8)))).eval(), h.O[i], t));
    big = std::max(
        big, T(norm_inf(h.Pi[i]) * (T(1) + norm_inf(h.Pi[i])) * (T(1) + norm_inf(xi.rate(t)) + norm_inf(xi.at(t)))));
  }
  const T gr = dyn::growth(h.lambda, kT<T>, h.steps);
  var::require_first_variation_vanishes<T>("Proposition 2.3, the Hamilton-Pontryagin action (2.16)", grid, f, fp,
                                           T(kT<T> * h.I.maxCoeff() * dyn::at_least_one(big) * gr * gr * h.kappa), 64);
}

// s2.hp-hamiltonian-action, exercise (2.24): S = int <Pi, O^-1 dO/dt> - h(Pi) dt is stationary
// along the subject's (2.20) for delta Pi arbitrary and delta O = O Xi_hat (ends fixed); h is the
// subject's (2.21).
template <class T>
void hp_hamiltonian_action_variation(const Subject<T>& s) {
  const auto grid = var::gauss_grid<T>(kT<T>);
  const HPFlow<T> h = hp_flow(s, grid.times);
  const auto xi = draw_bump<T, 3>(), dP = draw_bump<T, 3>(), bump = draw_bump<T, 3>();
  auto pairing = [&](const Mat3<T>& a, const Mat3<T>& b) { return s.pairing(MatX<T>(a), MatX<T>(b)); };
  auto integrand = [&](const Mat3<T>& P, const Mat3<T>& O, const T& t) {
    const Vec3<T> W = vee3(P).cwiseQuotient(h.I);
    const Mat3<T> body = O.transpose() * s.reconstruction_2_10(O, W);
    const Mat3<T> dP_hat = truth::skew_of(Vec3<T>(dP.at(t) + dP.c1));
    const Mat3<T> X = truth::skew_of(xi.at(t)), dX = truth::skew_of(xi.rate(t));
    const T dh = (s.hamiltonian_2_21(h.I, (P + dP_hat).eval()) - s.hamiltonian_2_21(h.I, (P - dP_hat).eval())) / T(2);
    return T(pairing(dP_hat, body) - dh + pairing(P, (dX + body * X - X * body).eval()));
  };
  std::vector<T> f, fp;
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    f.push_back(integrand(h.Pi[i], h.O[i], t));
    fp.push_back(integrand((h.Pi[i] + truth::skew_of(Vec3<T>(bump.at(t) / T(8)))).eval(), h.O[i], t));
    big = std::max(
        big, T(norm_inf(h.Pi[i]) * (T(1) + norm_inf(h.Pi[i])) * (T(1) + norm_inf(xi.rate(t)) + norm_inf(xi.at(t)))));
  }
  const T gr = dyn::growth(h.lambda, kT<T>, h.steps);
  var::require_first_variation_vanishes<T>("exercise (2.24), the action <Pi, O^-1 dO/dt> - h(Pi)", grid, f, fp,
                                           T(kT<T> * dyn::at_least_one(big) * gr * gr * h.kappa), 64);
}

// ---------------------------------------------------------------------------------------------
// s3.clebsch-variational, Proposition 3.1: S = int (1/2) Omega . I Omega + P . (dQ/dt + Omega x Q) dt
// is stationary along the subject's (3.21) (with Omega = I^-1 (P x Q), the stationarity in Omega)
// for arbitrary delta Omega, delta P and delta Q vanishing at the ends. l is the subject's (2.5).
template <class T>
void clebsch_variational_principle(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const Vec3<T> Q0 = dyn::draw_momentum<T>(), P0 = dyn::draw_momentum<T>();
  const auto dW = draw_bump<T, 3>(), dP = draw_bump<T, 3>(), dQ = draw_bump<T, 3>(), bump = draw_bump<T, 3>();
  const auto grid = var::gauss_grid<T>(kT<T>);
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    const auto d = s.clebsch_3_21(I, Vec3<T>(v.head(3)), Vec3<T>(v.tail(3)));
    VecX<T> out(6);
    out << d.first, d.second;
    return out;
  });
  VecX<T> x0(6);
  x0 << Q0, P0;
  const auto xs = g.sample(x0, T(0), grid.times);
  const long steps = g.stats().steps;
  auto integrand = [&](const Vec3<T>& Q, const Vec3<T>& P, const T& t) {
    const Vec3<T> W = truth::cross(P, Q).cwiseQuotient(I);
    const Vec3<T> Qdot = s.clebsch_3_21(I, Q, P).first;
    const Vec3<T> dw = dW.at(t) + dW.c0, dp = dP.at(t) + dP.c1, dq = dQ.at(t), dq_rate = dQ.rate(t);
    const T dl = (s.lagrangian_2_5(I, (W + dw).eval()) - s.lagrangian_2_5(I, (W - dw).eval())) / T(2);
    return T(dl + P.dot(truth::cross(dw, Q)) + dp.dot(Qdot + truth::cross(W, Q)) +
             P.dot(dq_rate + truth::cross(W, dq)));
  };
  std::vector<T> f, fp;
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    const Vec3<T> Q = xs[i].head(3), P = xs[i].tail(3);
    f.push_back(integrand(Q, P, t));
    fp.push_back(integrand(Q, (P + bump.at(t) / T(8)).eval(), t));
    big = std::max(big, T((T(1) + norm_inf(P)) * (T(1) + norm_inf(Q)) * (T(1) + norm_inf(P) * norm_inf(Q)) * T(4)));
  }
  const Vec3<T> Pi0 = truth::cross(P0, Q0);
  const T gr = dyn::growth(dyn::rigid_body_rate(I, Pi0), kT<T>, steps);
  var::require_first_variation_vanishes<T>(
      "Proposition 3.1, the Clebsch action (3.18)", grid, f, fp,
      T(kT<T> * I.maxCoeff() * dyn::at_least_one(big) * gr * gr * dyn::rigid_body_conditioning(I, Pi0, kT<T>)), 64);
}

// The skew n x n matrix with upper triangle v (row by row): the suite's own so(n) coordinates, used
// only to build variations, never to read the subject's.
template <class T>
MatX<T> skew_n(const VecX<T>& v, int n) {
  MatX<T> X = MatX<T>::Zero(n, n);
  int k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) X(i, j) = v(k), X(j, i) = -v(k), ++k;
  return X;
}

// ---------------------------------------------------------------------------------------------
// s2.manakov, Proposition 2.4: along the subject's (2.34), the first variation of
// S = int l(Omega) dt with the subject's l = -tr(Omega A Omega)/2 and Omega = its manakov_Omega(A, M),
// under delta Omega = dXi/dt + [Omega, Xi] (Xi skew, vanishing at the ends), vanishes. n = 3..5.
template <class T>
void manakov_variational_principle(const Subject<T>& s) {
  const int n = dyn::pick<T>(rc::gen::inRange(3, 6), "n");
  const auto a = dyn::draw_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  const MatX<T> M0 = dyn::draw_skew<T>(n, 32);
  const int m = n * (n - 1) / 2;
  const auto xi = draw_bump<T, Eigen::Dynamic>(m), bump = draw_bump<T, Eigen::Dynamic>(m);
  auto skew = [n](const VecX<T>& v) { return skew_n(v, n); };
  const auto grid = var::gauss_grid<T>(kT<T>);
  long steps = 0;
  const auto Ms = dyn::subject_manakov_M(s, A, M0, grid.times, &steps);
  auto integrand = [&](const MatX<T>& M, const T& t, const Bump<T, Eigen::Dynamic>& v) {
    const MatX<T> W = s.manakov_Omega(A, M);
    const MatX<T> X = skew(v.at(t)), dX = skew(v.rate(t));
    const MatX<T> dW = dX + W * X - X * W;
    return T((s.manakov_lagrangian(A, (W + dW).eval()) - s.manakov_lagrangian(A, (W - dW).eval())) / T(2));
  };
  const auto variations = converse_variations(xi, m);
  std::vector<T> f;
  std::vector<std::vector<T>> fp(variations.size());
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    f.push_back(integrand(Ms[i], t, xi));
    for (std::size_t v = 0; v < variations.size(); ++v)
      fp[v].push_back(integrand((Ms[i] + skew(bump.at(t)) / T(8)).eval(), t, variations[v]));
    big = std::max(big, T(norm_inf(Ms[i]) * (norm_inf(xi.rate(t)) + T(2) * norm_inf(Ms[i]) * norm_inf(xi.at(t)))));
  }
  const T gr = dyn::growth(dyn::manakov_rate(a, M0), kT<T>, steps);
  var::require_first_variation_vanishes_iff<T>("Proposition 2.4, Manakov's l = -tr(Omega A Omega)/2", grid, f, fp,
                                               T(kT<T> * T(n * n) * dyn::at_least_one(big) * gr * gr), 64);
}

// ---------------------------------------------------------------------------------------------
// s2.hamilton-pontryagin on SO(n), n = 3..6 (3, 4 in 50 digits): Proposition 2.3 for Manakov's body,
// l(Omega) = -tr(Omega A Omega)/2 (Proposition 2.4) with A = R D R^T not diagonal in three of the
// four regimes of gen::manakov_body (one of them scaled by 2^s, |s| <= 20). The action (2.16),
//     S = int l(Omega) + <M, O^-1 dO/dt - Omega> dt,
// varied by an arbitrary delta Omega (not zero at the ends), an arbitrary delta M and
// delta O = O Xi (Xi skew, vanishing at the ends; delta(O^-1 dO/dt) = dXi/dt + [O^-1 dO/dt, Xi] as
// in (2.17)), along the subject's (2.34) with O^-1 dO/dt = Omega, has the integrand
//     dl/dOmega . delta Omega - <M, delta Omega>        (the Legendre relation: its l, its Omega(M)
//                                                        and its pairing must agree)
//   + <delta M, O^-1 dO/dt - Omega>                     (zero: see below)
//   + <M, dXi/dt + [Omega, Xi]>                          (its (2.34), by parts).
// Omega is the subject's manakov_Omega(A, M), l its manakov_lagrangian, <,> its pairing (2.15).
// The subject has no reconstruction slot on SO(n) (on SO(3), hamilton_pontryagin_variation takes
// dO/dt from its (2.10)), so O would be integrated here with its Omega and the constraint term
// would vanish by construction: it is left out, and with it the attitude. Both directions: a
// perturbed M is not stationary for some Xi (require_first_variation_vanishes_iff).
// Sizes. M(0) is a drawn skew matrix times min d, so that Omega, and with it the speed of the
// motion on [0, T], stay of the drawn size while A and M take the regime's scale 2^s (a fixed T
// and A scaled alone would ask for 2^20 turns). delta Omega is a bump, M's perturbation a bump
// times min d / 8.
// Tolerance, T n^2 spread (legendre + motion (1 + lambda T)^2), k = 64, with |Omega| <= |M|_F / (2 min d)
// (Frobenius norm: A = R D R^T's rotation does not keep the largest entry, it keeps |.|_F):
//   - legendre = |A| (|Omega| + |delta Omega|)^2 + |M| |delta Omega|, the size of the two l values
//     and of <M, delta Omega>; the relation holds at every M, so the flow's error does not enter;
//   - motion = |M| (|dXi/dt| + 2 n |Omega| |Xi|), the size of the (2.34) term, whose error is the
//     flow's, grown as (1 + lambda T)^2 (two flows compared, as for Proposition 2.4);
//   - spread = max d / min d conditions the subject's solve for Omega; n^2-term sums.
template <class T>
void hamilton_pontryagin_variation_so_n(const Subject<T>& s) {
  // n = 3..6 in double; 3, 4 in 50 digits. A student's Omega(M) typically solves the n^2 x n^2
  // system afresh at every call (examples/students/correct.hpp): at n = 6 in 50 digits that made
  // one check of a correct implementation exceed the 60 s a check may take. Dimension-specific
  // mistakes show in double; what 50 digits add (precision lost to double) shows at any n.
  const int n = dyn::pick<T>(rc::gen::inRange(3, std::is_same_v<T, double> ? 7 : 5), "n");
  const auto b = dyn::pick<T>(gen::manakov_body<T>(n), "body");
  const T d_min = b.d.minCoeff();
  const MatX<T> M0 = (dyn::draw_skew<T>(n, 32) * d_min).eval();
  const int m = n * (n - 1) / 2;
  const auto xi = draw_bump<T, Eigen::Dynamic>(m), dW = draw_bump<T, Eigen::Dynamic>(m),
             bump = draw_bump<T, Eigen::Dynamic>(m);
  const auto grid = var::gauss_grid<T>(kT<T>);
  long steps = 0;
  const auto Ms = dyn::subject_manakov_M(s, b.A, M0, grid.times, &steps);
  auto delta_Omega = [&](const T& t) { return skew_n<T>((dW.at(t) + dW.c0).eval(), n); };
  // The integrand at (M, W = Omega(M)) for the variation Xi = v: the delta Omega term depends on
  // the curve only, so along the perturbed curve it is computed once for all the variations.
  auto legendre_term = [&](const MatX<T>& M, const MatX<T>& W, const T& t) {
    const MatX<T> dOm = delta_Omega(t);
    const T dl = (s.manakov_lagrangian(b.A, (W + dOm).eval()) - s.manakov_lagrangian(b.A, (W - dOm).eval())) / T(2);
    return T(dl - s.pairing(M, dOm));
  };
  auto motion_term = [&](const MatX<T>& M, const MatX<T>& W, const T& t, const Bump<T, Eigen::Dynamic>& v) {
    const MatX<T> X = skew_n<T>(v.at(t), n), dX = skew_n<T>(v.rate(t), n);
    return T(s.pairing(M, (dX + W * X - X * W).eval()));
  };
  const auto variations = converse_variations(xi, m);
  std::vector<T> f;
  std::vector<std::vector<T>> fp(variations.size());
  T legendre(0), motion(0);
  const T A_size = norm_inf(b.A);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    const MatX<T> W = s.manakov_Omega(b.A, Ms[i]);
    f.push_back(T(legendre_term(Ms[i], W, t) + motion_term(Ms[i], W, t, xi)));
    const MatX<T> Mp = (Ms[i] + skew_n<T>(bump.at(t), n) * (d_min / T(8))).eval(), Wp = s.manakov_Omega(b.A, Mp);
    const T Lp = legendre_term(Mp, Wp, t);
    for (std::size_t v = 0; v < variations.size(); ++v) fp[v].push_back(T(Lp + motion_term(Mp, Wp, t, variations[v])));
    const T M_size = norm_inf(Ms[i]), W_size = T(sqrt(T(Ms[i].squaredNorm())) / (T(2) * d_min)),
            dOm_size = norm_inf(delta_Omega(t));
    legendre = std::max(legendre, T(A_size * (W_size + dOm_size) * (W_size + dOm_size) + M_size * dOm_size));
    motion = std::max(motion, T(M_size * (norm_inf(xi.rate(t)) + T(2 * n) * W_size * norm_inf(xi.at(t)))));
  }
  const T gr = dyn::growth(T(sqrt(T(M0.squaredNorm())) / (T(2) * d_min)), kT<T>, steps);
  var::require_first_variation_vanishes_iff<T>(
      "Proposition 2.3 on SO(n), the Hamilton-Pontryagin action (2.16) for "
      "Manakov's l = -tr(Omega A Omega)/2",
      grid, f, fp, T(kT<T> * T(n * n) * b.spread * (legendre + motion * gr * gr)), 64);
}

// cay(S(t)) = (Id - S)^-1 (Id + S) and its time derivative (Id - S)^-1 dS/dt (cay(S) + Id).
template <class T>
std::pair<MatX<T>, MatX<T>> cayley_and_rate(const MatX<T>& S, const MatX<T>& dS) {
  const MatX<T> Id = MatX<T>::Identity(S.rows(), S.cols());
  const MatX<T> inv = (Id - S).partialPivLu().inverse();
  const MatX<T> C = inv * (Id + S);
  return {C, (inv * dS * (C + Id)).eval()};
}

// ---------------------------------------------------------------------------------------------
// s1.reconstruction (section 1): reconstructing g(t) from the solution of the reduced (left-
// invariant) Euler-Poincare equation by dg/dt = g xi gives a solution of the Euler-Lagrange
// equations on G. Checked on SO(3) with the *unreduced* Hamilton's principle (Theorem 1.1 (i)):
// for g_e(t) = g(t) cay(e eta_hat(t)), eta vanishing at the ends,
//   d/de int L(g_e, dg_e/dt) dt = 0 at e = 0,   L(g, dg/dt) = l(vee(g^-1 dg/dt)),
// with the subject's (3.8) and (2.10) for the flow and dg/dt, and its (2.5) for l. d/de is the
// order-8 central difference of support/derivatives.hpp (round-off roundoff_factor8 eps |S|).
// The perturbed curve is g(t) cay(beta_hat(t)) with beta a bump (a genuine curve, not a solution).
template <class T>
void reconstruction_solves_euler_lagrange(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_momentum<T>(), dyn::draw_rotation<T>()};
  const auto eta = draw_bump<T, 3>(), beta = draw_bump<T, 3>();
  const auto grid = var::gauss_grid<T>(kT<T>);
  long steps = 0;
  const auto xs = dyn::subject_rigid_body(s, I, x0, grid.times, &steps);
  // L along g_e = g_base cay(e eta_hat / 16) at one time; g = O, dg/dt the subject's (2.10). eta is
  // kept small (|eta| <= 1/10) so that e -> cay(e eta_hat) is far from its poles and the order-8
  // difference's truncation error (~ (d |eta|)^8) is far below its round-off.
  auto lagrangian = [&](const RigidBodyState<T>& x, const T& t, const T& e, bool perturbed) {
    MatX<T> g = x.O, dg = s.reconstruction_2_10(x.O, x.Pi.cwiseQuotient(I));
    if (perturbed) {
      const auto [B, dB] = cayley_and_rate<T>(MatX<T>(truth::skew_of(Vec3<T>(beta.at(t) / T(8)))),
                                              MatX<T>(truth::skew_of(Vec3<T>(beta.rate(t) / T(8)))));
      dg = (dg * B + g * dB).eval();
      g = (g * B).eval();
    }
    const auto [C, dC] = cayley_and_rate<T>(MatX<T>(truth::skew_of(Vec3<T>(e / T(16) * eta.at(t)))),
                                            MatX<T>(truth::skew_of(Vec3<T>(e / T(16) * eta.rate(t)))));
    const Mat3<T> ge = g * C, dge = dg * C + g * dC;
    return s.lagrangian_2_5(I, vee3(Mat3<T>(ge.transpose() * dge)));
  };
  auto first_variation = [&](bool perturbed) {
    std::vector<T> f;
    for (std::size_t i = 0; i < grid.times.size(); ++i) {
      const T t = grid.times[i];
      f.push_back(
          deriv::central8<T>([&](const T& e) { return lagrangian(xs[i], t, e, perturbed); }, deriv::step8<T>()));
    }
    return f;
  };
  T big(0);
  for (const auto& x : xs) big = std::max(big, dyn::energy(I, x.Pi));
  const T gr = dyn::growth(dyn::rigid_body_rate(I, x0.Pi), kT<T>, steps);
  const T scale = kT<T> * dyn::at_least_one(big) * I.maxCoeff() * deriv::roundoff_factor8<T>() * gr * gr *
                  dyn::rigid_body_conditioning(I, x0.Pi, kT<T>);
  var::require_first_variation_vanishes<T>(
      "section 1: g(t) reconstructed by dg/dt = g xi solves Hamilton's principle on G", grid, first_variation(false),
      first_variation(true), scale, 64);
}

// ---------------------------------------------------------------------------------------------
// s1.right-invariant-sign, Remark 1.1: for a right-invariant Lagrangian L(g, dg/dt) = l(xi),
// xi = dg/dt g^-1, the Euler-Poincare equation has the opposite sign, dmu/dt = -ad*_xi mu, and
// dg/dt = xi g reconstructs a solution of the Euler-Lagrange equations. Checked on SO(3) and
// SL(2, R) (l = xi . K xi / 2 in the subject's coordinates, its ad*) by the unreduced Hamilton's
// principle for right variations g_e = cay(e eta_hat) g (Cayley maps so(3) into SO(3) and sl(2)
// into SL(2)), as for s1.reconstruction. With the left sign +ad* the principle fails (noted).
template <class T>
void right_invariant_for(const Subject<T>& s, LieAlgebraId g) {
  const int m = g == LieAlgebraId::sl2 ? 2 : 3;
  const VecX<T> xi0 = dyn::pick<T>(gen::vec<T>(3, 32, 6), "xi0");
  VecX<T> K(3);
  for (int k = 0; k < 3; ++k) K(k) = dyn::pick<T>(dyn::quarter<T>(2, 8), "K_k");
  const auto eta = draw_bump<T, 3>(), bump = draw_bump<T, 3>();
  const auto grid = var::gauss_grid<T>(kT<T>);
  const MatX<T> g0 = MatX<T>::Identity(m, m);
  long steps = 0;
  auto solve = [&](T sign) {
    flow::Gbs<T> flow([&](const T&, const VecX<T>& v) {
      const VecX<T> mu = v.head(3);
      const VecX<T> x = mu.cwiseQuotient(K);
      MatX<T> G(m, m);
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) G(i, j) = v(3 + m * i + j);
      const MatX<T> dG = s.lie_hat(g, x) * G;
      VecX<T> d(3 + m * m);
      d.head(3) = sign * s.ad_star(g, x, mu);
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) d(3 + m * i + j) = dG(i, j);
      return d;
    });
    VecX<T> v0(3 + m * m);
    v0.head(3) = K.cwiseProduct(xi0);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) v0(3 + m * i + j) = g0(i, j);
    auto out = flow.sample(v0, T(0), grid.times);
    steps = flow.stats().steps;
    return out;
  };
  // L(g_e, dg_e/dt) with g_e = cay(e eta_hat / 16) g_base, g_base = g (dg/dt = xi_hat g, xi from
  // the state's mu) or, for the perturbed curve, cay(beta_hat(t) / 8) g.
  auto lagrangian = [&](const VecX<T>& v, const T& t, const T& e, bool perturbed) {
    const VecX<T> mu = v.head(3);
    MatX<T> G(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) G(i, j) = v(3 + m * i + j);
    MatX<T> dG = s.lie_hat(g, mu.cwiseQuotient(K)) * G;
    if (perturbed) {
      const auto [B, dB] =
          cayley_and_rate<T>((s.lie_hat(g, bump.at(t)) / T(8)).eval(), (s.lie_hat(g, bump.rate(t)) / T(8)).eval());
      dG = (dB * G + B * dG).eval();
      G = (B * G).eval();
    }
    const auto [C, dC] = cayley_and_rate<T>((e / T(16) * s.lie_hat(g, eta.at(t))).eval(),
                                            (e / T(16) * s.lie_hat(g, eta.rate(t))).eval());
    const MatX<T> Ge = C * G, dGe = dC * G + C * dG;
    const VecX<T> x = s.lie_vee(g, (dGe * Ge.inverse()).eval());
    return T(x.dot(K.cwiseProduct(x)) / T(2));
  };
  auto first_variation = [&](const std::vector<VecX<T>>& vs, bool perturbed) {
    std::vector<T> f;
    for (std::size_t i = 0; i < grid.times.size(); ++i) {
      const T t = grid.times[i];
      f.push_back(
          deriv::central8<T>([&](const T& e) { return lagrangian(vs[i], t, e, perturbed); }, deriv::step8<T>()));
    }
    return f;
  };
  const auto right = solve(T(-1));
  T big(0);
  for (const auto& v : right) big = std::max(big, T(norm_inf(v) * norm_inf(v)));
  const T lam = T(4) * dyn::at_least_one(norm_inf(right[0]));
  const T gr = two_flow_growth(lam, steps);
  const T scale = kT<T> * dyn::at_least_one(big) * deriv::roundoff_factor8<T>() * gr;
  var::require_first_variation_vanishes<T>(
      std::string("Remark 1.1 on ") + lie_algebra_name(g) + ": dmu/dt = -ad*_xi mu with dg/dt = xi g", grid,
      first_variation(right, false), first_variation(right, true), scale, 64);
  const auto left = solve(T(1));
  const auto fl = first_variation(left, false);
  const T with_left_sign = var::integrate(grid, grid.rules.size() - 1, fl);
  record_note(std::string("on ") + lie_algebra_name(g) + ", with the left-invariant sign +ad* instead, delta S = " +
              to_string_full(with_left_sign) + " (not stationary)");
}

template <class T>
void right_invariant_ep_sign(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::sl2}) right_invariant_for(s, g);
}

// ---------------------------------------------------------------------------------------------
// s1.ep-product-space, the exercise on G x Y: for L on T(G x Y) invariant under
// (g, (h, y)) -> (gh, y), the reduced l(xi, y, dy/dt) obeys d/dt dl/dxi = ad*_xi dl/dxi and
// d/dt dl/d(dy/dt) = dl/dy, and these are the stationarity conditions of int l dt under
// delta xi = deta/dt + [xi, eta], delta y = zeta (eta, zeta vanishing at the ends).
// The notes give no system on G x Y, so the check takes one coupling the group and the shape in
// both ways the statement allows: G = SO(3), SO(4) or SL(2, R) (in the subject's coordinates, with
// its ad*, hat and vee), Y = R^2 and
//   l = xi . K xi / 2 + |dy/dt|^2 / 2 + dy/dt . B xi + (a . y)(c . xi) - |y|^2 / 2,
// a gyroscopic coupling B and a shape-dependent momentum (a . y) c (|B_ij|, |a_i|, |c_j| <= 1/8, so
// the Legendre map is invertible). The Legendre map is affine with a constant matrix, so the
// reduced equations for (mu, y, p), mu = dl/dxi, p = dl/d(dy/dt), stay quadratic like the other
// Euler-Poincare flows here (a y-dependent inertia would make them rational, with complex
// singularities close enough to the time axis to slow the Gauss quadratures down).
template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

template <class T>
struct ProductSpaceBody {
  VecX<T> K;  // diagonal of K (in the subject's coordinates of the algebra)
  MatX<T> B;  // 2 x d
  Vec2<T> a;
  VecX<T> c;
  // The Legendre map (xi, dy/dt) -> (mu, p) = A (xi, dy/dt) + ((a . y) c, 0), A = [K, B^T; B, Id]:
  // A is constant, so it is factored once, not at every evaluation of the vector field.
  Eigen::PartialPivLU<MatX<T>> legendre;

  ProductSpaceBody(VecX<T> K_, MatX<T> B_, Vec2<T> a_, VecX<T> c_)
      : K(std::move(K_)), B(std::move(B_)), a(std::move(a_)), c(std::move(c_)) {
    const int d = static_cast<int>(K.size());
    MatX<T> A = MatX<T>::Zero(d + 2, d + 2);
    A.topLeftCorner(d, d) = K.asDiagonal();
    A.topRightCorner(d, 2) = B.transpose();
    A.bottomLeftCorner(2, d) = B;
    A.bottomRightCorner(2, 2) = MatX<T>::Identity(2, 2);
    legendre.compute(A);
  }
  // (xi, dy/dt) from (mu, y, p).
  std::pair<VecX<T>, Vec2<T>> velocities(const VecX<T>& mu, const Vec2<T>& y, const Vec2<T>& p) const {
    const int d = static_cast<int>(K.size());
    VecX<T> rhs(d + 2);
    rhs << (mu - a.dot(y) * c), p;
    const VecX<T> x = legendre.solve(rhs);
    return {x.head(d), Vec2<T>(x.tail(2))};
  }
  VecX<T> dl_dxi(const VecX<T>& xi, const Vec2<T>& y, const Vec2<T>& v) const {
    return (K.cwiseProduct(xi) + B.transpose() * v + a.dot(y) * c).eval();
  }
  Vec2<T> dl_dv(const VecX<T>& xi, const Vec2<T>&, const Vec2<T>& v) const { return (v + B * xi).eval(); }
  Vec2<T> dl_dy(const VecX<T>& xi, const Vec2<T>& y, const Vec2<T>&) const { return (c.dot(xi) * a - y).eval(); }
};

template <class T>
void ep_product_space_for(const Subject<T>& s, LieAlgebraId g) {
  const int d = g == LieAlgebraId::so4 ? 6 : 3;
  VecX<T> K(d);
  for (int k = 0; k < d; ++k) K(k) = dyn::pick<T>(dyn::quarter<T>(2, 8), "K_k");
  const auto eighth = [] {  // -1/8, 0 or 1/8
    return T(dyn::pick<T>(dyn::quarter<T>(-1, 1), "2 B_ij or 2 c_j (an entry -1/8, 0 or 1/8)") / T(2));
  };
  MatX<T> B(2, d);
  VecX<T> c(d);
  for (int j = 0; j < d; ++j) {
    B(0, j) = eighth();
    B(1, j) = eighth();
    c(j) = eighth();
  }
  Vec2<T> a(eighth(), eighth());
  const ProductSpaceBody<T> body(std::move(K), std::move(B), std::move(a), std::move(c));
  const VecX<T> mu0 = dyn::pick<T>(gen::vec<T>(d, 32, 6), "mu0");
  const Vec2<T> y0 = dyn::pick<T>(gen::vec<T>(2, 32, 6), "y0"), p0 = dyn::pick<T>(gen::vec<T>(2, 32, 6), "p0");
  const auto eta = draw_bump<T, Eigen::Dynamic>(d);
  const auto zeta = draw_bump<T, 2>();
  const auto bump = draw_bump<T, Eigen::Dynamic>(d);
  const auto grid = var::gauss_grid<T>(kT<T>);
  // State (mu, y, p): dmu/dt = ad*_xi mu, dy/dt = v, dp/dt = dl/dy.
  flow::Gbs<T> flow([&](const T&, const VecX<T>& w) {
    const VecX<T> mu = w.head(d);
    const Vec2<T> y = w.segment(d, 2), p = w.tail(2);
    const auto [xi, v] = body.velocities(mu, y, p);
    VecX<T> dw(d + 4);
    dw << s.ad_star(g, xi, mu), v, body.dl_dy(xi, y, v);
    return dw;
  });
  VecX<T> w0(d + 4);
  w0 << mu0, y0, p0;
  const auto ws = flow.sample(w0, T(0), grid.times);
  // delta l = dl/dxi . (deta/dt + [xi, eta]) + dl/dy . zeta + dl/d(dy/dt) . dzeta/dt.
  auto integrand = [&](const VecX<T>& w, const T& t) {
    const Vec2<T> y = w.segment(d, 2);
    const auto [xi, v] = body.velocities(w.head(d), y, w.tail(2));
    const VecX<T> dxi = constrained_variation(s, g, xi, eta.at(t), eta.rate(t));
    return T(body.dl_dxi(xi, y, v).dot(dxi) + body.dl_dy(xi, y, v).dot(zeta.at(t)) +
             body.dl_dv(xi, y, v).dot(zeta.rate(t)));
  };
  std::vector<T> f, fp;
  T big(0);
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const T t = grid.times[i];
    VecX<T> perturbed = ws[i];
    perturbed.head(d) += bump.at(t) / T(8);
    f.push_back(integrand(ws[i], t));
    fp.push_back(integrand(perturbed, t));
    const T n = dyn::at_least_one(norm_inf(ws[i]));
    big = std::max(big, T(n * (norm_inf(eta.rate(t)) + T(4) * n * norm_inf(eta.at(t)) + norm_inf(zeta.at(t)) +
                               norm_inf(zeta.rate(t)))));
  }
  // As for Theorem 1.1 (iii): rates of at most ~4 |state| here, (1 + lambda T)^2 for two flows.
  const T lam = T(4) * dyn::at_least_one(norm_inf(ws[0]));
  const T gr = two_flow_growth(lam, flow.stats().steps);
  var::require_first_variation_vanishes<T>(
      std::string("the G x Y exercise with G = ") + lie_algebra_name(g) + ", Y = R^2", grid, f, fp, T(kT<T> * big * gr),
      64);
}

template <class T>
void ep_product_space_variation(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2}) ep_product_space_for(s, g);
}

}  // namespace

GM_PROPERTY(restricted_variation_2_8, all_scalars,
            {.spec = "s2.restricted-variation",
             .title = "Proposition 2.1: for O(t, s) in SO(3), dOmega/ds - dXi/dt = Omega x Xi (2.8), "
                      "exact derivatives",
             .tolerance = ToleranceClass::Exact,
             .needs = {"vee"},
             .negative_controls = {"vee_reads_upper_triangle"},
             .cases = {.d = 100, .mp = 25, .q = 10}});

GM_PROPERTY(
    euler_variational_principle, float_scalars,
    {.spec = "s2.euler-variational",
     .title = "Theorem 2.1: along the subject's (2.1), delta int l dt = 0 for delta Omega = dXi/dt + Omega x Xi",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"euler_2_1", "lagrangian_2_5"},
     .negative_controls = {"euler_2_1_sign_error", "euler_2_1_missing_division"},
     .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(ep_reduced_variation_vanishes, float_scalars,
            {.spec = "s1.ep-theorem",
             .title = "Theorem 1.1 (iii)<=>(iv) on so(3), so(4), sl(2,R), l neither quadratic nor diagonal: along the "
                      "subject's EP flow, delta int l dt = 0 for delta xi = deta/dt + [xi, eta], and a perturbed curve "
                      "is not stationary",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"ad_star", "lie_hat", "lie_vee"},
             .negative_controls = {"ad_star_sign_flipped", "ad_star_sl2_transpose_pairing"},
             .cases = {.d = 10, .mp = 4, .q = 0}});

GM_PROPERTY(hamilton_pontryagin_variation, float_scalars,
            {.spec = "s2.hamilton-pontryagin",
             .title = "Proposition 2.3: the Hamilton-Pontryagin action (2.16) is stationary along the subject's (2.20)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"euler_matrix_2_12", "reconstruction_2_10", "lagrangian_2_13", "pairing"},
             .negative_controls = {"euler_matrix_commutator_sign", "reconstruction_right_multiplied"},
             .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(hamilton_pontryagin_variation_so_n, float_scalars,
            {.spec = "s2.hamilton-pontryagin",
             .title = "Proposition 2.3 on SO(n), n = 3..6, both directions: the Hamilton-Pontryagin action (2.16) with "
                      "Manakov's l and a non-diagonal A is stationary along the subject's (2.34), a perturbed M is not",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"manakov_2_34", "manakov_Omega", "manakov_lagrangian", "pairing"},
             .negative_controls = {"manakov_2_34_diagonal_A_only", "manakov_Omega_diagonal_A_only",
                                   "manakov_lagrangian_sign_flipped", "pairing_without_half"},
             .cases = {.d = 10, .mp = 5, .q = 0}});

GM_PROPERTY(hp_hamiltonian_action_variation, float_scalars,
            {.spec = "s2.hp-hamiltonian-action",
             .title = "exercise (2.24): int <Pi, O^-1 dO/dt> - h(Pi) dt is stationary along the subject's (2.20)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"euler_matrix_2_12", "reconstruction_2_10", "hamiltonian_2_21", "pairing"},
             .negative_controls = {"hamiltonian_2_21_sign_flipped", "euler_matrix_commutator_sign"},
             .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(clebsch_variational_principle, float_scalars,
            {.spec = "s3.clebsch-variational",
             .title = "Proposition 3.1: the Clebsch action (3.18) is stationary along the subject's (3.21)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"clebsch_3_21", "lagrangian_2_5"},
             .negative_controls = {"clebsch_3_21_Q_sign"},
             .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(
    manakov_variational_principle, float_scalars,
    {.spec = "s2.manakov",
     .title = "Proposition 2.4, both directions: along the subject's (2.34), delta int -tr(Omega A Omega)/2 dt = 0 "
              "for delta Omega = dXi/dt + [Omega, Xi], and a perturbed curve is not stationary",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"manakov_2_34", "manakov_Omega", "manakov_lagrangian"},
     .negative_controls = {"manakov_commutator_reversed", "manakov_lagrangian_constant"},
     .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(reconstruction_solves_euler_lagrange, float_scalars,
            {.spec = "s1.reconstruction",
             .title = "section 1: g from the left-invariant EP solution by dg/dt = g xi makes the unreduced action "
                      "stationary (Theorem 1.1 (i))",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"euler_3_8", "reconstruction_2_10", "lagrangian_2_5"},
             .negative_controls = {"euler_3_8_cross_reversed", "reconstruction_right_multiplied"},
             .cases = {.d = 10, .mp = 10, .q = 0}});

GM_PROPERTY(
    right_invariant_ep_sign, float_scalars,
    {.spec = "s1.right-invariant-sign",
     .title = "Remark 1.1 on so(3), sl(2,R): for right-invariant l, dmu/dt = -ad*_xi mu with dg/dt = xi g makes "
              "the unreduced action stationary",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"ad_star", "lie_hat", "lie_vee"},
     .negative_controls = {"ad_star_sign_flipped"},
     .cases = {.d = 10, .mp = 5, .q = 0}});

GM_PROPERTY(ep_product_space_variation, float_scalars,
            {.spec = "s1.ep-product-space",
             .title = "exercise on G x Y: along d/dt dl/dxi = ad*_xi dl/dxi, d/dt dl/ddy = dl/dy (subject's ad*), "
                      "delta int l dt = 0 for delta xi = deta/dt + [xi, eta], delta y = zeta",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"ad_star", "lie_hat", "lie_vee"},
             .negative_controls = {"ad_star_sign_flipped", "ad_star_sl2_transpose_pairing"},
             .cases = {.d = 10, .mp = 4, .q = 0}});

}  // namespace properties_variations
}  // namespace gm
