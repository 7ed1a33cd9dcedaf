// Claims of integrators written in the canonical variables of the Clebsch formulations:
// clebsch_step on (Q, P) of (3.21) and manakov_clebsch_step on (Q, P) of (3.23), both canonical
// Hamiltonian systems (impl/canonical_integrators.hpp derives H). Verified like the claims of
// integrator_claims.cpp, measured whether or not claimed:
//
//   order       error at t = 1 against the exact flow, which the notes give by reconstruction:
//               Q(t) = O(t)^-1 Q(0), P(t) = O(t)^-1 P(0) with (Pi, O) the rigid body started at
//               (P(0) x Q(0), Id) (Remark 3.3, (3.20)); for (3.23) Q(t) = Q(0) O(t), P(t) = P(0) O(t)
//               with (M, O) Manakov's body started at (Q^T P - P^T Q, Id) (d/dt Q(0) O = Q(0) O Omega).
//               (M, O) and (Pi, O) come from the Taylor oracle.
//   symmetric   step(h) then step(-h) is the identity.
//   energy      H(Q, P) = h(P x Q) (3.4), or Manakov's -tr(Omega M)/4 of M(Q, P), kept to round-off.
//   symplectic  the step's Jacobian D Phi preserves the canonical two-form
//                   omega(u, v) = <u_Q, v_P> - <u_P, v_Q>:   omega(D Phi u, D Phi v) = omega(u, v).
//
// Symplecticity is judged to the accuracy of the Jacobian, not exactly. The steps are black boxes
// typed on the scalar, and integrators exist in double and 50 digits only, so D Phi u is the
// order-8 central difference along u (support/derivatives.hpp), whose round-off is amplified by
// roundoff_factor8 (~1/d): the allowance, 16 eps * scale below, is about 3e-12 for (3.21) and up to
// about 4e-11 for (3.23) in double, about 1e-42 in 50 digits. The error model counts round-off, not
// the order-8 truncation term |D^9 Phi| d^8 / 630; measured, the symplectic reference methods stay
// at 0.07-0.2 of one eps * scale. A method that is not symplectic shows a defect of the size of its
// local error: RK4 at h = 1/4 exceeds the allowance 1e6 times ((3.21)) and 1e4 times ((3.23)) in
// double, 1e36 times in 50 digits; a midpoint rule solved only to 1e-10 shows ~1e-11, which the
// 50-digit run separates by thirty orders of magnitude.
// For (3.21) u runs over the six unit vectors (all of D Phi^T J D Phi - J is compared); for (3.23)
// over six random dyadic directions in R^{2 n^2}, n = 3..6, and all fifteen pairs are compared
// (a skew matrix S != 0 has u^T S v != 0 for almost every pair).
//
// Spec entries: s3.clebsch-reconstruction (the exact flow of (3.21)), s3.clebsch-poisson (the
// canonical structure (Q, P) carries, whose brackets (3.22) the map to Pi respects), and
// mm.manakov-clebsch for (3.23).
#include <cstdio>

#include "impl/canonical_integrators.hpp"
#include "properties/integrators/support/convergence.hpp"
#include "properties/integrators/support/order_claim.hpp"
#include "properties/integrators/support/roundoff_claim.hpp"
#include "properties/integrators/support/step_field_matrix.hpp"
#include "properties/registry.hpp"
#include "properties/support/claims.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_integrator_canonical {
namespace {

constexpr int kStates = 3;

// One drawn case of either system, stepped through the integrator's slot on the stacked state
// Z = [Q; P] (impl/canonical_integrators.hpp).
template <class T>
struct CanonicalCase {
  std::string system;  // "(3.21)" or "(3.23), n = ..."
  int n = 3;
  std::function<MatX<T>(const MatX<T>&, const T&)> step;
  std::function<T(const MatX<T>&)> energy;
  MatX<T> Z0;
  T energy_scale;                          // a bound on the sum of |terms| of H at Z0 (H is of degree 4 in Z)
  std::function<MatX<T>(const T&)> exact;  // the exact flow at time t from Z0
  std::function<std::string()> body;       // the body's data (I or A) by the notes' names, for failures
  // The step's own vector field at Z against the system's (support/step_field_matrix.hpp).
  std::function<stepfield::Diagnosis(const MatX<T>&)> diagnose;

