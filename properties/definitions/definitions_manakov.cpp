// Manakov's slots checked on their own, for n = 3..6 and for non-diagonal
// A = R D R^T with exact rational rotations R (code right only for a diagonal A used to
// pass, since all but one Manakov property drew diagonal A). Each property needs one slot and
// compares it with (2.34), Proposition 2.4 or (3.23) written here from the definition.
//
// Tolerances: exact (0) in rationals. In floats, solving A X + X A = M loses up to the condition
// of X -> A X + X A, which for A = R diag(d) R^T is spread = max d / min d; the scales below
// carry that factor where a property compares an Omega recovered from M.
#include "properties/registry.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/tolerance.hpp"

namespace gm {
namespace properties_definitions_manakov {
namespace {

template <class T>
MatX<T> commutator_of(const MatX<T>& X, const MatX<T>& Y) {
  return X * Y - Y * X;
}

// A skew Omega of size n, scaled by 2^e (e in [-20, 20]) half of the time, and in thirds (not
// representable in double) a quarter of the time.
template <class T>
MatX<T> draw_omega(int n) {
  const int e = *gen::uniform(0, 2).as("Omega scaled (1: yes)") ? *gen::uniform(-20, 21).as("e (a scale 2^e)") : 0;
  const bool thirds = *gen::uniform(0, 4).as("Omega in thirds (3: yes)") == 3;
  return (*gen::skew<T>(n).as("Omega / 2^e (before the thirds)") * gen::pow2<T>(e) / T(thirds ? 3 : 1)).eval();
}

template <class T>
std::string body_text(const gen::ManakovBody<T>& b) {
  return named("A", b.A) + "    (A = R diag(d) R^T with d = " + show_value(b.d) + ")\n";
}

// (2.34): M = A Omega + Omega A.
template <class T>
void definition_manakov_M(const Subject<T>& s) {
  const int n = *gen::uniform(3, 7).as("n");
  const auto b = *gen::manakov_body<T>(n).as("body");
  const MatX<T> W = draw_omega<T>(n);
  showing_inputs([&] { return body_text(b) + named("Omega", W); },
                 [&] {
                   require_close("slot manakov_M: M = A Omega + Omega A, (2.34) (n = " + std::to_string(n) + ")",
                                 s.manakov_M(b.A, W), MatX<T>(b.A * W + W * b.A), T(T(n) * norm_inf(b.A) * norm_inf(W)),
                                 4.0 * n);
                 });
}

// (2.34) read backwards: Omega solves A Omega + Omega A = M (unique for positive definite A).
// The check is the residual, which a backward-stable solver keeps at round-off whatever A's
// condition: k = 8 n^2.
template <class T>
void definition_manakov_Omega(const Subject<T>& s) {
  const int n = *gen::uniform(3, 7).as("n");
  const auto b = *gen::manakov_body<T>(n).as("body");
  const MatX<T> W = draw_omega<T>(n);
  const MatX<T> M = b.A * W + W * b.A;
  showing_inputs([&] { return body_text(b) + named("M", M); },
                 [&] {
                   const MatX<T> Ws = s.manakov_Omega(b.A, M);
                   require("slot manakov_Omega: Omega is n x n (n = " + std::to_string(n) + ")",
                           Ws.rows() == n && Ws.cols() == n,
                           "got " + std::to_string(Ws.rows()) + " x " + std::to_string(Ws.cols()));
                   require_close("slot manakov_Omega: A Omega + Omega A = M, (2.34) (n = " + std::to_string(n) + ")",
                                 MatX<T>(b.A * Ws + Ws * b.A), M, T(T(n) * norm_inf(b.A) * norm_inf(Ws)), 8.0 * n * n);
                 });
}

// (2.34), (2.36): dM/dt = [M, Omega] with Omega from M.
template <class T>
void definition_manakov_2_34(const Subject<T>& s) {
  const int n = *gen::uniform(3, 7).as("n");
  const auto b = *gen::manakov_body<T>(n).as("body");
  const MatX<T> W = draw_omega<T>(n);
  const MatX<T> M = b.A * W + W * b.A;
  showing_inputs([&] { return body_text(b) + named("M", M); },
                 [&] {
                   require_close("slot manakov_2_34: dM/dt = [M, Omega], A Omega + Omega A = M, (2.34) (n = " +
                                     std::to_string(n) + ")",
                                 s.manakov_2_34(b.A, M), commutator_of(M, W), T(b.spread * norm_inf(M) * norm_inf(W)),
                                 8.0 * n * n + 8.0 * n);
                 });
}

// Proposition 2.4's Lagrangian: l(Omega) = -tr(Omega A Omega) / 2.
template <class T>
void definition_manakov_lagrangian(const Subject<T>& s) {
  const int n = *gen::uniform(3, 7).as("n");
  const auto b = *gen::manakov_body<T>(n).as("body");
  const MatX<T> W = draw_omega<T>(n);
  showing_inputs([&] { return body_text(b) + named("Omega", W); },
                 [&] {
                   require_close("slot manakov_lagrangian: l = -tr(Omega A Omega)/2, Proposition 2.4",
                                 s.manakov_lagrangian(b.A, W), T(-(W * b.A * W).trace() / T(2)),
                                 T(T(n * n) * norm_inf(b.A) * norm_inf(W) * norm_inf(W)), 2.0 * n * n);
                 });
}

// (3.23) with the corrected momentum of the closing exercise (erratum mm.manakov-clebsch):
// M = Q^T P - P^T Q, Omega from A Omega + Omega A = M, dQ/dt = Q Omega, dP/dt = P Omega. Omega is
// computed here through A's eigenvectors: Omega = R W R^T with W_ij = (R^T M R)_ij / (d_i + d_j).
template <class T>
void definition_manakov_clebsch_3_23(const Subject<T>& s) {
  const int n = *gen::uniform(3, 7).as("n");
  const auto b = *gen::manakov_body<T>(n).as("body");
  const MatX<T> Q = *gen::mat<T>(n, n).as("Q");
  const MatX<T> P = *gen::mat<T>(n, n).as("P");
  const MatX<T> M = Q.transpose() * P - P.transpose() * Q;
  const MatX<T> Mb = b.R.transpose() * M * b.R;
  MatX<T> Wb(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) Wb(i, j) = Mb(i, j) / (b.d(i) + b.d(j));
  const MatX<T> W = b.R * Wb * b.R.transpose();
  const auto [dQ, dP] = s.manakov_clebsch_3_23(b.A, Q, P);
  const T omega_size = T(b.spread * norm_inf(M) / b.d.minCoeff());
  // The closing exercise as printed, M = (P^T Q - Q^T P)/2 = -M/2: Omega and both rates scale by -1/2.
  recognising_erratum(
      [&] {
        return !M.isZero() && (dQ + Q * W / T(2)).cwiseAbs().maxCoeff() <=
                                  T(64 * n * n) * eps<T>() * T(T(n) * norm_inf(Q) * omega_size);
      },
      "mm.manakov-clebsch", "M = (P^T Q - Q^T P)/2",
      [&] {
        showing_inputs([&] { return body_text(b) + named("Q", Q) + named("P", P); },
                       [&] {
                         require_close("slot manakov_clebsch_3_23: dQ/dt = Q Omega, M = Q^T P - P^T Q, (3.23)", dQ,
                                       MatX<T>(Q * W), T(T(n) * norm_inf(Q) * omega_size), 16.0 * n * n);
                         require_close("slot manakov_clebsch_3_23: dP/dt = P Omega, M = Q^T P - P^T Q, (3.23)", dP,
                                       MatX<T>(P * W), T(T(n) * norm_inf(P) * omega_size), 16.0 * n * n);
                       });
      });
}

}  // namespace

#define GM_MANAKOV_DEFINITION(slot, entry, statement, ...)  \
  GM_PROPERTY(definition_##slot, all_scalars,               \
              {.spec = entry,                               \
               .title = "slot " #slot " alone: " statement, \
               .tolerance = ToleranceClass::Exact,          \
               .needs = {#slot},                            \
               .negative_controls = {__VA_ARGS__},          \
               .cases = {.d = 100, .mp = 25, .q = 15}})

GM_MANAKOV_DEFINITION(manakov_M, "s2.manakov", "M = A Omega + Omega A, (2.34), n = 3..6, A = R D R^T",
                      "manakov_M_one_sided");
GM_MANAKOV_DEFINITION(manakov_Omega, "s2.manakov", "A Omega + Omega A = M, (2.34), n = 3..6, non-diagonal A",
                      "manakov_Omega_as_if_commuting", "manakov_Omega_diagonal_A_only");
GM_MANAKOV_DEFINITION(manakov_2_34, "s2.manakov", "dM/dt = [M, Omega], (2.34), n = 3..6, non-diagonal A",
                      "manakov_2_34_one_sided", "manakov_commutator_reversed", "manakov_2_34_diagonal_A_only");
GM_MANAKOV_DEFINITION(manakov_lagrangian, "s2.manakov-momentum", "l = -tr(Omega A Omega)/2, Proposition 2.4",
                      "manakov_lagrangian_sign_flipped");
GM_MANAKOV_DEFINITION(manakov_clebsch_3_23, "mm.manakov-clebsch",
                      "(3.23) with M = Q^T P - P^T Q (the corrected closing exercise), non-diagonal A",
                      "manakov_clebsch_P_left_multiplied", "manakov_clebsch_M_as_printed");

#undef GM_MANAKOV_DEFINITION
}  // namespace properties_definitions_manakov
}  // namespace gm
