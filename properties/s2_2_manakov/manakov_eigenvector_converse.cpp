// s2.eigenvectors, Proposition 2.5, the converse direction: the two coupled linear equations
//     M psi = lambda psi   and   dpsi/dt = -Omega psi,   Omega = Omega(M) from (2.34),
// give back the SO(n) rigid-body dynamics (2.36), dM/dt = [M, Omega] (the proof: differentiate
// the first equation, substitute the second, and (dM/dt + [Omega, M]) psi = 0 for a complete set
// of eigenvectors psi).
//
// Executable form. M is skew, so its eigenvectors come in pairs psi = u -+ i v with eigenvalues
// +-i mu; in real form the eigenvalue problem for a complete set of eigenvectors is M R = R D with
// R orthogonal (columns u_j, v_j, and the kernel) and D block-diagonal with blocks
// [[0, mu_j], [-mu_j, 0]] (and a 0 for odd n): M = R D R^T. The linear system is then the flow of
// the eigenvectors alone,
//     dR/dt = -Omega(R D R^T) R,   D constant (the eigenvalues do not move),
// integrated here without ever calling the subject's (2.34) right-hand side; only the subject's
// Omega(M) (manakov_Omega) is used. The property checks that M(t) := R(t) D R(t)^T is the
// solution of the subject's (2.36) from the same M(0) (its manakov_2_34 flow): the motion
// defined by the linear system is the rigid-body motion.
//
// Tolerance: two accurate flows compared state to state (support/dynamics.hpp): 64 eps scale
// (1 + lambda t)^2 for the phase error, times 2 n for the n-term products of R D R^T and of
// Omega R (k = 128 n), on the scale |M(0)| >= 1.
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"

#include <cstdio>

namespace gm {
namespace properties_manakov_eigenvector_converse {
namespace {

// t = 10 in 50 digits too.
template <class T>
T horizon() {
  return T(10);
}

template <class T>
void manakov_eigenvector_system_gives_2_36(const Subject<T>& s) {
  const int n = dyn::pick<T>(rc::gen::inRange(3, 7), "n");
  const auto a = dyn::draw_manakov_a<T>(n);
  const MatX<T> A = dyn::diag_of(a);
  const MatX<T> R0 = *gen::rotation<T>(n).as("R0");
  // D: blocks [[0, mu_j], [-mu_j, 0]], mu_j = k / 4 with 1 <= |k| <= 16 (so M(0) is not 0).
  MatX<T> D = MatX<T>::Zero(n, n);
  for (int j = 0; j + 1 < n; j += 2) {
    const int k = dyn::pick<T>(rc::gen::inRange(1, 17), "k (mu_j = k / 4)");
    D(j, j + 1) = T(k) / T(4);
    D(j + 1, j) = -T(k) / T(4);
  }
  const MatX<T> M0 = R0 * D * R0.transpose();
  const int nn = n * n;
  VecX<T> r0(nn);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) r0(n * i + j) = R0(i, j);
  auto unpack = [n](const VecX<T>& v) {
    MatX<T> R(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) R(i, j) = v(n * i + j);
    return R;
  };
  flow::Gbs<T> g([&](const T&, const VecX<T>& v) {
    const MatX<T> R = unpack(v);
    const MatX<T> M = R * D * R.transpose();        // M psi = lambda psi, in real form M R = R D
    const MatX<T> dR = -s.manakov_Omega(A, M) * R;  // dpsi/dt = -Omega psi, for every column
    VecX<T> d(nn);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) d(n * i + j) = dR(i, j);
    return d;
  });
  const auto times = dyn::times_to(horizon<T>(), 5);
  const auto rs = g.sample(r0, T(0), times);
  const auto Ms = dyn::subject_manakov_M(s, A, M0, times);
  const T lambda = dyn::manakov_rate(a, M0);
  const T size = dyn::at_least_one(T(M0.norm()));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const MatX<T> R = unpack(rs[i]);
    const T gr = dyn::growth(lambda, times[i]);
    char what[160];
    std::snprintf(what, sizeof what,
                  "Proposition 2.5 converse: R D R^T from dpsi/dt = -Omega psi is the solution of (2.36), n = %d", n);
    require_close(what, (R * D * R.transpose()).eval(), Ms[i], T(size * gr * gr), 128 * n);
  }
}

}  // namespace

GM_PROPERTY(manakov_eigenvector_system_gives_2_36, float_scalars,
            {.spec = "s2.eigenvectors",
             .title = "Proposition 2.5 converse: M psi = lambda psi with dpsi/dt = -Omega psi gives back (2.36)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"manakov_2_34", "manakov_Omega"},
             .negative_controls = {"manakov_commutator_reversed", "manakov_Omega_as_if_commuting"},
             .cases = {.d = 20, .mp = 2, .q = 0}});

}  // namespace properties_manakov_eigenvector_converse
}  // namespace gm