  // The case's inputs by the notes' names, with the step h.
  std::string inputs(const T& h) const {
    const auto k = Z0.rows() / 2;
    return "    system: " + system + "\n" + body() + named("Q", MatX<T>(Z0.topRows(k))) +
           named("P", MatX<T>(Z0.bottomRows(k))) + named("h", h);
  }
};

template <class T>
T at_least_one_abs(const MatX<T>& Z) {
  return dyn::at_least_one(max_abs(Z));
}

// The size of H's round-off at Z: H is a sum of positive terms (|H| bounds their sum), and an
// error of eps |Z| in each entry of Z moves H by at most eps |Z|_inf sum |dH/dz| to first order,
// where (dH/dP, -dH/dQ) is the field f(Z): scale |H| + |Z|_inf sum |f(Z)|.
template <class T>
T energy_scale(const T& H, const MatX<T>& Z, const MatX<T>& f) {
  return T(abs_value(H) + max_abs(Z) * f.cwiseAbs().sum());
}

template <class T>
CanonicalCase<T> clebsch_case(const Integrator<T>& in) {
  CanonicalCase<T> c;
  const Vec3<T> I = dyn::draw_generic_inertia<T>();
  c.system = "(3.21)";
  c.body = [I]() { return named("I", I); };
  c.step = [&in, I](const MatX<T>& Z, const T& h) { return ref::stack<T>(in.clebsch_step(I, ref::unstack3<T>(Z), h)); };
  c.energy = [I](const MatX<T>& Z) {
    const auto [Q, P] = ref::unstack3<T>(Z);
    return dyn::energy(I, ref::cross<T>(P, Q));
  };
  c.diagnose = [step = c.step, I](const MatX<T>& Z) {
    return stepfield::diagnose_clebsch<T>(stepfield::canonical_field<T>(step, Z), I, Z);
  };
  c.Z0 = ref::stack<T>(Vec3Pair<T>{dyn::draw_generic_momentum<T>(), dyn::draw_generic_momentum<T>()});
  c.energy_scale = energy_scale<T>(c.energy(c.Z0), c.Z0, ref::clebsch_field<T>(I, c.Z0));
  const MatX<T> Z0 = c.Z0;
  c.exact = [I, Z0](const T& t) {
    const auto [Q, P] = ref::unstack3<T>(Z0);
    const RigidBodyState<T> x =
        dyn::oracle_rigid_body(I, RigidBodyState<T>{ref::cross<T>(P, Q), Mat3<T>::Identity()}, {t}).front();
    return ref::stack<T>(Vec3Pair<T>{Vec3<T>(x.O.transpose() * Q), Vec3<T>(x.O.transpose() * P)});
  };
  return c;
}

template <class T>
MatX<T> draw_generic_matrix(int n) {
  MatX<T> X(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) X(i, j) = dyn::generic_entry<T>();
  return X;
}

// n from lo to hi. Entries of Q and P of size in [1/16, 1/2]: M = Q^T P - P^T Q then has entries of
// size about sqrt(2n)/4 (at most n/2), Omega about as large as in the (3.21) case, and the
// fixed-point solve of an implicit step of h = 1/4 contracts.
template <class T>
CanonicalCase<T> manakov_clebsch_case(const Integrator<T>& in, int lo, int hi) {
  CanonicalCase<T> c;
  c.n = dyn::pick<T>(rc::gen::inRange(lo, hi + 1), "n");
  const int n = c.n;
  const std::vector<T> a = dyn::draw_generic_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  c.system = "(3.23), n = " + std::to_string(n);
  c.body = [A]() { return named("A", A); };
  c.step = [&in, A](const MatX<T>& Z, const T& h) {
    return ref::stack<T>(in.manakov_clebsch_step(A, ref::unstack_n<T>(Z), h));
  };
  c.diagnose = [step = c.step, A](const MatX<T>& Z) {
    return stepfield::diagnose_manakov_clebsch<T>(stepfield::canonical_field<T>(step, Z), A, Z);
  };
  c.energy = [a](const MatX<T>& Z) {
    const auto [Q, P] = ref::unstack_n<T>(Z);
    return dyn::manakov_energy(a, ref::manakov_clebsch_M<T>(Q, P));
  };
  const T shrink = T(1) / T(2);
  c.Z0 = ref::stack<T>(
      MatXPair<T>{MatX<T>(shrink * draw_generic_matrix<T>(n)), MatX<T>(shrink * draw_generic_matrix<T>(n))});
  c.energy_scale = energy_scale<T>(c.energy(c.Z0), c.Z0, ref::manakov_clebsch_field<T>(A, c.Z0));
  const MatX<T> Z0 = c.Z0;
  c.exact = [a, Z0](const T& t) {
    const auto [Q, P] = ref::unstack_n<T>(Z0);
    const auto k = Q.rows();
    const ManakovState<T> x =
        dyn::oracle_manakov(a, ManakovState<T>{ref::manakov_clebsch_M<T>(Q, P), MatX<T>::Identity(k, k)}, {t}).front();
    return ref::stack<T>(MatXPair<T>{MatX<T>(Q * x.O), MatX<T>(P * x.O)});
  };
  return c;
}

template <class T>
CanonicalCase<T> draw_case(StepKind kind, const Integrator<T>& in, int lo = 3, int hi = 6) {
  return kind == StepKind::Clebsch ? clebsch_case<T>(in) : manakov_clebsch_case<T>(in, lo, hi);
}

template <class T>
MatX<T> run(const CanonicalCase<T>& c, MatX<T> Z, const T& h, int steps) {
  for (int k = 0; k < steps; ++k) Z = c.step(Z, h);
  return Z;
}

// A false claim leads with the step's own equation at the case's start.
template <class T, class Judge>
void explained(const CanonicalCase<T>& c, Judge&& judge) {
  stepfield::explaining_claims([&] { return "the step's own equation: " + c.diagnose(c.Z0).text + judged_tag<T>(); },
                               judge);
}

// ---------------------------------------------------------------------------------------------
// Order: as integrator_order (h = 1/8 ... 1/128 for (3.21), to 1/64 for (3.23) with n = 3, 4);
// the log-log slope above the round-off floor must be within 0.1 of the claim.
template <class T>
void canonical_order(StepKind kind, const Integrator<T>& in, const IntegratorClaims& cl) {
  const CanonicalCase<T> c = draw_case<T>(kind, in, 3, 4);
  const T t_end(1);
  const MatX<T> exact = c.exact(t_end);
  const T scale = at_least_one_abs(c.Z0);
  std::vector<double> hs, errs, floors;
  Series ser{"convergence (Clebsch " + c.system.substr(0, 6) + "): " + in.name,
             "error at t = 1" + judged_tag<T>(),
             "step h",
             "max error",
             true,
             true,
             {},
             static_cast<double>(cl.order)};
  const std::vector<int> Ns =
      kind == StepKind::Clebsch ? std::vector<int>{8, 16, 32, 64, 128} : std::vector<int>{8, 16, 32, 64};
  std::vector<double> errs_Q, errs_P;
  const auto k = c.Z0.rows() / 2;  // Z stacks Q over P
  for (int N : Ns) {
    const T h = t_end / T(N);
    const MatX<T> D = run(c, c.Z0, h, N) - exact;
    const T err = max_abs(D);
    hs.push_back(to_double(h));
    errs.push_back(to_double(err));
    errs_Q.push_back(to_double(T(max_abs(MatX<T>(D.topRows(k))))));
    errs_P.push_back(to_double(T(max_abs(MatX<T>(D.bottomRows(k))))));
    floors.push_back(16.0 * step_eps_double<T>() * to_double(scale) * N * c.n);
    ser.points.emplace_back(hs.back(), errs.back());
  }
  record_series(ser);
  const std::string parts = parts_order({"Q", "P"}, {errs_Q, errs_P}, hs, floors);
  explained(c, [&] {
    showing_inputs(
        [&] {
          return c.inputs(t_end / T(Ns.front())) + "    (h halved down to 1/" + std::to_string(Ns.back()) + ")\n";
        },
        [&] {
          judge_order_claim(in.name, cl.order, " on the Clebsch system " + c.system, judged_tag<T>(), hs, errs, floors,
                            parts);
        });
  });
}

// Symmetry: step(h) then step(-h), h = 1/4; two steps at a few eps each: k = 64 on the scale
// max(1, |Z|) times n (the entries of M sum 2n products).
template <class T>
void canonical_symmetric(StepKind kind, const Integrator<T>& in, const IntegratorClaims& cl) {
  const T h = T(1) / T(4);
  T worst(0), worst_scale(1);
  std::string system, inputs;
  CanonicalCase<T> shown;
  for (int k = 0; k < kStates; ++k) {
    const CanonicalCase<T> c = draw_case<T>(kind, in);
    system = c.system.substr(0, 6);
    const T scale = at_least_one_abs(c.Z0) * T(c.n);
    const T r = max_abs(MatX<T>(c.step(c.step(c.Z0, h), -h) - c.Z0)) / scale;
    if (k == 0 || worse(r, worst)) worst = r, worst_scale = scale, inputs = c.inputs(h), shown = c;
  }
  explained(shown, [&] {
    showing_inputs([&] { return inputs; },
                   [&] {
                     judge_roundoff_claim<T>("symmetric", cl.symmetric, in.name,
                                             "Clebsch " + system + " step(h) then step(-h) returns to the start",
                                             T(worst * worst_scale), worst_scale, 64);
                   });
  });
}

// Energy over 64 steps (32 for (3.23)) of h = 1/8: H is of degree 4, k = 16 per degree and step on
// the scale of H's terms (as integrator_energy).
template <class T>
void canonical_energy(StepKind kind, const Integrator<T>& in, const IntegratorClaims& cl) {
  const int steps = kind == StepKind::Clebsch ? 64 : 32;
  T worst(0), worst_scale(1);
  std::string system, inputs;
  CanonicalCase<T> shown;
  for (int k = 0; k < kStates; ++k) {
    const CanonicalCase<T> c = draw_case<T>(kind, in);
    system = c.system.substr(0, 6);
    if (k == 0) shown = c;
    const T H0 = c.energy(c.Z0);
    MatX<T> Z = c.Z0;
    for (int s = 0; s < steps; ++s) {
      Z = c.step(Z, T(1) / T(8));
      const T r = abs_value(T(c.energy(Z) - H0)) / c.energy_scale;
      if (worse(r, worst)) worst = r, worst_scale = c.energy_scale, inputs = c.inputs(T(1) / T(8)), shown = c;
    }
  }
  explained(shown, [&] {
    showing_inputs([&] { return inputs; },
                   [&] {
                     judge_roundoff_claim<T>("energy", cl.energy, in.name,
                                             "the Hamiltonian H(Q, P) of the Clebsch system " + system +
                                                 " is kept to round-off over " + std::to_string(steps) + " steps",
                                             T(worst * worst_scale), T(steps * worst_scale), 64);
                   });
  });
}

// Symplecticity (see the head of the file). Directional derivatives D Phi u_i by central8, then
// |omega(D Phi u_i, D Phi u_j) - omega(u_i, u_j)| over all pairs. Error model: each entry of
// D Phi u carries about roundoff_factor8 * eps * max(1, |Phi|) (support/derivatives.hpp), and
// omega sums N = rows * cols products of two such entries: k = 16 on the scale
// N * max(1, |D Phi u|) * max(1, |Phi|) * roundoff_factor8. h = 1/4.
template <class T>
T two_form(const MatX<T>& U, const MatX<T>& V) {
  const auto k = U.rows() / 2;
  return T((U.topRows(k).cwiseProduct(V.bottomRows(k))).sum() - (U.bottomRows(k).cwiseProduct(V.topRows(k))).sum());
}

template <class T>
void canonical_symplectic(StepKind kind, const Integrator<T>& in, const IntegratorClaims& cl) {
  const T h = T(1) / T(4);
  T worst(0), worst_raw(0), worst_scale(1);
  std::string system, where, inputs;
  CanonicalCase<T> shown;
  for (int s = 0; s < kStates; ++s) {
    const CanonicalCase<T> c = draw_case<T>(kind, in);
    system = c.system.substr(0, 6);
    if (s == 0) shown = c;
    const auto rows = c.Z0.rows(), cols = c.Z0.cols();
    std::vector<MatX<T>> u;
    if (kind == StepKind::Clebsch) {
      for (int i = 0; i < 6; ++i) u.push_back(MatX<T>(VecX<T>::Unit(6, i)));
    } else {
      for (int i = 0; i < 6; ++i) {
        MatX<T> d(rows, cols);
        for (Eigen::Index r = 0; r < rows; ++r)
          for (Eigen::Index q = 0; q < cols; ++q) d(r, q) = T(dyn::pick<T>(rc::gen::inRange(-8, 9), "8 d_rq")) / T(8);
        u.push_back(d);
      }
    }
    const MatX<T> Phi0 = c.step(c.Z0, h);
    std::vector<MatX<T>> Du;
    T size(1);
    for (const auto& d : u) {
      Du.push_back(deriv::central8<T>([&](const T& e) { return c.step(MatX<T>(c.Z0 + e * d), h); }, deriv::step8<T>()));
      size = std::max(size, max_abs(Du.back()));
    }
    const T scale = T(rows * cols) * size * at_least_one_abs(Phi0) * deriv::roundoff_factor8<T>();
    for (size_t i = 0; i < u.size(); ++i)
      for (size_t j = i + 1; j < u.size(); ++j) {
        const T raw = abs_value(T(two_form<T>(Du[i], Du[j]) - two_form<T>(u[i], u[j])));
        const T r = raw / scale;
        if (worse(r, worst)) {
          worst = r, worst_raw = raw, worst_scale = scale;
          inputs = c.inputs(h) + named("u", u[i]) + named("v", u[j]);
          where = c.system + fmt(", directions %g and %g", static_cast<double>(i), static_cast<double>(j));
          shown = c;
        }
      }
  }
  explained(shown, [&] {
    showing_inputs([&] { return inputs; },
                   [&] {
                     judge_roundoff_claim<T>("symplectic", cl.symplectic, in.name,
                                             "omega(D Phi u, D Phi v) = omega(u, v): the Clebsch " + system +
                                                 " step preserves the canonical two-form (worst at " + where + ")",
                                             worst_raw, worst_scale, 16);
                   });
  });
}

template <class T>
void clebsch_integrator_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_order<T>(StepKind::Clebsch, in, c);
}
template <class T>
void manakov_clebsch_integrator_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_order<T>(StepKind::ManakovClebsch, in, c);
}
template <class T>
void clebsch_integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symmetric<T>(StepKind::Clebsch, in, c);
}
template <class T>
void manakov_clebsch_integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symmetric<T>(StepKind::ManakovClebsch, in, c);
}
template <class T>
void clebsch_integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_energy<T>(StepKind::Clebsch, in, c);
}
template <class T>
void manakov_clebsch_integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_energy<T>(StepKind::ManakovClebsch, in, c);
}
template <class T>
void clebsch_integrator_symplectic(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symplectic<T>(StepKind::Clebsch, in, c);
}
template <class T>
void manakov_clebsch_integrator_symplectic(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symplectic<T>(StepKind::ManakovClebsch, in, c);
}

}  // namespace

