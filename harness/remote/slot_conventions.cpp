#include "harness/remote/slot_conventions.hpp"

#include <map>

namespace gm::harness {

namespace {

// The documented coordinates of so(n) (properties/support/truth.hpp, so_n_matrix), in words.
constexpr const char* kDocumentedSoN =
    "documented (used when hat_n is not given): so(2): [[0, -v1], [v1, 0]]; n >= 3: the top-left 3 x 3 block is "
    "(2.11) of (v1, v2, v3), i.e. v1 = m(3,2), v2 = m(1,3), v3 = m(2,1), then column c = 4..n above the diagonal holds "
    "the next c - 1 coordinates from the top (so(4): v4 = m(1,4), v5 = m(2,4), v6 = m(3,4)); entries m(row,column) "
    "count from 1";

const std::map<std::string_view, std::string>& table() {
  static const std::map<std::string_view, std::string> t = {
      {"hat", "fixed by (2.11): hat(v) = [[0, -v3, v2], [v3, 0, -v1], [-v2, v1, 0]], so that hat(v) w = v x w"},
      {"vee", "fixed by (2.11): vee(m) = (m(3,2), m(1,3), m(2,1)) for skew m"},
      {"pairing", "fixed by (2.15): <A, B> = tr(A^T B) / 2, for any n x n matrices (n = 2..6), not only skew ones"},
      {"hat_n",
       std::string(
           "free: the coordinates of so(n), at every n (n = 3 included; agreeing with (2.11) there is "
           "recommended): each coordinate is one entry above the diagonal, with its negative below; their order "
           "and signs are yours. The suite learns them from hat_n(e_k, n) and checks vee_n, so4_bracket_R6 and "
           "ad_star_so4_R6 in them. ") +
           kDocumentedSoN},
      {"vee_n",
       "follows hat_n: reads back the coordinates hat_n writes; without hat_n, the documented ones (see hat_n)"},
      {"lie_hat",
       "free: the basis of each algebra. so(3), so(4): coordinates as for hat_n (order and signs yours); sl(2, R): any "
       "three traceless 2 x 2 matrices forming a basis (documented: (a, b, c) -> [[a, b], [c, -a]]). The suite learns "
       "the basis from lie_hat(g, e_k) and checks lie_vee and ad_star in it"},
      {"lie_vee", "follows lie_hat: reads back the coordinates lie_hat writes; without lie_hat, the documented ones"},
      {"ad_star",
       "in lie_hat's basis (documented without it); the pairing of g* with g is that of the dual basis, "
       "<mu, xi> = mu_k xi^k, so (ad*_xi mu)_k = <mu, [xi, e_k]>"},
      {"so4_bracket_R6",
       "in hat_n's coordinates of so(4) (documented without hat_n): [a, b] = vee_4([hat_4(a), hat_4(b)])"},
      {"ad_star_so4_R6",
       "in hat_n's coordinates of so(4) (documented without hat_n), dual-basis pairing as for ad_star"},
      {"euler_3_8", "fixed by (3.8): dPi/dt = Pi x Omega with Omega = I^-1 Pi (I the principal moments, a 3-vector)"},
      {"euler_matrix_2_12", "fixed by (2.12): Pi_hat and the result are skew matrices in the hat convention (2.11)"},
      {"lie_poisson_2_23",
       "gradients as skew matrices in the hat convention (2.11); {f, h} = -<Pi, [df, dh]> with (2.15)"},
      {"canonical_bracket", "sign fixed: {f, h} = df/dq . dh/dp - df/dp . dh/dq, so {q_i, p_j} = delta_ij"},
      {"momentum_map", "sign fixed by the momentum-map section: J(q, p) = p x q (not q x p)"},
      {"clebsch_3_21", "Pi = P x Q (3.21); returns the pair (dQ/dt, dP/dt)"},
      {"reconstruction_2_10",
       "fixed by (2.10): O maps body coordinates to space coordinates, and dO/dt = O Omega_hat (body angular velocity, "
       "left-invariant; not Omega_hat O)"},
      {"spatial_momentum", "fixed: pi = Ad*_{O^-1} Pi = O Pi (erratum s2.noether: not O^T Pi, not O^-1 Pi O)"},
      {"inertia_space", "I_space = O diag(I) O^T, O mapping body to space"},
      {"inertia_tensor_2_3",
       "the points are the columns of X (3 x N), their masses m (N); I = sum m_k (|X_k|^2 Id - X_k X_k^T)"},
      {"inertia_bilinear_2_3", "the points are the columns of X (3 x N), as for inertia_tensor_2_3"},
      {"manakov_M", "A is any symmetric positive definite n x n matrix (not only diagonal); M = A Omega + Omega A"},
      {"manakov_Omega", "A symmetric positive definite, not only diagonal: Omega solves A Omega + Omega A = M"},
      {"manakov_2_34", "dM/dt = [M, Omega] = M Omega - Omega M, Omega from A Omega + Omega A = M"},
      {"manakov_clebsch_3_23",
       "M = Q^T P - P^T Q (erratum mm.manakov-clebsch); returns (dQ/dt, dP/dt) = (Q Omega, P Omega)"},
  };
  return t;
}

}  // namespace

std::string slot_convention(std::string_view slot) {
  const auto& t = table();
  auto it = t.find(slot);
  return it == t.end() ? std::string() : it->second;
}

std::string integrator_state() {
  return "Integrators. The state of the rigid body is (Pi, O): Pi the body angular momentum, O in SO(3) mapping body "
         "coordinates to space coordinates, moving by dO/dt = O Omega_hat (2.10) with Omega = I^-1 Pi (3.5); Pi moves "
         "by (3.8). Manakov's state is (M, O): M in so(n), O in SO(n), dO/dt = O Omega. The canonical steps act on (Q, "
         "P): 3-vectors of (3.21), or n x n matrices of (3.23).";
}

}  // namespace gm::harness
