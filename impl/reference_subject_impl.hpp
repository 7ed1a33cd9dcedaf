// Fills every slot of Subject<T> with the reference implementation. Included only by the three
// reference_subject_*.cpp files, one per scalar, so each scalar is compiled once, in parallel.
#pragma once

#include "impl/brackets.hpp"
#include "impl/energy.hpp"
#include "impl/euler.hpp"
#include "impl/inertia.hpp"
#include "impl/lie_algebras.hpp"
#include "impl/manakov.hpp"
#include "impl/momentum_map.hpp"
#include "impl/reconstruction.hpp"
#include "impl/reference_subject.hpp"
#include "impl/so3.hpp"
#include "impl/son.hpp"

namespace gm {

template <class T>
void add_reference_integrators(Subject<T>& s);  // impl/integrators (floating-point scalars only)

template <class T>
Subject<T> make_reference_subject() {
  Subject<T> s;
  s.hat = ref::hat<T>;
  s.vee = ref::vee<T>;
  s.pairing = ref::pairing<T>;
  s.hat_n = ref::hat_n<T>;
  s.vee_n = ref::vee_n<T>;
  s.lie_hat = ref::lie_hat<T>;
  s.lie_vee = ref::lie_vee<T>;
  s.ad_star = ref::ad_star<T>;
  s.so4_bracket_R6 = ref::so4_bracket_R6<T>;
  s.ad_star_so4_R6 = ref::ad_star_so4_R6<T>;

  s.euler_2_1 = ref::euler_2_1<T>;
  s.euler_2_2 = ref::euler_2_2<T>;
  s.euler_3_7 = ref::euler_3_7<T>;
  s.euler_3_8 = ref::euler_3_8<T>;
  s.euler_matrix_2_12 = ref::euler_matrix_2_12<T>;

  s.lagrangian_2_5 = ref::lagrangian_2_5<T>;
  s.lagrangian_2_13 = ref::lagrangian_2_13<T>;
  s.legendre_3_1 = ref::legendre_3_1<T>;
  s.omega_3_5 = ref::omega_3_5<T>;
  s.hamiltonian_3_3 = ref::hamiltonian_3_3<T>;
  s.hamiltonian_3_4 = ref::hamiltonian_3_4<T>;
  s.hamiltonian_2_21 = ref::hamiltonian_2_21<T>;
  s.casimir = ref::casimir<T>;

  s.lie_poisson_2_23 = ref::lie_poisson_2_23<T>;
  s.lie_poisson_3_6 = ref::lie_poisson_3_6<T>;
  s.nambu_3_13 = ref::nambu_3_13<T>;
  s.nambu_motion_3_14 = ref::nambu_motion_3_14<T>;
  s.canonical_bracket = ref::canonical_bracket<T>;
  s.nambu_3_16 = ref::nambu_3_16<T>;

  s.momentum_map = ref::momentum_map<T>;
  s.clebsch_3_21 = ref::clebsch_3_21<T>;
  s.reconstruction_2_10 = ref::reconstruction_2_10<T>;
  s.spatial_momentum = ref::spatial_momentum<T>;
  s.inertia_space = ref::inertia_space<T>;
  s.inertia_tensor_2_3 = ref::inertia_tensor_2_3<T>;
  s.inertia_bilinear_2_3 = ref::inertia_bilinear_2_3<T>;

  s.manakov_M = ref::manakov_M<T>;
  s.manakov_Omega = ref::manakov_Omega<T>;
  s.manakov_2_34 = ref::manakov_2_34<T>;
  s.manakov_lagrangian = ref::manakov_lagrangian<T>;
  s.manakov_clebsch_3_23 = ref::manakov_clebsch_3_23<T>;

  if constexpr (!is_exact_v<T>) add_reference_integrators<T>(s);
  return s;
}

}  // namespace gm
