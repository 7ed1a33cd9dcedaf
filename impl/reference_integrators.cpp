// The reference subject's integrators (impl/integrators.hpp), in double and Real50, and what
// their author claims about them. The claims are verified like anyone's, by the integrator-scoped
// properties (properties/integrators/integrator_claims.cpp); a claim is made only where it is a theorem about
// the method, never because a test happened to pass.
#include "core/declared_step.hpp"
#include "impl/canonical_integrators.hpp"
#include "impl/integrators.hpp"
#include "impl/reference_subject.hpp"

namespace gm {

template <class T>
void add_reference_integrators(Subject<T>& s) {
  Integrator<T> midpoint;
  midpoint.name = "implicit_midpoint";
  midpoint.rigid_body_step = ref::implicit_midpoint_step<T>;
  midpoint.manakov_step = ref::manakov_implicit_midpoint_step<T>;
  s.integrators.push_back(std::move(midpoint));

  Integrator<T> splitting;
  splitting.name = "lie_poisson_splitting";
  // Kept as an engine keeps it: a quaternion and the spatial momentum (impl/integrators.hpp).
  splitting.form = parse_state_form("quaternion_wxyz pi");
  splitting.declared_step = ref::lie_poisson_splitting_quaternion_step<T>;
  adapt_declared_step(splitting);
  s.integrators.push_back(std::move(splitting));

  Integrator<T> rk4;
  rk4.name = "rk4";
  rk4.rigid_body_step = ref::rk4_step<T>;
  rk4.manakov_step = ref::manakov_rk4_step<T>;
  rk4.clebsch_step = ref::clebsch_rk4_step<T>;
  rk4.manakov_clebsch_step = ref::manakov_clebsch_rk4_step<T>;
  s.integrators.push_back(std::move(rk4));

  Integrator<T> isospectral;
  isospectral.name = "isospectral_cayley";
  isospectral.manakov_step = ref::manakov_isospectral_step<T>;
  s.integrators.push_back(std::move(isospectral));

  // In the canonical Clebsch variables (impl/canonical_integrators.hpp).
  Integrator<T> clebsch_midpoint;
  clebsch_midpoint.name = "clebsch_midpoint";
  clebsch_midpoint.clebsch_step = ref::clebsch_midpoint_step<T>;
  clebsch_midpoint.manakov_clebsch_step = ref::manakov_clebsch_midpoint_step<T>;
  s.integrators.push_back(std::move(clebsch_midpoint));

  Integrator<T> clebsch_splitting;
  clebsch_splitting.name = "clebsch_splitting";
  clebsch_splitting.clebsch_step = ref::clebsch_splitting_step<T>;
  s.integrators.push_back(std::move(clebsch_splitting));
}
template void add_reference_integrators<double>(Subject<double>&);
template void add_reference_integrators<Real50>(Subject<Real50>&);

std::vector<IntegratorClaims> reference_integrator_claims() {
  std::vector<IntegratorClaims> c;
  // Implicit midpoint: symmetric and of order 2; keeps every quadratic invariant: |Pi|^2 and h
  // (rigid body), tr(M^2) and the energy (Manakov), O^T O. Not the quartic tr(M^4) (n >= 4), so
  // no spectrum claim. Not claimed Poisson: the midpoint rule is not a Poisson map for the
  // Lie-Poisson bracket (3.6) in general.
  c.push_back({.integrator = "implicit_midpoint",
               .order = 2,
               .symmetric = true,
               .casimir = true,
               .energy = true,
               .orthogonality = true,
               .spectrum = false,
               .poisson = false,
               .noether = false,
               .equivariant = true,
               .bounded_energy = true});
  // (Structure claims, properties/integrators/integrator_structure.cpp.) Every method here updates O only by
  // right multiplication, O_{n+1} = O_n U(Pi_n, h) (RK4: each stage is linear in O and multiplied
  // on the right), and the Pi- or M-part does not depend on O: step(Pi, R O) = (Pi', R O'), so all
  // claim `equivariant`. An energy kept exactly is a fortiori bounded, so midpoint and the
  // isospectral method claim `bounded_energy`. Midpoint keeps O Pi (bilinear, a quadratic
  // invariant), but Manakov's O M O^T is cubic in (M, O) and for n >= 4 the midpoint rule does not
  // keep it (for n = 3 it does, O hat(Pi) O^T = hat(O Pi)): no `noether` claim for midpoint.
  // Strang splitting into the exact flows of Pi_i^2 / (2 I_i): symmetric, order 2, Casimir (rotations),
  // Poisson (exact Hamiltonian flows composed). Energy error O(h^2). Kept with a quaternion: its
  // norm is kept (products of unit quaternions: unit_quaternion); orthogonality is not its to claim
  // (the matrix the properties see is the suite's R(q / |q|)).
  c.push_back({.integrator = "lie_poisson_splitting",
               .order = 2,
               .symmetric = true,
               .casimir = true,
               .energy = false,
               .orthogonality = false,
               .spectrum = false,
               .poisson = true,
               .noether = true,
               .equivariant = true,
               .bounded_energy = true,
               .unit_quaternion = true});
  // Splitting: each sub-flow keeps O Pi (Noether). Bounded energy: on the sphere |Pi| = const the
  // step is an area-preserving (Poisson) map O(h^2)-close to the flow of a one-degree-of-freedom
  // system, so backward error analysis gives a modified energy h + O(h^2) kept up to exponentially
  // small terms: |h - h0| = O(h^2) with no drift over exponentially long times.
  // Classical RK4: order 4, nothing else.
  c.push_back({.integrator = "rk4", .order = 4, .equivariant = true});
  // Isospectral Cayley (Manakov only): symmetric, order 2, the whole spectrum of M (hence
  // tr(M^2)), orthogonality of O, and the energy E(M) = -tr(Omega(M) M)/4: Omega(.) is linear and
  // self-adjoint for the trace pairing, so E(M1) - E(M0) = -tr(W (M1 - M0))/2 with W = Omega(M_*),
  // and tr(W U^T M0 U) = tr(U W U^T M0) = tr(W M0) because U = cay(h W) commutes with W.
  c.push_back({.integrator = "isospectral_cayley",
               .order = 2,
               .symmetric = true,
               .casimir = true,
               .energy = true,
               .orthogonality = true,
               .spectrum = true,
               .poisson = false,
               .noether = true,
               .equivariant = true,
               .bounded_energy = true});
  // Isospectral Noether: O_{n+1} M_{n+1} O_{n+1}^T = O_n U U^T M_n U U^T O_n^T = O_n M_n O_n^T.
  //
  // Canonical (Clebsch) steps, properties/integrators/integrator_canonical.cpp. RK4 (above) also steps (3.21)
  // and (3.23); its order-4 claim covers them, and it is not symplectic. The midpoint rule is
  // symplectic for every canonical Hamiltonian system, symmetric, of order 2; it does not keep H,
  // which is quartic in (Q, P) (a separate integrator from implicit_midpoint, whose energy claim
  // is a theorem for the quadratic h(Pi) only). The splitting into exact rotation flows is
  // symplectic (a composition of Hamiltonian flows), symmetric (Strang), of order 2.
  c.push_back({.integrator = "clebsch_midpoint", .order = 2, .symmetric = true, .symplectic = true});
  c.push_back({.integrator = "clebsch_splitting", .order = 2, .symmetric = true, .symplectic = true});
  return c;
}

}  // namespace gm
