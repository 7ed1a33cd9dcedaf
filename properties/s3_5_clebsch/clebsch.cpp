// Clebsch variables (section 3.5): the equations (3.21) imply Euler's equations for Pi = P x Q,
// and the map (Q, P) -> Pi = P x Q is Poisson from the canonical bracket to the Lie-Poisson
// bracket (3.22), Remark 3.6.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_clebsch {
namespace {

// Pi_a = eps_abc P_b Q_c as polynomials in x = (Q, P) in R^6 (Q = x1..x3, P = x4..x6).
template <class T>
std::vector<Polynomial<T>> clebsch_Pi() {
  std::vector<Polynomial<T>> Pi(3, Polynomial<T>(6));
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        const int e = truth::levi_civita(a, b, c);
        if (!e) continue;
        Pi[static_cast<std::size_t>(a)] =
            Pi[static_cast<std::size_t>(a)] +
            (Polynomial<T>::coordinate(6, 3 + b) * Polynomial<T>::coordinate(6, c)).scaled(T(e));
      }
  return Pi;
}

// Remark 3.6 / answer (3.22): for functions f, h of Pi, the canonical bracket of F = f(P x Q) and
// H = h(P x Q) (formed symbolically, so their gradients come from their own coefficients) is the
// Lie-Poisson bracket (3.6) of f and h at Pi = P x Q; in particular {Pi_a, Pi_b} = -eps_abc Pi_c.
// Sizes: the canonical side 6 |dF| |dH| (majorants of the composed polynomials on the box of (Q, P));
// the Lie-Poisson side 6 |Pi| |df| |dh| on the box |Pi| <= 2 |(Q, P)|^2.
template <class T>
void clebsch_map_is_poisson(const Subject<T>& s) {
  const auto f = *gen::polynomial<T>(3, 3).as("f");
  const auto h = *gen::polynomial<T>(3, 3).as("h");
  const VecX<T> x = *gen::point<T>(6).as("x");
  const Vec3<T> Q(x.head(3)), P(x.tail(3));
  const auto Pi_of = clebsch_Pi<T>();
  const Vec3<T> Pi = s.momentum_map(Q, P);
  require_close("(3.21): Pi = P x Q", Pi, truth::cross(P, Q), T(T(2) * norm_inf(P) * norm_inf(Q)), 2);
  const T R = norm_inf(x), R_Pi = T(2) * R * R;
  auto canonical_of = [&](const Polynomial<T>& F, const Polynomial<T>& H) {
    const VecX<T> dF = F.gradient(x), dH = H.gradient(x);
    return s.canonical_bracket(Vec3<T>(dF.head(3)), Vec3<T>(dF.tail(3)), Vec3<T>(dH.head(3)), Vec3<T>(dH.tail(3)));
  };
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      T expected(0);
      for (int c = 0; c < 3; ++c) expected -= T(truth::levi_civita(a, b, c)) * Pi(c);
      require_close("(3.22): {Pi_" + std::to_string(a + 1) + ", Pi_" + std::to_string(b + 1) + "} = -eps_abc Pi_c",
                    canonical_of(Pi_of[static_cast<std::size_t>(a)], Pi_of[static_cast<std::size_t>(b)]), expected,
                    T(T(6) * R * R), 8);
    }
  const Polynomial<T> F = substitute(f, Pi_of), H = substitute(h, Pi_of);
  const VecX<T> Pi_x(Pi);
  const T scale =
      T(6) * F.gradient_bound(R) * H.gradient_bound(R) + T(6) * R_Pi * f.gradient_bound(R_Pi) * h.gradient_bound(R_Pi);
  const int k = 4 + std::max(F.eval_ops(), H.eval_ops()) + kTripleProductOps + std::max(f.eval_ops(), h.eval_ops()) + 2;
  require_close("(3.22): {f(P x Q), h(P x Q)}_canonical = {f, h}_(3.6) at Pi = P x Q", canonical_of(F, H),
                s.lie_poisson_3_6(Pi, Vec3<T>(f.gradient(Pi_x)), Vec3<T>(h.gradient(Pi_x))), scale, k);
}

// Proposition 3.1: (3.21), dQ/dt = -Omega x Q and dP/dt = -Omega x P with Omega = I^-1 Pi, give
// dPi/dt = dP/dt x Q + P x dQ/dt = -Omega x Pi, which is Euler's equation (3.8) for Pi = I Omega.
// Sizes: w = |Pi| / min I bounds Omega; |dQ/dt| <= 2 w |Q|; |dPi/dt| <= 8 w |P| |Q|.
template <class T>
void clebsch_implies_euler(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> Q = *gen::vec3<T>().as("Q");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const auto [Q_dot, P_dot] = s.clebsch_3_21(I, Q, P);
  const Vec3<T> Pi = s.momentum_map(Q, P);
  const Vec3<T> Omega = Pi.cwiseQuotient(I);
  const T w = T(2) * norm_inf(P) * norm_inf(Q) / I.minCoeff();
  require_close("(3.21): dQ/dt = -Omega x Q", Q_dot, (-truth::cross(Omega, Q)).eval(), T(T(2) * w * norm_inf(Q)), 6);
  require_close("(3.21): dP/dt = -Omega x P", P_dot, (-truth::cross(Omega, P)).eval(), T(T(2) * w * norm_inf(P)), 6);
  const Vec3<T> Pi_dot = (truth::cross(P_dot, Q) + truth::cross(P, Q_dot)).eval();
  const T scale = T(8) * w * norm_inf(P) * norm_inf(Q);
  require_close("elimination after (3.21): dPi/dt = -Omega x Pi", Pi_dot, (-truth::cross(Omega, Pi)).eval(), scale, 12);
  require_close("... which is Euler's equation (3.8) for Pi = I Omega", Pi_dot, s.euler_3_8(I, Pi), scale, 12);
}

}  // namespace

GM_PROPERTY(clebsch_map_is_poisson, all_scalars,
            {.spec = "s3.clebsch-poisson",
             .title = "(3.22), Remark 3.6: canonical brackets of f(P x Q), h(P x Q) are the Lie-Poisson bracket (3.6)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"momentum_map", "canonical_bracket", "lie_poisson_3_6"},
             .negative_controls = {"canonical_bracket_sign_flipped", "momentum_map_reversed",
                                   "lie_poisson_3_6_sign_flipped"},
             .cases = {.d = 100, .mp = 25, .q = 15}});

GM_PROPERTY(clebsch_implies_euler, all_scalars,
            {.spec = "s3.clebsch-euler",
             .title = "Proposition 3.1: (3.21) implies dPi/dt = -Omega x Pi, Euler's equation, for Pi = P x Q",
             .tolerance = ToleranceClass::Exact,
             .needs = {"clebsch_3_21", "momentum_map", "euler_3_8"},
             .negative_controls = {"clebsch_3_21_sign_flipped", "clebsch_3_21_Pi_for_Omega"}});

}  // namespace properties_clebsch
}  // namespace gm
