// The vector field Manakov's step and the Clebsch steps follow (step_field.hpp does the
// rigid body): the extrapolated (step(x, h) - x) / h, compared at the failing state with
//   manakov_step          dM/dt = [M, Omega] (2.36), M = A Omega + Omega A (2.34), and the
//                         attitude dO/dt = O Omega ((2.10) on SO(n)): Omega_step = O^T dO/dt;
//   clebsch_step          (3.21): dQ/dt = -Omega x Q, dP/dt = -Omega x P, Omega = I^-1 (P x Q);
//   manakov_clebsch_step  (3.23): dQ/dt = Q Omega, dP/dt = P Omega, A Omega + Omega A = Q^T P - P^T Q
//                         (the M of mm.manakov-clebsch, corrected).
// A field that differs is matched against the mistakes these equations invite (a reversed
// commutator or cross product, Omega solved from one side of (2.34), the notes' misprinted
// M = (P^T Q - Q^T P)/2, Omega applied from the wrong side) and said in the notes' terms, with the
// matrices it compares; a field that agrees rules the equation out, and names no other cause.
#pragma once

#include "impl/canonical_integrators.hpp"
#include "impl/manakov.hpp"
#include "properties/integrators/support/step_field.hpp"
#include "properties/support/named_inputs.hpp"

#include <string>
#include <vector>

