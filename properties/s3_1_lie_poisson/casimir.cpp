// The Casimir c(Pi) = |Pi|^2 / 2 of the rigid body's Lie-Poisson bracket (section 3.3, (2.27)):
// the function courses ask students to write first. Checked on its own against its formula, then
// as what makes it a Casimir: it Poisson-commutes with every function under (3.6), so Euler's
// equations (3.8) conserve it.
//
// Gradients of the subject's c are central differences with unit steps, exact for a quadratic c
// (truth::gradient_of_quadratic); a c that is not quadratic shows up in definition_casimir first.
#include "properties/registry.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_casimir {
namespace {

template <class T>
void definition_casimir(const Subject<T>& s) {
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  showing_inputs([&] { return named("Pi", P); },
                 [&] {
                   require_close("slot casimir: c(Pi) = |Pi|^2 / 2, (2.27)", s.casimir(P), T(P.dot(P) / T(2)),
                                 T(P.squaredNorm()), 4);
                 });
}

template <class T>
Vec3<T> grad_c(const Subject<T>& s, const Vec3<T>& P) {
  return truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return s.casimir(y); }, P);
}

// {c, f} = 0 for every f: with (3.6), -Pi . (grad c x df) = 0 for every gradient df. The gradient
// rounds a few times on values of size (|Pi| + 1)^2: k = 16 + the triple product's 8.
template <class T>
void casimir_commutes_3_6(const Subject<T>& s) {
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Vec3<T> df = *gen::regime_vec3<T>().as("df/dPi");
  const Vec3<T> dc = grad_c(s, P);
  const T size = T((norm_inf(P) + T(1)) * (norm_inf(P) + T(1)));
  showing_inputs([&] { return named("Pi", P) + named("df/dPi", df); },
                 [&] {
                   require_close("casimir and lie_poisson_3_6: {c, f} = -Pi . (grad c x df) = 0, section 3.3",
                                 s.lie_poisson_3_6(P, dc, df), T(0), T(norm_inf(P) * size * norm_inf(df)), 24);
                 });
}

// dc/dt = grad c . dPi/dt = 0 along (3.8).
template <class T>
void casimir_conserved_by_euler(const Subject<T>& s) {
  const Vec3<T> I = *gen::regime_inertia<T>().as("I");
  const Vec3<T> P = *gen::regime_vec3<T>().as("Pi");
  const Vec3<T> dc = grad_c(s, P);
  const T size = T((norm_inf(P) + T(1)) * (norm_inf(P) + T(1)));
  showing_inputs([&] { return named("I", I) + named("Pi", P); },
                 [&] {
                   require_close("casimir and euler_3_8: dc/dt = grad c . dPi/dt = 0, (3.8)",
                                 T(dc.dot(s.euler_3_8(I, P))), T(0), T(size * P.squaredNorm() / I.minCoeff()), 32);
                 });
}

}  // namespace

GM_PROPERTY(definition_casimir, all_scalars,
            {.spec = "s3.casimir",
             .title = "slot casimir alone: c(Pi) = |Pi|^2 / 2, (2.27)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"casimir"},
             .negative_controls = {"casimir_without_half", "casimir_weighted"}});

GM_PROPERTY(casimir_commutes_3_6, all_scalars,
            {.spec = "s3.casimir",
             .title = "{c, f} = 0 for every f under (3.6): c is a Casimir",
             .tolerance = ToleranceClass::Exact,
             .needs = {"casimir", "lie_poisson_3_6"},
             .negative_controls = {"casimir_weighted", "lie_poisson_3_6_cyclic_index_slip"}});

GM_PROPERTY(casimir_conserved_by_euler, all_scalars,
            {.spec = "s3.casimir",
             .title = "dc/dt = grad c . dPi/dt = 0 along Euler's equations (3.8)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"casimir", "euler_3_8"},
             .negative_controls = {"casimir_weighted", "euler_3_8_second_component_sign"}});

}  // namespace properties_casimir
}  // namespace gm
