// Every algebraic slot checked on its own: each property below needs exactly one slot
// and compares it with the notes' formula, written here from the definition (support/truth.hpp),
// never with another slot of the same subject. So a subject that provides any subset of slots
// has each of them checked, and an error shared by two slots cannot cancel out. Inputs come from
// every regime (support/regimes.hpp): axes, zero components, tiny and huge magnitudes, and for
// so(n) every dimension n = 2..6.
//
// Tolerances: exact (0) in rationals; in floats k eps * scale, scale the product of the sizes of
// the inputs that are multiplied, k the number of roundings of the formula on both sides.
#include "properties/registry.hpp"
#include "properties/support/coordinates.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_definitions_algebra {
namespace {

// (2.11): hat(v) is the matrix with hat(v)_jk = -v_i eps_ijk.
template <class T>
void definition_hat(const Subject<T>& s) {
  const Vec3<T> v = *gen::regime_vec3<T>().as("v");
  showing_inputs(
      [&] { return named("v", v); },
      [&] { require_close("slot hat: hat(v) = (-v_i eps_ijk), (2.11)", s.hat(v), truth::skew_of(v), norm_inf(v), 0); });
}

// vee inverts (2.11) on skew matrices.
template <class T>
void definition_vee(const Subject<T>& s) {
  const Vec3<T> v = *gen::regime_vec3<T>().as("v");
  const Mat3<T> S = truth::skew_of(v);
  showing_inputs(
      [&] { return named("S", S); },
      [&] { require_close("slot vee: vee(S) = (S_32, S_13, S_21) for skew S, (2.11)", s.vee(S), v, norm_inf(v), 0); });
}

// (2.15): <A, B> = tr(A^T B) / 2, for any n x n matrices (n = 2..6), not only skew ones. The sum
// has n^2 products: k = 2 n^2 + 2.
template <class T>
void definition_pairing(const Subject<T>& s) {
  const int n = *gen::uniform(2, 7).as("n");
  const int e = *gen::uniform(-30, 31).as("e (a scale 2^e)");
  const MatX<T> A = (*gen::mat<T>(n, n).as("A / 2^e") * gen::pow2<T>(e)).eval();
  const MatX<T> B = *gen::uniform(0, 2).as("B in thirds (1: yes)") ? MatX<T>(*gen::mat<T>(n, n).as("3 B") / T(3))
                                                                   : MatX<T>(*gen::mat<T>(n, n).as("B"));
  showing_inputs([&] { return named("A", A) + named("B", B); },
                 [&] {
                   require_close("slot pairing: <A, B> = tr(A^T B)/2, (2.15)", s.pairing(A, B),
                                 T(A.cwiseProduct(B).sum() / T(2)), T(norm_inf(A) * norm_inf(B) * T(n * n)),
                                 2.0 * n * n + 2);
                 });
}

// The coordinates of so(n) and of the generic algebras are the student's (
// support/coordinates.hpp): hat_n and lie_hat define them, every coordinate slot is checked in
// them, and a slot without its hat in the documented ones (`geomech slots`).

// A note for the report when the student's coordinates are not the documented ones.
template <class T>
void note_coordinates(const coords::Basis<T>& b, const std::string& algebra) {
  if (!b.documented)
    record_note(
        "checked in your coordinates of " + algebra + ", from " + b.origin + ": " + b.describe() +
        " (the documented ones: " +
        (b.skew ? coords::documented_so_n<T>(b.n) : coords::documented_algebra<T>(LieAlgebraId::sl2)).describe() +
        "); the notes leave this choice open");
}

std::string n_text(int n) { return " (n = " + std::to_string(n) + ")"; }

// hat_n for every n = 2..6: hat_n(e_k, n) are plus or minus the elementary skew matrices, each
// entry once (coordinates of so(n), in an order and with signs of the student's choosing), and
// hat_n is linear: hat_n(v, n) = sum v_k hat_n(e_k, n).
template <class T>
void definition_hat_n(const Subject<T>& s) {
  const int n = *gen::uniform(2, 7).as("n");
  const VecX<T> v = *gen::regime_vec<T>(truth::so_dimension(n)).as("v");
  std::string why;
  const auto basis = coords::learned_so_n(s, n, &why);
  showing_inputs(
      [&] { return named("v", v) + "    n = " + std::to_string(n) + "\n"; },
      [&] {
        require("slot hat_n: hat_n(e_k, n) are coordinates of so(n): one entry above the diagonal each" + n_text(n),
                basis.has_value(), why);
        require_close("slot hat_n: hat_n(v, n) = sum_k v_k hat_n(e_k, n), the so(n) matrix of v" + n_text(n),
                      s.hat_n(v, n), basis->matrix(v), norm_inf(v), 0);
      });
  note_coordinates(*basis, "so(" + std::to_string(n) + ")");
}

// vee_n reads back the coordinates of hat_n (the student's, or the documented ones without hat_n).
template <class T>
void definition_vee_n(const Subject<T>& s) {
  const int n = *gen::uniform(2, 7).as("n");
  const VecX<T> v = *gen::regime_vec<T>(truth::so_dimension(n)).as("v");
  const coords::Basis<T> basis = coords::so_n_for(s, n);
  const MatX<T> m = basis.matrix(v);
  std::string hint;
  if (basis.documented && !s.hat_n) {
    hint = coords::basis_hint<T>("vee_n", "hat_n", "so(" + std::to_string(n) + ")", basis,
                                 {coords::basis_of_vee<T>(
                                     n, [&](const MatX<T>& x) { return VecX<T>(s.vee_n(x)); }, "your vee_n")},
                                 [&](const coords::Basis<T>& alt) { return VecX<T>(s.vee_n(alt.matrix(v))) == v; });
  }
  showing_inputs([&] { return named("m", m); },
                 [&] {
                   try {
                     require_close(
                         "slot vee_n: vee_n(m) are the so(n) coordinates of m, in " + basis.name() + n_text(n),
                         s.vee_n(m), v, norm_inf(v), 0);
                   } catch (rc::detail::CaseResult& r) {
                     r.description = hint + r.description;
                     throw;
                   }
                 });
  note_coordinates(basis, "so(" + std::to_string(n) + ")");
}

LieAlgebraId draw_algebra() {
  static const LieAlgebraId all[] = {LieAlgebraId::so3, LieAlgebraId::so4, LieAlgebraId::sl2};
  return all[*gen::uniform(0, 3).as("the algebra (0 so(3), 1 so(4), 2 sl(2, R))")];
}

// lie_hat: lie_hat(g, e_k) is a basis of g (so(3), so(4): coordinates as for hat_n; sl(2, R): any
// basis of traceless matrices), and lie_hat is linear in it.
template <class T>
void definition_lie_hat(const Subject<T>& s) {
  const LieAlgebraId g = draw_algebra();
  const VecX<T> x = *gen::regime_vec<T>(truth::algebra_dimension(g)).as("x");
  std::string why;
  const auto basis = coords::learned_algebra(s, g, &why);
  showing_inputs([&] { return std::string("    g = ") + lie_algebra_name(g) + "\n" + named("x", x); },
                 [&] {
                   require(std::string("slot lie_hat: lie_hat(g, e_k) is a basis of ") + lie_algebra_name(g),
                           basis.has_value(), why);
                   require_close(
                       std::string("slot lie_hat: lie_hat(g, x) = sum_k x_k lie_hat(g, e_k), the matrix of x in ") +
                           lie_algebra_name(g),
                       s.lie_hat(g, x), basis->matrix(x), T(norm_inf(x) * basis->condition),
                       basis->skew ? 0.0 : 4.0 * 3);
                 });
  note_coordinates(*basis, lie_algebra_name(g));
}

template <class T>
void definition_lie_vee(const Subject<T>& s) {
  const LieAlgebraId g = draw_algebra();
  const VecX<T> x = *gen::regime_vec<T>(truth::algebra_dimension(g)).as("x");
  const coords::Basis<T> basis = coords::algebra_for(s, g);
  const MatX<T> m = basis.matrix(x);
  std::string hint;
  if (basis.documented && !s.lie_hat && g != LieAlgebraId::sl2)
    hint =
        coords::basis_hint<T>("lie_vee", "lie_hat", lie_algebra_name(g), basis,
                              {coords::basis_of_vee<T>(
                                  basis.n, [&](const MatX<T>& y) { return VecX<T>(s.lie_vee(g, y)); }, "your lie_vee")},
                              [&](const coords::Basis<T>& alt) { return VecX<T>(s.lie_vee(g, alt.matrix(x))) == x; });
  showing_inputs([&] { return std::string("    g = ") + lie_algebra_name(g) + "\n" + named("m", m); },
                 [&] {
                   try {
                     require_close(std::string("slot lie_vee: the coordinates of m in ") + lie_algebra_name(g) +
                                       ", in " + basis.name(),
                                   s.lie_vee(g, m), x, T(norm_inf(x) * basis.condition), 4.0 * basis.dimension());
                   } catch (rc::detail::CaseResult& r) {
                     r.description = hint + r.description;
                     throw;
                   }
                 });
  note_coordinates(basis, lie_algebra_name(g));
}

// ad*_xi mu from its definition <ad*_xi mu, eta> = <mu, [xi, eta]> (Theorem 1.1 (iv)) in a basis:
// component k is mu . coords([xi, e_k]), the pairing of g* with g being that of the dual basis.
template <class T>
VecX<T> ad_star_in(const coords::Basis<T>& b, const VecX<T>& xi, const VecX<T>& mu) {
  const int d = b.dimension();
  const MatX<T> X = b.matrix(xi);
  VecX<T> out(d);
  for (int k = 0; k < d; ++k) out(k) = mu.dot(b.coordinates(MatX<T>(X * b.E[k] - b.E[k] * X)));
  return out;
}

// Theorem 1.1 (iv) in the student's basis of g (from lie_hat; documented without it). Both sides
// sum d n products of |xi| |mu| (d the dimension, n the matrix size): k = 4 d n, times the basis's
// condition for a basis whose coordinates are not exact.
template <class T>
void definition_ad_star(const Subject<T>& s) {
  const LieAlgebraId g = draw_algebra();
  const int d = truth::algebra_dimension(g);
  const VecX<T> xi = *gen::regime_vec<T>(d).as("xi");
  const VecX<T> mu = *gen::regime_vec<T>(d).as("mu");
  const coords::Basis<T> basis = coords::algebra_for(s, g);
  const int n = basis.n;
  const T scale = T(norm_inf(xi) * norm_inf(mu) * basis.condition);
  std::string hint;
  if (basis.documented && !s.lie_hat && g != LieAlgebraId::sl2) {
    std::vector<std::optional<coords::Basis<T>>> alts;
    if (s.lie_vee)
      alts.push_back(coords::basis_of_vee<T>(
          n, [&](const MatX<T>& y) { return VecX<T>(s.lie_vee(g, y)); }, "your lie_vee"));
    if (s.vee_n)
      alts.push_back(coords::basis_of_vee<T>(
          n, [&](const MatX<T>& y) { return VecX<T>(s.vee_n(y)); }, "your vee_n"));
    if (auto b = coords::learned_so_n(s, n)) alts.push_back(b);
    hint =
        coords::basis_hint<T>("ad_star", "lie_hat", lie_algebra_name(g), basis, alts, [&](const coords::Basis<T>& alt) {
          return max_abs(VecX<T>(s.ad_star(g, xi, mu) - ad_star_in(alt, xi, mu))) <= T(4.0 * d * n) * eps<T>() * scale;
        });
  }
  showing_inputs(
      [&] { return std::string("    g = ") + lie_algebra_name(g) + "\n" + named("xi", xi) + named("mu", mu); },
      [&] {
        try {
          require_close(std::string("slot ad_star: <ad*_xi mu, e_k> = <mu, [xi, e_k]> in ") + lie_algebra_name(g) +
                            ", in " + basis.name(),
                        s.ad_star(g, xi, mu), ad_star_in(basis, xi, mu), scale, 4.0 * d * n);
        } catch (rc::detail::CaseResult& r) {
          r.description = hint + r.description;
          throw;
        }
      });
  note_coordinates(basis, lie_algebra_name(g));
}

// The so(4) = R^6 slots are read in the coordinates of hat_n(., 4) (documented without it); a failure
// in the documented ones is explained when the coordinates of the student's vee_n or lie_hat on
// so(4) make it right.
template <class T>
std::vector<std::optional<coords::Basis<T>>> so4_alternatives(const Subject<T>& s) {
  std::vector<std::optional<coords::Basis<T>>> alts;
  if (s.vee_n)
    alts.push_back(coords::basis_of_vee<T>(
        4, [&](const MatX<T>& y) { return VecX<T>(s.vee_n(y)); }, "your vee_n"));
  if (auto b = coords::learned_algebra(s, LieAlgebraId::so4)) alts.push_back(b);
  if (s.lie_vee)
    alts.push_back(coords::basis_of_vee<T>(
        4, [&](const MatX<T>& y) { return VecX<T>(s.lie_vee(LieAlgebraId::so4, y)); }, "your lie_vee on so(4)"));
  return alts;
}

// SO(4) exercise: the bracket of R^6 is the commutator read through hat_4.
template <class T>
void definition_so4_bracket_R6(const Subject<T>& s) {
  const VecX<T> a = *gen::regime_vec<T>(6).as("a");
  const VecX<T> b = *gen::regime_vec<T>(6).as("b");
  const coords::Basis<T> basis = coords::so_n_for(s, 4);
  auto bracket_in = [&](const coords::Basis<T>& B) {
    const MatX<T> A = B.matrix(a), Bm = B.matrix(b);
    return B.coordinates(MatX<T>(A * Bm - Bm * A));
  };
  const T scale = T(norm_inf(a) * norm_inf(b));
  std::string hint;
  if (basis.documented && !s.hat_n)
    hint = coords::basis_hint<T>(
        "so4_bracket_R6", "hat_n", "so(4)", basis, so4_alternatives(s), [&](const coords::Basis<T>& alt) {
          return max_abs(VecX<T>(VecX<T>(s.so4_bracket_R6(Vec6<T>(a), Vec6<T>(b))) - bracket_in(alt))) <=
                 T(16) * eps<T>() * scale;
        });
  showing_inputs([&] { return named("a", a) + named("b", b); },
                 [&] {
                   try {
                     require_close("slot so4_bracket_R6: [a, b] = vee_4([hat_4(a), hat_4(b)]), in " + basis.name(),
                                   VecX<T>(s.so4_bracket_R6(Vec6<T>(a), Vec6<T>(b))), bracket_in(basis), scale, 16);
                   } catch (rc::detail::CaseResult& r) {
                     r.description = hint + r.description;
                     throw;
                   }
                 });
  note_coordinates(basis, "so(4)");
}

template <class T>
void definition_ad_star_so4_R6(const Subject<T>& s) {
  const VecX<T> xi = *gen::regime_vec<T>(6).as("xi");
  const VecX<T> mu = *gen::regime_vec<T>(6).as("mu");
  const coords::Basis<T> basis = coords::so_n_for(s, 4);
  const T scale = T(norm_inf(xi) * norm_inf(mu));
  std::string hint;
  if (basis.documented && !s.hat_n)
    hint = coords::basis_hint<T>(
        "ad_star_so4_R6", "hat_n", "so(4)", basis, so4_alternatives(s), [&](const coords::Basis<T>& alt) {
          return max_abs(VecX<T>(VecX<T>(s.ad_star_so4_R6(Vec6<T>(xi), Vec6<T>(mu))) - ad_star_in(alt, xi, mu))) <=
                 T(96) * eps<T>() * scale;
        });
  showing_inputs([&] { return named("xi", xi) + named("mu", mu); },
                 [&] {
                   try {
                     require_close(
                         "slot ad_star_so4_R6: <ad*_xi mu, e_k> = <mu, [xi, e_k]> in so(4) = R^6, in " + basis.name(),
                         VecX<T>(s.ad_star_so4_R6(Vec6<T>(xi), Vec6<T>(mu))), ad_star_in(basis, xi, mu), scale, 96);
                   } catch (rc::detail::CaseResult& r) {
                     r.description = hint + r.description;
                     throw;
                   }
                 });
  note_coordinates(basis, "so(4)");
}

// The triple product -a . (b x c) of the brackets (3.6), (2.23), (3.13): six products, k = 8.
template <class T>
T minus_triple(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return -a.dot(truth::cross(b, c));
}

template <class T>
T size3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return norm_inf(a) * norm_inf(b) * norm_inf(c);
}