#define GM_CL .cases = {.d = 10, .mp = 2, .q = 0}, .step = StepKind::Clebsch
#define GM_MCL .cases = {.d = 5, .mp = 1, .q = 0}, .step = StepKind::ManakovClebsch

GM_PROPERTY(
    clebsch_integrator_order, integrator_scalars,
    {.spec = "s3.clebsch-reconstruction",
     .title = "Clebsch (3.21) integrator: measured order at t = 1 (against Q(t) = O(t)^-1 Q(0)) matches the claim",
     .tolerance = ToleranceClass::Truncation,
     .needs = {},
     .negative_controls = {"explicit_verlet_nonseparable", "clebsch_midpoint_sign_flipped"},
     GM_CL,
     .judges = {"order"}});

GM_PROPERTY(manakov_clebsch_integrator_order, integrator_scalars,
            {.spec = "mm.manakov-clebsch",
             .title = "Clebsch (3.23) integrator: measured order at t = 1 (against Q(t) = Q(0) O(t)) matches the claim",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"explicit_verlet_nonseparable", "manakov_clebsch_midpoint_printed_M"},
             GM_MCL,
             .judges = {"order"}});

GM_PROPERTY(clebsch_integrator_symmetric, integrator_scalars,
            {.spec = "s3.clebsch-reconstruction",
             .title = "Clebsch (3.21) integrator claimed symmetric: step(h) then step(-h) is the identity to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"explicit_verlet_nonseparable", "clebsch_midpoint_loose_solve"},
             GM_CL,
             .judges = {"symmetric"}});