namespace gm::stepfield {

template <class T>
std::string m(const MatX<T>& x) {
  return show_value(MatX<double>(x.unaryExpr([](const T& e) { return to_double(e); })));
}

template <class T>
bool agrees(const MatX<T>& a, const MatX<T>& b, const T& size) {
  return max_abs(MatX<T>(a - b)) <= agree_tolerance<T>() * size;
}

// A mistake's field and what to say when the step follows it.
template <class T>
struct Reading {
  MatX<T> field;
  std::string text;
};

// The text of the first reading `measured` agrees with; `otherwise` when none does.
template <class T>
std::string read_field(const MatX<T>& measured, const std::vector<Reading<T>>& readings, const T& size,
                       const std::string& otherwise) {
  for (const auto& r : readings)
    if (agrees(measured, r.field, size)) return r.text;
  return otherwise;
}

template <class T>
MatX<T> bracket(const MatX<T>& X, const MatX<T>& Y) {
  return MatX<T>(X * Y - Y * X);
}

// ---------------------------------------------------------------------------------------------
// Manakov's (M, O).

template <class T>
struct ManakovField {
  MatX<T> M_dot;  // dM/dt the step follows
  MatX<T> Omega;  // O^T dO/dt: the body angular velocity it turns O with
  T spread = T(0);
};

template <class T>
ManakovField<T> manakov_field(const Integrator<T>& in, const MatX<T>& A, const ManakovState<T>& x) {
  const auto n = x.M.rows();
  ManakovField<T> f;
  const MatX<T> D = rate_at_zero<T>(
      [&](const T& h) {
        const ManakovState<T> y = in.manakov_step(A, x, h);
        MatX<T> d(2 * n, n);
        d.topRows(n) = y.M - x.M;
        d.bottomRows(n) = x.O.transpose() * (y.O - x.O);
        return d;
      },
      &f.spread, T(max_abs(x.M) / A.diagonal().minCoeff()));  // about |Omega| of (2.34)
  f.M_dot = D.topRows(n);
  f.Omega = D.bottomRows(n);
  return f;
}

template <class T>
Diagnosis diagnose_manakov(const ManakovField<T>& f, const MatX<T>& A, const ManakovState<T>& x) {
  const auto n = x.M.rows();
  const MatX<T> Omega = ref::manakov_Omega<T>(A, x.M);  // (2.34)
  const MatX<T> rhs = bracket(x.M, Omega);              // (2.36)
  const T size_m = max_abs(rhs) + T(n) * max_abs(x.M) * max_abs(Omega);
  const T size_w = max_abs(Omega) + max_abs(MatX<T>(A.inverse() * x.M));
  const MatX<T> commuting = A.inverse() * x.M / T(2), one_sided = A.inverse() * x.M;
  const std::string omega_is = "Omega from (2.34) M = A Omega + Omega A is " + m(Omega);
  const std::string pi_text = read_field<T>(
      f.M_dot,
      {{MatX<T>(-rhs), "your step follows dM/dt = [Omega, M] = " + m(f.M_dot) + "; (2.36) is [M, Omega] = " + m(rhs) +
                           ": the commutator is reversed"},
       {bracket(x.M, commuting),
        "your step follows dM/dt = [M, Omega] with Omega = A^-1 M / 2, as if A and Omega "
        "commuted; " +
            omega_is + ": the commutator form is right, its Omega is not"},
       {bracket(x.M, one_sided),
        "your step follows dM/dt = [M, Omega] with Omega = A^-1 M, one side of (2.34); " + omega_is},
       {MatX<T>(MatX<T>::Zero(n, n)), "your step leaves M unchanged (dM/dt = 0); (2.36) gives [M, Omega] = " + m(rhs)}},
      size_m,
      "your step follows dM/dt = " + m(f.M_dot) + "; (2.36) gives [M, Omega] = " + m(rhs) + " with " + omega_is);
  const bool pi_ok = agrees(f.M_dot, rhs, size_m);
  const bool om_ok = agrees(f.Omega, Omega, size_w);
  const std::string om_text = read_field<T>(
      f.Omega,
      {{MatX<T>(-Omega),
        "your step turns the body with dO/dt = -O Omega, the opposite of dO/dt = O Omega ((2.10) on "
        "SO(n)), " +
            omega_is},
       {MatX<T>(x.O.transpose() * Omega * x.O),
        "your step turns the body with dO/dt = Omega O (Omega applied on the "
        "left); the reconstruction is dO/dt = O Omega ((2.10) on SO(n)), " +
            omega_is},
       {commuting, "your step turns the body with Omega = A^-1 M / 2, as if A and Omega commuted; " + omega_is},
       {one_sided, "your step turns the body with Omega = A^-1 M, one side of (2.34); " + omega_is}},
      size_w, "your step turns the body with Omega = O^T dO/dt = " + m(f.Omega) + " where (2.34) gives " + m(Omega));
  Diagnosis d;
  d.field_right = pi_ok && om_ok;
  if (d.field_right)
    d.text =
        "your step's vector field is right: it follows (2.36) and dO/dt = O Omega (the extrapolated (step(x, h) - x)/h "
        "agrees with [M, Omega] = " +
        m(rhs) + " and " + omega_is +
        "): the equation is not the cause, and this reading identifies no other (the measurement is the evidence)";
  else
    d.text = (pi_ok ? "" : pi_text) + (pi_ok || om_ok ? "" : "; ") + (om_ok ? "" : om_text);
  return d;
}

// ---------------------------------------------------------------------------------------------
// The Clebsch steps on the stacked state Z = [Q; P] (impl/canonical_integrators.hpp).

// The field of a canonical step Z -> step(Z, h).
template <class T, class Step>
MatX<T> canonical_field(Step&& step, const MatX<T>& Z) {
  return rate_at_zero<T>([&](const T& h) { return MatX<T>(step(Z, h) - Z); }, nullptr);
}

template <class T>
std::string qp(const MatX<T>& F) {
  const auto k = F.rows() / 2;
  return "dQ/dt = " + m(MatX<T>(F.topRows(k))) + ", dP/dt = " + m(MatX<T>(F.bottomRows(k)));
}

template <class T>
Diagnosis diagnose_canonical(const MatX<T>& field, const MatX<T>& truth, std::vector<Reading<T>> readings,
                             const std::string& system) {
  const T size = max_abs(truth) + max_abs(field) / T(4);
  readings.push_back({MatX<T>(MatX<T>::Zero(truth.rows(), truth.cols())),
                      "your step leaves Q and P unchanged; " + system + " gives " + qp(truth)});
  Diagnosis d;
  d.field_right = agrees(field, truth, size);
  if (d.field_right)
    d.text = "your step's vector field is right: it follows " + system +
             " (the extrapolated (step(Z, h) - Z)/h agrees "
             "with " +
             qp(truth) +
             "): the equation is not the cause, and this reading identifies no other (the measurement is the evidence)";
  else
    d.text =
        read_field<T>(field, readings, size, "your step follows " + qp(field) + "; " + system + " gives " + qp(truth));
  return d;
}

// (3.21) with Omega = I^-1 Pi, Pi = P x Q.
template <class T>
Diagnosis diagnose_clebsch(const MatX<T>& field, const Vec3<T>& I, const MatX<T>& Z) {
  const auto [Q, P] = ref::unstack3<T>(Z);
  const MatX<T> F = ref::clebsch_field<T>(I, Z);
  const Vec3<T> Omega_I = I.cwiseProduct(truth::cross(P, Q));  // I Pi for I^-1 Pi
  const MatX<T> inertia =
      ref::stack<T>(Vec3Pair<T>{Vec3<T>(-truth::cross(Omega_I, Q)), Vec3<T>(-truth::cross(Omega_I, P))});
  return diagnose_canonical<T>(
      field, F,
      {{MatX<T>(-F), "your step follows dQ/dt = Omega x Q, dP/dt = Omega x P (" + qp(field) +
                         "); (3.21) is dQ/dt = "
                         "-Omega x Q, dP/dt = -Omega x P with Pi = P x Q (a sign, or Pi taken as Q x P)"},
       {inertia,
        "your step turns Q and P with Omega = I Pi; (3.5) is Omega = I^-1 Pi (Pi = P x Q): the inertia is "
        "applied instead of its inverse"}},
      "(3.21)");
}

// (3.23) with A Omega + Omega A = Q^T P - P^T Q.
template <class T>
Diagnosis diagnose_manakov_clebsch(const MatX<T>& field, const MatX<T>& A, const MatX<T>& Z) {
  const auto [Q, P] = ref::unstack_n<T>(Z);
  const MatX<T> F = ref::manakov_clebsch_field<T>(A, Z);
  const MatX<T> Omega = ref::manakov_Omega<T>(A, ref::manakov_clebsch_M<T>(Q, P));
  const MatX<T> left = ref::stack<T>(MatXPair<T>{MatX<T>(Omega * Q), MatX<T>(Omega * P)});
  return diagnose_canonical<T>(
      field, F,
      {{MatX<T>(-F / T(2)),
        "your step's momentum is the notes' printed M = (P^T Q - Q^T P)/2, which is an erratum (see "
        "spec/CATALOGUE.md, entry mm.manakov-clebsch): Hamilton's principle identifies M = Q^T P - "
        "P^T Q, so your Omega has the opposite sign and half the size"},
       {MatX<T>(-F),
        "your step's Omega has the opposite sign: its M is P^T Q - Q^T P; the M of (3.23) is Q^T P - P^T Q "
        "(mm.manakov-clebsch)"},
       {MatX<T>(F / T(2)),
        "your step's Omega is half of (3.23)'s: its M is (Q^T P - P^T Q)/2; Omega solves A Omega + "
        "Omega A = Q^T P - P^T Q"},
       {left,
        "your step follows dQ/dt = Omega Q, dP/dt = Omega P (Omega on the left); (3.23) is dQ/dt = Q Omega, "
        "dP/dt = P Omega"}},
      "(3.23)");
}

// A false claim of Manakov's step explains itself as the rigid body's does (explaining_at in
// step_field.hpp): (2.36), (2.34) and dO/dt = O Omega.
template <class T, class States, class Judge>
void explaining_manakov_step(const Integrator<T>& in, const MatX<T>& A, States&& states, Judge&& judge) {
  explaining_at<T>(
      states,
      [&](const ManakovState<T>& x) { return stepfield::diagnose_manakov(stepfield::manakov_field(in, A, x), A, x); },
      judge);
}

}  // namespace gm::stepfield
