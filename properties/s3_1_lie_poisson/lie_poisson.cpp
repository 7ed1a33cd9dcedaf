// The Lie-Poisson bracket of the rigid body: its two forms agree through the hat map (2.25), (3.10);
// the coordinate brackets (3.11)/(3.12); |Pi|^2 is a Casimir; it generates Euler's equations in
// matrix form (2.22), (2.23) and in R^3 form (2.26), (3.6)-(3.8).
//
// Derivatives of the subject's Hamiltonian are central differences with unit steps, exact for
// quadratic functions (truth::gradient_of_quadratic). In floats they round a few times on values
// of h near Pi, whose size is Hs = (|Pi| + 1)^2 / min I; as in properties/s3_1_lie_poisson/legendre.cpp, k = 16
// covers the gradient (two evaluations of a sum of three quotients, a difference, a halving).
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/poisson_axioms.hpp"
#include "properties/support/polynomial.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

namespace gm {
namespace properties_lie_poisson {
namespace {

inline constexpr int kGradientOfH = 16;  // rounding chain of a central-difference gradient of h

template <class T>
Vec3<T> unit(int i) {
  Vec3<T> e = Vec3<T>::Zero();
  e(i) = T(1);
  return e;
}

template <class T>
T hamiltonian_scale(const Vec3<T>& I, const Vec3<T>& P) {
  return T((norm_inf(P) + T(1)) * (norm_inf(P) + T(1)) / I.minCoeff());
}

// (3.11), transcribed row by row from the table of the notes, and (3.12): {Pi_i, Pi_j} =
// -eps_ijk Pi_k = Pi_hat_ij, in the R^3 form (3.6) and in the matrix form (3.10) with the
// coordinate functions' gradients e_i (as skew matrices hat(e_i)).
// Rounding: one triple product (5) of size 6 |Pi|; the matrix form 13 roundings of size 27 |Pi|.
template <class T>
void lie_poisson_table_3_11(const Subject<T>& s) {
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  Mat3<T> table;
  table << T(0), -P(2), P(1), P(2), T(0), -P(0), -P(1), P(0), T(0);
  const Mat3<T> P_hat = truth::skew_of(P);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T eps_P(0);
      for (int k = 0; k < 3; ++k) eps_P -= T(truth::levi_civita(i, j, k)) * P(k);
      const std::string ij = "{Pi_" + std::to_string(i + 1) + ", Pi_" + std::to_string(j + 1) + "}";
      require_close("(3.11)/(3.12): table entry = -eps_ijk Pi_k = Pi_hat_ij for " + ij, table(i, j), eps_P, T(0), 0);
      require_close("(3.11)/(3.12): table entry = Pi_hat_ij for " + ij, table(i, j), P_hat(i, j), T(0), 0);
      require_close("(3.6) gives the table (3.11) for " + ij, s.lie_poisson_3_6(P, unit<T>(i), unit<T>(j)), table(i, j),
                    T(T(6) * norm_inf(P)), kTripleProductOps);
      require_close("(3.10) gives the table (3.11) for " + ij,
                    s.lie_poisson_2_23(P_hat, truth::skew_of(unit<T>(i)), truth::skew_of(unit<T>(j))), table(i, j),
                    T(T(27) * norm_inf(P)), 13);
    }
}

// |Pi|^2 is a Casimir: {|Pi|^2, F} = 0 for every F (here: polynomials of degree <= 4), in both
// forms of the bracket.
template <class T>
void lie_poisson_casimir(const Subject<T>& s) {
  Polynomial<T> C(3);
  for (int i = 0; i < 3; ++i) C = C + Polynomial<T>::coordinate(3, i) * Polynomial<T>::coordinate(3, i);
  const auto F = *gen::polynomial<T>(3).as("F");
  const VecX<T> x = *gen::point<T>(3).as("x");
  PointBracket<T> r3;
  r3.name = "lie_poisson_3_6";
  r3.at = [&s](const VecX<T>& y, const VecX<T>& a, const VecX<T>& b) {
    return s.lie_poisson_3_6(Vec3<T>(y), Vec3<T>(a), Vec3<T>(b));
  };
  r3.bound = [](const T& R, const T& a, const T& b) { return triple_product_bound(R, a, b); };
  r3.ops = kTripleProductOps;
  PointBracket<T> matrix = r3;
  matrix.name = "lie_poisson_2_23";
  matrix.at = [&s](const VecX<T>& y, const VecX<T>& a, const VecX<T>& b) {
    return s.lie_poisson_2_23(truth::skew_of<T>(Vec3<T>(y)), truth::skew_of<T>(Vec3<T>(a)),
                              truth::skew_of<T>(Vec3<T>(b)));
  };
  matrix.bound = [](const T& R, const T& a, const T& b) { return T(T(27) * R * a * b); };
  matrix.ops = 13;  // see lie_poisson_axioms.cpp
  check_casimir(r3, "(3.6): {|Pi|^2, F} = 0", C, F, x);
  check_casimir(matrix, "(3.10): {|Pi|^2, F} = 0", C, F, x);
}

// (2.25): through the hat map, -<Pi_hat, [df_hat, dh_hat]> = -df . dh x Pi = -Pi . df x dh;
// (2.26): for the coordinate functions f = Pi_i, {Pi, h} = -dh/dPi x Pi, for any h (a random
// polynomial). Scales: triple products of the inputs' sizes; k = 13 (matrix form) + 5.
template <class T>
void lie_poisson_hat_map_2_25(const Subject<T>& s) {
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const Vec3<T> df = *gen::vec3<T>().as("df/dPi");
  const Vec3<T> dh = *gen::vec3<T>().as("dh/dPi");
  const T scale = T(27) * norm_inf(P) * norm_inf(df) * norm_inf(dh);
  const T r3 = s.lie_poisson_3_6(P, df, dh);
  require_close("(2.25): -<Pi_hat, [df_hat, dh_hat]> = -Pi . df x dh",
                s.lie_poisson_2_23(truth::skew_of(P), truth::skew_of(df), truth::skew_of(dh)), r3, scale, 18);
  require_close("(2.25): -Pi . df x dh = -df . dh x Pi", r3, T(-df.dot(truth::cross(dh, P))), scale, 10);
  const auto h = *gen::polynomial<T>(3).as("h");
  const VecX<T> x = *gen::point<T>(3).as("x");
  const Vec3<T> X(x);
  const Vec3<T> grad_h(h.gradient(x));
  const Vec3<T> expected = (-truth::cross(grad_h, X)).eval();
  const T R = norm_inf(x);
  for (int i = 0; i < 3; ++i)
    require_close("(2.26): {Pi_" + std::to_string(i + 1) + ", h} = (-dh/dPi x Pi)_" + std::to_string(i + 1),
                  s.lie_poisson_3_6(X, unit<T>(i), grad_h), expected(i), T(T(6) * R * h.gradient_bound(R)),
                  kTripleProductOps + 2 + h.eval_ops());
}

// (2.22) and (2.23): the matrix Euler equation is dPi/dt = -[dh/dPi, Pi], with dh/dPi the gradient
// of the subject's matrix Hamiltonian (2.21) along the basis hat(e_k) (orthonormal for (2.15));
// and a polynomial f(Pi) changes along it by df/dt = grad f . dPi/dt (chain rule)
//   = -<df/dPi, [dh/dPi, Pi]> = -<Pi, [df/dPi, dh/dPi]> = {f, h}.
// Sizes: |dh/dPi| <= Hs, its rounding <= 16 eps Hs; the commutator and pairing multiply by |Pi|
// (or |grad f|) and add 4 + 13 roundings; euler_matrix_2_12 itself rounds ~ 5 times on
// |Pi|^2 / min I <= |Pi| Hs.
template <class T>
void lie_poisson_matrix_2_22_2_23(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const VecX<T> x = *gen::point<T>(3).as("x");
  const Vec3<T> P(x);
  const Mat3<T> P_hat = truth::skew_of(P);
  const Vec3<T> dh =
      truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return s.hamiltonian_2_21(I, truth::skew_of(y)); }, P);
  const Mat3<T> dh_hat = truth::skew_of(dh);
  const T Hs = hamiltonian_scale(I, P);
  const Mat3<T> P_dot = s.euler_matrix_2_12(I, P_hat);
  require_close("(2.22): dPi/dt = -[dh/dPi, Pi]", P_dot, (-(dh_hat * P_hat - P_hat * dh_hat)).eval(),
                T(T(6) * norm_inf(P) * Hs), 2 * kGradientOfH + 4 + 5);