GM_PROPERTY(manakov_clebsch_integrator_symmetric, integrator_scalars,
            {.spec = "mm.manakov-clebsch",
             .title = "Clebsch (3.23) integrator claimed symmetric: step(h) then step(-h) is the identity to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"explicit_verlet_nonseparable", "clebsch_midpoint_loose_solve"},
             GM_MCL,
             .judges = {"symmetric"}});

GM_PROPERTY(clebsch_integrator_energy, integrator_scalars,
            {.spec = "s3.clebsch-euler",
             .title = "Clebsch (3.21) integrator claiming energy: H(Q, P) = h(P x Q) kept to round-off",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"clebsch_midpoint_claims_energy"},
             GM_CL,
             .judges = {"energy"}});

GM_PROPERTY(
    manakov_clebsch_integrator_energy, integrator_scalars,
    {.spec = "mm.manakov-clebsch",
     .title = "Clebsch (3.23) integrator claiming energy: -tr(Omega M)/4 of M = Q^T P - P^T Q kept to round-off",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {},
     .negative_controls = {"clebsch_midpoint_claims_energy"},
     GM_MCL,
     .judges = {"energy"}});

GM_PROPERTY(clebsch_integrator_symplectic, integrator_scalars,
            {.spec = "s3.clebsch-poisson",
             .title = "Clebsch (3.21) integrator claimed symplectic: D Phi preserves dQ ^ dP (to the accuracy of an "
                      "order-8 Jacobian)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"explicit_verlet_nonseparable", "rk4_claims_symplectic",
                                   "clebsch_midpoint_loose_solve"},
             GM_CL,
             .judges = {"symplectic"}});

GM_PROPERTY(manakov_clebsch_integrator_symplectic, integrator_scalars,
            {.spec = "mm.manakov-clebsch",
             .title = "Clebsch (3.23) integrator claimed symplectic: D Phi preserves the canonical two-form (n = 3..6)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {},
             .negative_controls = {"explicit_verlet_nonseparable", "rk4_claims_symplectic",
                                   "clebsch_midpoint_loose_solve"},
             GM_MCL,
             .judges = {"symplectic"}});

#undef GM_CL
#undef GM_MCL

}  // namespace properties_integrator_canonical
}  // namespace gm
