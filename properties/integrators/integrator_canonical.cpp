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
#include "properties/integrators/support/canonical_kind.hpp"
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

// The cases of both systems and their traits (support/canonical_kind.hpp).
using canonicalkind::at_least_one_abs;
using canonicalkind::CanonicalCase;
using canonicalkind::ClebschKind;
using canonicalkind::ManakovClebschKind;

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
template <class Kind, class T>
void canonical_order(const Integrator<T>& in, const IntegratorClaims& cl) {
  const CanonicalCase<T> c = Kind::template draw_case<T>(in, 3, 4);
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
  const std::vector<int> Ns = Kind::order_steps();
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
template <class Kind, class T>
void canonical_symmetric(const Integrator<T>& in, const IntegratorClaims& cl) {
  const T h = T(1) / T(4);
  T worst(0), worst_scale(1);
  std::string system, inputs;
  CanonicalCase<T> shown;
  for (int k = 0; k < kStates; ++k) {
    const CanonicalCase<T> c = Kind::template draw_case<T>(in);
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
template <class Kind, class T>
void canonical_energy(const Integrator<T>& in, const IntegratorClaims& cl) {
  const int steps = Kind::energy_steps;
  T worst(0), worst_scale(1);
  std::string system, inputs;
  CanonicalCase<T> shown;
  for (int k = 0; k < kStates; ++k) {
    const CanonicalCase<T> c = Kind::template draw_case<T>(in);
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

template <class Kind, class T>
void canonical_symplectic(const Integrator<T>& in, const IntegratorClaims& cl) {
  const T h = T(1) / T(4);
  T worst(0), worst_raw(0), worst_scale(1);
  std::string system, where, inputs;
  CanonicalCase<T> shown;
  for (int s = 0; s < kStates; ++s) {
    const CanonicalCase<T> c = Kind::template draw_case<T>(in);
    system = c.system.substr(0, 6);
    if (s == 0) shown = c;
    const auto rows = c.Z0.rows(), cols = c.Z0.cols();
    const std::vector<MatX<T>> u = Kind::template directions<T>(c);  // drawn after the case, as before
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
  canonical_order<ClebschKind>(in, c);
}
template <class T>
void manakov_clebsch_integrator_order(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_order<ManakovClebschKind>(in, c);
}
template <class T>
void clebsch_integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symmetric<ClebschKind>(in, c);
}
template <class T>
void manakov_clebsch_integrator_symmetric(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symmetric<ManakovClebschKind>(in, c);
}
template <class T>
void clebsch_integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_energy<ClebschKind>(in, c);
}
template <class T>
void manakov_clebsch_integrator_energy(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_energy<ManakovClebschKind>(in, c);
}
template <class T>
void clebsch_integrator_symplectic(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symplectic<ClebschKind>(in, c);
}
template <class T>
void manakov_clebsch_integrator_symplectic(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  canonical_symplectic<ManakovClebschKind>(in, c);
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