  const auto f = *gen::polynomial<T>(3).as("f");
  const Vec3<T> df(f.gradient(x));
  const Mat3<T> df_hat = truth::skew_of(df);
  const T R = norm_inf(x);
  const T scale = T(27) * f.gradient_bound(R) * R * Hs;
  const int k = 2 * kGradientOfH + 13 + 4 + f.eval_ops();
  const T f_dot = df.dot(Vec3<T>(P_dot(2, 1), P_dot(0, 2), P_dot(1, 0)));
  const T middle = -s.pairing(MatX<T>(df_hat), MatX<T>((dh_hat * P_hat - P_hat * dh_hat).eval()));
  require_close("(2.23): df/dt = grad f . dPi/dt = -<df/dPi, [dh/dPi, Pi]>", f_dot, middle, scale, k);
  require_close("(2.23): -<df/dPi, [dh/dPi, Pi]> = -<Pi, [df/dPi, dh/dPi]> =: {f, h}", middle,
                s.lie_poisson_2_23(P_hat, df_hat, dh_hat), scale, k);
}

// (3.6)-(3.8): with h of (3.4), dPi/dt = {Pi, h} = Pi x dh/dPi is (3.7) and (3.8):
// {Pi_i, h} = -Pi . e_i x dh/dPi = (Pi x dh/dPi)_i. Sizes: |Pi| Hs; k = the gradient (twice, as it
// enters two products) + the triple product + the (3.7)/(3.8) side (16, as in euler_forms.cpp).
template <class T>
void lie_poisson_generates_euler_3_7(const Subject<T>& s) {
  const Vec3<T> I = *gen::inertia<T>().as("I");
  const Vec3<T> P = *gen::vec3<T>().as("Pi");
  const Vec3<T> dh = truth::gradient_of_quadratic<T>([&](const Vec3<T>& y) { return s.hamiltonian_3_4(I, y); }, P);
  const T scale = T(6) * norm_inf(P) * hamiltonian_scale(I, P);
  const int k = 2 * kGradientOfH + kTripleProductOps + 16;
  Vec3<T> bracket;
  for (int i = 0; i < 3; ++i) bracket(i) = s.lie_poisson_3_6(P, unit<T>(i), dh);
  require_close("(3.6): {Pi, h} = Pi x dh/dPi", bracket, truth::cross(P, dh), scale, k);
  require_close("(3.6)-(3.7): {Pi, h} = euler_3_7(I, Pi)", bracket, s.euler_3_7(I, P), scale, k);
  require_close("(3.6)-(3.8): {Pi, h} = euler_3_8(I, Pi)", bracket, s.euler_3_8(I, P), scale, k);
}

}  // namespace