// (3.6): {f, h}(Pi) = -Pi . (df x dh).
template <class T>
void definition_lie_poisson_3_6(const Subject<T>& s) {
  const Vec3<T> Pi = *gen::regime_vec3<T>().as("Pi"), df = *gen::regime_vec3<T>().as("df/dPi"),
                dh = *gen::regime_vec3<T>().as("dh/dPi");
  showing_inputs([&] { return named("Pi", Pi) + named("df/dPi", df) + named("dh/dPi", dh); },
                 [&] {
                   require_close("slot lie_poisson_3_6: {f, h} = -Pi . (df x dh), (3.6)", s.lie_poisson_3_6(Pi, df, dh),
                                 minus_triple(Pi, df, dh), size3(Pi, df, dh), 8);
                 });
}

// (2.23): {f, h} = -<Pi, [df, dh]> with skew matrices; in vectors, -Pi . (df x dh) by (2.25).
// The matrix form sums more products: k = 24.
template <class T>
void definition_lie_poisson_2_23(const Subject<T>& s) {
  const Vec3<T> Pi = *gen::regime_vec3<T>().as("Pi"), df = *gen::regime_vec3<T>().as("df/dPi"),
                dh = *gen::regime_vec3<T>().as("dh/dPi");
  const Mat3<T> P = truth::skew_of(Pi), F = truth::skew_of(df), H = truth::skew_of(dh);
  showing_inputs([&] { return named("Pi_hat", P) + named("df_hat", F) + named("dh_hat", H); },
                 [&] {
                   require_close("slot lie_poisson_2_23: {f, h} = -<Pi, [df, dh]> = -Pi . (df x dh), (2.23)",
                                 s.lie_poisson_2_23(P, F, H), minus_triple(Pi, df, dh), size3(Pi, df, dh), 24);
                 });
}

