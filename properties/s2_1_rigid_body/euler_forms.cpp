// Euler's equations in every form of the notes, each compared with the componentwise form (2.1)
// written out by the property itself: (2.1), (2.2)/(2.9), (3.7), (3.8) and the matrix form (2.12).
//
// All forms are compared in momentum space, dPi/dt = I dOmega/dt, whose components are
// (I2 - I3) Omega2 Omega3 and cyclically: exact products of the dyadic inputs. A form that
// divides by I rounds a few times on numbers of size |I| |Omega|^2, hence scale |I| |Omega|^2.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_euler_forms {
namespace {

// I dOmega/dt from (2.1), componentwise.
template <class T>
Vec3<T> momentum_rate_2_1(const Vec3<T>& I, const Vec3<T>& W) {
  return Vec3<T>((I(1) - I(2)) * W(1) * W(2), (I(2) - I(0)) * W(2) * W(0), (I(0) - I(1)) * W(0) * W(1));
}

template <class T>
struct EulerCase {
  Vec3<T> I, Omega, Pi, expected;
  T scale;
};

template <class T>
EulerCase<T> draw_euler_case() {
  EulerCase<T> c;
  c.I = *gen::inertia<T>().as("I");
  c.Omega = *gen::vec3<T>().as("Omega");
  c.Pi = c.I.cwiseProduct(c.Omega);  // exact: dyadic times dyadic
  c.expected = momentum_rate_2_1(c.I, c.Omega);
  c.scale = norm_inf(c.I) * norm_inf(c.Omega) * norm_inf(c.Omega);
  return c;
}

template <class T>
void euler_form_2_1(const Subject<T>& s) {
  const auto c = draw_euler_case<T>();
  require_close("I * euler_2_1(I, Omega) = componentwise (2.1)", c.I.cwiseProduct(s.euler_2_1(c.I, c.Omega)).eval(),
                c.expected, c.scale, 8);
}

template <class T>
void euler_form_2_2(const Subject<T>& s) {
  const auto c = draw_euler_case<T>();
  require_close("I * euler_2_2(I, Omega) = componentwise (2.1)", c.I.cwiseProduct(s.euler_2_2(c.I, c.Omega)).eval(),
                c.expected, c.scale, 8);
}

template <class T>
void euler_form_3_7(const Subject<T>& s) {
  const auto c = draw_euler_case<T>();
  require_close("euler_3_7(I, I Omega) = componentwise (2.1)", s.euler_3_7(c.I, c.Pi), c.expected, c.scale, 16);
}

template <class T>
void euler_form_3_8(const Subject<T>& s) {
  const auto c = draw_euler_case<T>();
  require_close("euler_3_8(I, I Omega) = componentwise (2.1)", s.euler_3_8(c.I, c.Pi), c.expected, c.scale, 16);
}

template <class T>
void euler_matrix_form_2_12(const Subject<T>& s) {
  const auto c = draw_euler_case<T>();
  require_close("euler_matrix_2_12(I, hat(I Omega)) = hat of componentwise (2.1)",
                s.euler_matrix_2_12(c.I, truth::skew_of(c.Pi)), truth::skew_of(c.expected), c.scale, 16);
}

}  // namespace

GM_PROPERTY(euler_form_2_1, all_scalars,
            {.spec = "s2.euler-equations",
             .title = "(2.1): I1 dOmega1/dt = (I2 - I3) Omega2 Omega3, and cyclically",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_2_1"},
             .negative_controls = {"euler_2_1_sign_error", "euler_2_1_missing_division"}});

GM_PROPERTY(euler_form_2_2, all_scalars,
            {.spec = "s2.euler-equations",
             .title = "(2.2): I dOmega/dt = I Omega x Omega is (2.1)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_2_2"},
             .negative_controls = {"euler_2_2_cross_reversed"}});

GM_PROPERTY(euler_form_3_7, all_scalars,
            {.spec = "s3.euler-momentum-form",
             .title = "(3.7): dPi1/dt = (1/I3 - 1/I2) Pi2 Pi3, and cyclically, is (2.1) with Pi = I Omega",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_3_7"},
             .negative_controls = {"euler_3_7_index_slip"}});

GM_PROPERTY(euler_form_3_8, all_scalars,
            {.spec = "s3.euler-momentum-form",
             .title = "(3.8): dPi/dt = Pi x I^-1 Pi is (2.1) with Pi = I Omega",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_3_8"},
             .negative_controls = {"euler_3_8_cross_reversed", "euler_3_8_I_not_inverted"}});

GM_PROPERTY(euler_matrix_form_2_12, all_scalars,
            {.spec = "s2.matrix-euler",
             .title = "(2.12): dPi/dt = -[Omega_hat, Pi] is (2.1) through the hat map",
             .tolerance = ToleranceClass::Exact,
             .needs = {"euler_matrix_2_12"},
             .negative_controls = {"euler_matrix_commutator_sign"}});

}  // namespace properties_euler_forms
}  // namespace gm