GM_PROPERTY(lie_poisson_table_3_11, all_scalars,
            {.spec = "s3.lie-poisson-table",
             .title = "(3.11)/(3.12): {Pi_i, Pi_j} = -eps_ijk Pi_k = Pi_hat_ij, in the forms (3.6) and (3.10)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6", "lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_3_6_sign_flipped", "lie_poisson_2_23_one_sided_product"}});

GM_PROPERTY(lie_poisson_casimir, all_scalars,
            {.spec = "s3.casimir",
             .title = "|Pi|^2 is a Casimir: {|Pi|^2, F} = 0 for polynomial F, in the forms (3.6) and (3.10)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"lie_poisson_3_6", "lie_poisson_2_23"},
             .negative_controls = {"lie_poisson_3_6_cyclic_index_slip", "lie_poisson_2_23_cyclic_index_slip"}});

GM_PROPERTY(
    lie_poisson_hat_map_2_25, all_scalars,
    {.spec = "s2.lie-poisson-r3",
     .title = "(2.25): the matrix bracket (2.23) is -Pi . df x dh through the hat map; (2.26): {Pi, h} = -dh x Pi",
     .tolerance = ToleranceClass::Exact,
     .needs = {"lie_poisson_3_6", "lie_poisson_2_23"},
     .negative_controls = {"lie_poisson_2_23_one_sided_product", "lie_poisson_3_6_sign_flipped"}});

GM_PROPERTY(lie_poisson_matrix_2_22_2_23, all_scalars,
            {.spec = "s2.lie-poisson-matrix",
             .title = "(2.22): dPi/dt = -[dh/dPi, Pi]; (2.23): df/dt = -<Pi, [df/dPi, dh/dPi]> = {f, h}",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hamiltonian_2_21", "euler_matrix_2_12", "pairing", "lie_poisson_2_23"},
             .negative_controls = {"euler_matrix_commutator_sign", "lie_poisson_2_23_one_sided_product",
                                   "hamiltonian_2_21_sign_flipped"}});

GM_PROPERTY(lie_poisson_generates_euler_3_7, all_scalars,
            {.spec = "s3.lie-poisson-euler",
             .title = "(3.6)-(3.8): with h of (3.4), dPi/dt = {Pi, h} = Pi x dh/dPi is (3.7) and (3.8)",
             .tolerance = ToleranceClass::Exact,
             .needs = {"hamiltonian_3_4", "lie_poisson_3_6", "euler_3_7", "euler_3_8"},
             .negative_controls = {"lie_poisson_3_6_sign_flipped", "hamiltonian_with_I"}});

}  // namespace properties_lie_poisson
}  // namespace gm