// (3.13): {f, h} = -grad c . (grad f x grad h).
template <class T>
void definition_nambu_3_13(const Subject<T>& s) {
  const Vec3<T> dc = *gen::regime_vec3<T>().as("grad c"), df = *gen::regime_vec3<T>().as("grad f"),
                dh = *gen::regime_vec3<T>().as("grad h");
  showing_inputs([&] { return named("grad c", dc) + named("grad f", df) + named("grad h", dh); },
                 [&] {
                   require_close("slot nambu_3_13: {f, h} = -grad c . (grad f x grad h), (3.13)",
                                 s.nambu_3_13(dc, df, dh), minus_triple(dc, df, dh), size3(dc, df, dh), 8);
                 });
}

// (3.14): dx/dt = grad c x grad h.
template <class T>
void definition_nambu_motion_3_14(const Subject<T>& s) {
  const Vec3<T> dc = *gen::regime_vec3<T>().as("grad c"), dh = *gen::regime_vec3<T>().as("grad h");
  showing_inputs([&] { return named("grad c", dc) + named("grad h", dh); },
                 [&] {
                   require_close("slot nambu_motion_3_14: dx/dt = grad c x grad h, (3.14)", s.nambu_motion_3_14(dc, dh),
                                 truth::cross(dc, dh), T(norm_inf(dc) * norm_inf(dh)), 4);
                 });
}

