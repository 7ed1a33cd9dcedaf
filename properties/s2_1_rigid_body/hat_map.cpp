// The hat map (2.11) and the trace pairing (2.15): the identification of so(3) with R^3.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_hat_map {
namespace {

// hat(a) v = a x v. Each entry of hat(a) v is a sum of two products: k = 4 covers the roundings
// on both sides (the truth's cross product rounds too).
template <class T>
void hat_is_cross_product(const Subject<T>& s) {
  const Vec3<T> a = *gen::vec3<T>().as("a");
  const Vec3<T> v = *gen::vec3<T>().as("v");
  require_close("hat(a) v = a x v", (s.hat(a) * v).eval(), truth::cross(a, v), T(norm_inf(a) * norm_inf(v)), 4);
  require_close("hat(a) is the matrix -a_i eps_ijk of (2.11)", s.hat(a), truth::skew_of(a), T(norm_inf(a)), 0);
}

// [hat(a), hat(b)] = hat(a x b): the hat map is a Lie-algebra isomorphism (R^3, x) -> so(3).
// Entries of the commutator are sums of four products (k = 8 with the right-hand side).
template <class T>
void hat_is_lie_algebra_isomorphism(const Subject<T>& s) {
  const Vec3<T> a = *gen::vec3<T>().as("a");
  const Vec3<T> b = *gen::vec3<T>().as("b");
  const Mat3<T> A = s.hat(a), B = s.hat(b);
  require_close("[hat(a), hat(b)] = hat(a x b)", (A * B - B * A).eval(), s.hat(truth::cross(a, b)),
                T(norm_inf(a) * norm_inf(b)), 8);
}

// vee inverts hat on skew matrices, and hat(v) is skew.
template <class T>
void vee_inverts_hat(const Subject<T>& s) {
  const Vec3<T> a = *gen::vec3<T>().as("a");
  const Mat3<T> S = *gen::skew3<T>().as("S");
  require_close("vee(hat(a)) = a", s.vee(s.hat(a)), a, T(norm_inf(a)), 0);
  require_close("hat(vee(S)) = S for skew S", s.hat(s.vee(S)), S, T(norm_inf(S)), 0);
  const Mat3<T> H = s.hat(a);
  require_close("hat(a)^T = -hat(a)", H.transpose().eval(), (-H).eval(), T(norm_inf(a)), 0);
}

// <hat(a), hat(b)> = (1/2) tr(hat(a)^T hat(b)) = a . b. Six products summed on the left, three on
// the right: k = 12.
template <class T>
void trace_pairing_is_dot_product(const Subject<T>& s) {
  const Vec3<T> a = *gen::vec3<T>().as("a");
  const Vec3<T> b = *gen::vec3<T>().as("b");
  const MatX<T> A = truth::skew_of(a), B = truth::skew_of(b);
  require_close("<hat(a), hat(b)> = a . b", s.pairing(A, B), T(a.dot(b)), T(norm_inf(a) * norm_inf(b)), 12);
}

}  // namespace

GM_PROPERTY(hat_is_cross_product, all_scalars,
            {.spec = "s2.hat-map",
             .title = "hat(a) v = a x v, with hat(a)_jk = -a_i eps_ijk as in (2.11)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hat"},
             .negative_controls = {"hat_transposed"}});

GM_PROPERTY(hat_is_lie_algebra_isomorphism, all_scalars,
            {.spec = "s2.hat-map",
             .title = "[hat(a), hat(b)] = hat(a x b)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hat"},
             .negative_controls = {"hat_transposed", "hat_scaled"}});

GM_PROPERTY(vee_inverts_hat, all_scalars,
            {.spec = "s2.hat-map",
             .title = "vee(hat(a)) = a, hat(vee(S)) = S for skew S, and hat(a) is skew",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hat", "vee"},
             .negative_controls = {"vee_reads_upper_triangle"}});

GM_PROPERTY(trace_pairing_is_dot_product, all_scalars,
            {.spec = "s2.trace-pairing",
             .title = "<hat(a), hat(b)> = (1/2) trace(hat(a)^T hat(b)) = a . b",
             .tolerance = ToleranceClass::Exact,
             .needs = {"pairing"},
             .negative_controls = {"pairing_without_half"}});

}  // namespace properties_hat_map
}  // namespace gm