// Section 3.5: {f, h} = df/dq . dh/dp - df/dp . dh/dq, so that {q_i, p_j} = delta_ij.
template <class T>
void definition_canonical_bracket(const Subject<T>& s) {
  const Vec3<T> fq = *gen::regime_vec3<T>().as("fq"), fp = *gen::regime_vec3<T>().as("fp");
  const Vec3<T> hq = *gen::regime_vec3<T>().as("hq"), hp = *gen::regime_vec3<T>().as("hp");
  showing_inputs([&] { return named("df/dq", fq) + named("df/dp", fp) + named("dh/dq", hq) + named("dh/dp", hp); },
                 [&] {
                   require_close("slot canonical_bracket: {f, h} = df/dq . dh/dp - df/dp . dh/dq",
                                 s.canonical_bracket(fq, fp, hq, hp), T(fq.dot(hp) - fp.dot(hq)),
                                 T(norm_inf(fq) * norm_inf(hp) + norm_inf(fp) * norm_inf(hq)), 8);
                 });
}

// The momentum-map section: J(q, p) = p x q, the cotangent lift of SO(3) acting on R^3.
template <class T>
void definition_momentum_map(const Subject<T>& s) {
  const Vec3<T> q = *gen::regime_vec3<T>().as("q"), p = *gen::regime_vec3<T>().as("p");
  showing_inputs([&] { return named("q", q) + named("p", p); },
                 [&] {
                   require_close("slot momentum_map: J(q, p) = p x q (the momentum-map section)", s.momentum_map(q, p),
                                 truth::cross(p, q), T(norm_inf(q) * norm_inf(p)), 4);
                 });
}

}  // namespace

#define GM_DEFINITION(slot, entry, statement, tolerance_class, ...) \
  GM_PROPERTY(definition_##slot, all_scalars,                       \
              {.spec = entry,                                       \
               .title = "slot " #slot " alone: " statement,         \
               .tolerance = ToleranceClass::tolerance_class,        \
               .needs = {#slot},                                    \
               .negative_controls = {__VA_ARGS__},                  \
               .cases = {.d = 200, .mp = 100, .q = 50}})

GM_DEFINITION(hat, "s2.hat-map", "hat(v) = (-v_i eps_ijk), (2.11), on axes, zeros, tiny and huge v", Exact,
              "hat_transposed", "hat_scaled");
GM_DEFINITION(vee, "s2.hat-map", "vee inverts (2.11) on skew matrices", Exact, "vee_reads_upper_triangle");
GM_DEFINITION(pairing, "s2.trace-pairing", "<A, B> = tr(A^T B)/2 for n x n matrices, n = 2..6", Exact,
              "pairing_without_half", "pairing_upper_triangle");
GM_DEFINITION(hat_n, "s1.so4-hat",
              "hat_n(v, n) is linear in coordinates of so(n), n = 2..6 (their order and signs the student's)", Exact,
              "hat_n_written_for_so4");
GM_DEFINITION(vee_n, "s1.so4-hat", "vee_n inverts hat_n for n = 2..6 (in hat_n's coordinates, documented without it)",
              Exact, "vee_n_written_for_so4");
GM_DEFINITION(lie_hat, "s1.ad-star-coordinates",
              "coordinates to matrices: a basis of so(3), so(4), sl(2, R) (of the student's choosing)", Exact,
              "lie_hat_sl2_not_traceless");
GM_DEFINITION(lie_vee, "s1.ad-star-coordinates",
              "matrices to coordinates in so(3), so(4), sl(2, R), in lie_hat's basis", Exact, "lie_vee_sl2_transposed",
              "lie_hat_sl2_transposed");
GM_DEFINITION(ad_star, "s1.ad-star-definition",
              "<ad*_xi mu, eta> = <mu, [xi, eta]> on so(3), so(4), sl(2, R), in lie_hat's basis", Exact,
              "ad_star_is_ad", "ad_star_sign_flipped", "ad_star_sl2_transpose_pairing");
GM_DEFINITION(so4_bracket_R6, "s1.so4-hat", "[a, b] = vee_4([hat_4 a, hat_4 b]) in hat_n's coordinates", Exact,
              "so4_bracket_R6_sign_slip");
GM_DEFINITION(ad_star_so4_R6, "s1.so4-ep-r6", "ad* of so(4) = R^6 from its definition, in hat_n's coordinates", Exact,
              "ad_star_so4_R6_sign_slip");
GM_DEFINITION(lie_poisson_3_6, "s3.lie-poisson-euler", "{f, h} = -Pi . (df x dh), (3.6)", Exact,
              "lie_poisson_3_6_sign_flipped", "lie_poisson_3_6_cyclic_index_slip");
GM_DEFINITION(lie_poisson_2_23, "s2.lie-poisson-matrix", "{f, h} = -<Pi, [df, dh]>, (2.23)", Exact,
              "lie_poisson_2_23_one_sided_product", "lie_poisson_2_23_sign_flipped");
GM_DEFINITION(nambu_3_13, "s3.nambu-motion", "{f, h} = -grad c . (grad f x grad h), (3.13)", Exact,
              "nambu_3_13_sign_flipped", "nambu_3_13_cyclic_index_slip");
GM_DEFINITION(nambu_motion_3_14, "s3.nambu-motion", "dx/dt = grad c x grad h, (3.14)", Exact,
              "nambu_motion_3_14_reversed", "nambu_motion_3_14_half_cross");
GM_DEFINITION(canonical_bracket, "s3.clebsch-poisson", "{f, h} = f_q . h_p - f_p . h_q on T*R^3", Exact,
              "canonical_bracket_sign_flipped", "canonical_bracket_symmetric");
GM_DEFINITION(momentum_map, "mm.hamiltonian-action", "J(q, p) = p x q", Exact, "momentum_map_reversed",
              "momentum_map_sign_slip");

#undef GM_DEFINITION
}  // namespace properties_definitions_algebra
}  // namespace gm
