// The vector field a step follows, read in the form the integrator keeps its state in
// (core/state_form.hpp: a quaternion, Omega, omega, pi), so that a false claim of such a step speaks
// to its owner in their own variables ("your omega ...", "your quaternion ...") before the notes'
// (Pi, O) reading of step_field.hpp. As there, D(h) = (step(x, h) - x)/h is extrapolated to h = 0,
// here of the declared variables (the suite's conversion of the step's result; q on the side of the
// starting q, since q and -q are one attitude), and compared with what (3.8), (2.2) and (2.10) give
// in that form at x, with Omega = I^-1 Pi:
//
//   dPi/dt = Pi x Omega (3.8)           dOmega/dt = I^-1 dPi/dt (2.2)
//   domega/dt = O I^-1 dPi/dt            dpi/dt = 0 (Theorem 2.2)
//   dq/dt = q (0, Omega) / 2 = (0, omega) q / 2      (2.10) for q = (w, v), O = R(q)
//
// A step whose own variables jump as h -> 0 (step(x, h) - x does not shrink with h) is not consistent:
// a conversion inside it that is not undone (a rotation applied where its transpose was meant) does
// that, and the reading says so instead of printing a huge "field".
#pragma once

#include "properties/integrators/support/step_field.hpp"

#include <string>

namespace gm::stepfield {

template <class T>
struct FormField {
  Vec3<T> angular_dot;   // d/dt of the declared angular vector
  Vec4<T> q_dot;         // d/dt of the quaternion, in the declared order (a quaternion form only)
  Vec3<T> angular_jump;  // step(x, h) - x of the angular vector at the smallest h, when it does not shrink
  Vec4<T> q_jump;
  bool jumps = false;
};

template <class T>
Vec4<T> quaternion_times(const Vec4<T>& a, const Vec4<T>& b) {  // Hamilton's product, (w, x, y, z)
  return Vec4<T>(
      a(0) * b(0) - a(1) * b(1) - a(2) * b(2) - a(3) * b(3), a(0) * b(1) + a(1) * b(0) + a(2) * b(3) - a(3) * b(2),
      a(0) * b(2) - a(1) * b(3) + a(2) * b(0) + a(3) * b(1), a(0) * b(3) + a(1) * b(2) - a(2) * b(1) + a(3) * b(0));
}

template <class T>
Vec4<T> pure(const Vec3<T>& v) {
  return Vec4<T>(T(0), v(0), v(1), v(2));
}

template <class T>
FormField<T> declared_field(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x) {
  const StateForm& f = in.form;
  const EngineState<T> u0 = to_declared<T>(f, I, x.O, x.Pi);
  auto difference = [&](const T& h) {
    const RigidBodyState<T> y = in.rigid_body_step(I, x, h);
    const EngineState<T> u = to_declared<T>(f, I, y.O, y.Pi, f.has_quaternion() ? &u0.q : nullptr);
    MatX<T> d = MatX<T>::Zero(7, 1);
    d.topRows(3) = u.angular() - u0.angular();
    if (f.has_quaternion()) d.bottomRows(4) = u.q - u0.q;
    return d;
  };
  FormField<T> ff;
  T spread(0);
  const T rate = max_abs(Vec3<T>(x.Pi.cwiseQuotient(I)));
  const MatX<T> D = rate_at_zero<T>(difference, &spread, rate);
  ff.angular_dot = D.topRows(3);
  ff.q_dot = D.bottomRows(4);
  // Consistency: at h and h / 32 a consistent step's change shrinks 32-fold; a jump does not.
  const T h = first_step<T>(rate);
  const MatX<T> big = difference(h), small = difference(T(h / T(32)));
  const T size = T(1) + max_abs(u0.angular());
  if (max_abs(small) > max_abs(big) / T(4) && max_abs(small) > agree_tolerance<T>() * size) {
    ff.jumps = true;
    ff.angular_jump = small.topRows(3);
    ff.q_jump = small.bottomRows(4);
  }
  return ff;
}

template <class T>
std::string v4(const Vec4<T>& x) {
  return show_value(Vec4<double>(to_double(x(0)), to_double(x(1)), to_double(x(2)), to_double(x(3))));
}

// The declared-form reading, leading the notes' one (`notes`, from diagnose() in step_field.hpp).
template <class T>
Diagnosis in_declared_form(const Integrator<T>& in, const Vec3<T>& I, const RigidBodyState<T>& x,
                           const Diagnosis& notes) {
  const StateForm& f = in.form;
  const FormField<T> ff = declared_field(in, I, x);
  const EngineState<T> u = to_declared<T>(f, I, x.O, x.Pi);
  const Vec3<T> Omega = x.Pi.cwiseQuotient(I);        // (3.5)
  const Vec3<T> Pi_dot = truth::cross(x.Pi, Omega);   // (3.8)
  const Vec3<T> Omega_dot = Pi_dot.cwiseQuotient(I);  // (2.2)
  const Vec3<T> omega = x.O * Omega;
  const char* name = angular_key(f.angular);
  const std::string yours = your_angular(f);
  Vec3<T> expected;
  switch (f.angular) {
    case Angular::Pi:
      expected = Pi_dot;
      break;
    case Angular::Omega:
      expected = Omega_dot;
      break;
    case Angular::omega:
      expected = x.O * Omega_dot;
      break;
    case Angular::pi:
      expected = Vec3<T>::Zero();
      break;
  }
  const T size =
      max_abs(expected) + max_abs(x.Pi) * max_abs(Omega) / I.minCoeff() + max_abs(u.angular()) * max_abs(Omega);
  std::string a_text, q_text;
  bool a_ok = true, q_ok = true;
  const std::string intro = "your state is " + describe_state_form(f) +
                            " (the suite reads it as the notes' (Pi, O) by " + state_form_conversion(f) + ")";
  if (ff.jumps) {
    Diagnosis d;
    d.text = intro + ": your step is not consistent in it: as h -> 0, step(x, h) - x does not shrink but stays near " +
             std::string(name) + ": " + v(ff.angular_jump) +
             (f.has_quaternion() ? ", q: " + v4(ff.q_jump) : std::string()) +
             " (h = " + to_string_full(T(first_step<T>(max_abs(Omega)) / T(32))) +
             "), so a conversion inside the step is not undone (a rotation applied where its transpose, the inverse, "
             "was meant?) and no order can hold";
    return d;
  }
  if (!agrees(ff.angular_dot, expected, size)) {
    a_ok = false;
    const std::string notes_says = f.angular == Angular::pi ? "Theorem 2.2 keeps pi = O Pi constant"
                                   : f.angular == Angular::Pi
                                       ? "(3.8) gives Pi x Omega = " + v(expected)
                                       : "(2.2) gives " +
                                             std::string(f.angular == Angular::omega ? "O I^-1 ((I Omega) x Omega) = "
                                                                                     : "I^-1 ((I Omega) x Omega) = ") +
                                             v(expected);
    if (max_abs(ff.angular_dot) <= agree_tolerance<T>() * size)
      a_text = yours + " stays constant (d" + name + "/dt = 0) where " + notes_says +
               ": the gyroscopic term (I Omega) x Omega is missing";
    else if (agrees(ff.angular_dot, Vec3<T>(-expected), size))
      a_text = yours + " follows d" + name + "/dt = " + v(ff.angular_dot) + ", the opposite of what " + notes_says +
               ": the gyroscopic term has the wrong sign";
    else if (f.angular == Angular::omega &&
             agrees(ff.angular_dot, Vec3<T>(truth::cross(Vec3<T>(I.cwiseProduct(omega)), omega).cwiseQuotient(I)),
                    size))
      a_text = yours + " follows domega/dt = I^-1 ((I omega) x omega) = " + v(ff.angular_dot) + " where " + notes_says +
               ": the body's inertia is applied to the spatial omega (it is not rotated into space, I_space = O I O^T, "
               "Remark 2.1)";
    else
      a_text = yours + " follows d" + name + "/dt = " + v(ff.angular_dot) + " where " + notes_says;
  }
  if (f.has_quaternion()) {
    const Vec4<T> q = state_form::wxyz<T>(u.q, f.attitude);
    const Vec4<T> q_dot = state_form::wxyz<T>(ff.q_dot, f.attitude);
    const Vec4<T> right = quaternion_times<T>(q, pure<T>(Omega)) / T(2);  // (2.10): q (0, Omega) / 2
    const T qsize = max_abs(Omega);
    auto same = [&](const Vec4<T>& a, const Vec4<T>& b) {
      return max_abs(Vec4<T>(a - b)) <= agree_tolerance<T>() * qsize;
    };
    const std::string yq = your_attitude(f);
    if (!same(q_dot, right)) {
      q_ok = false;
      const std::string should = "(2.10) in quaternions is dq/dt = q (0, Omega) / 2 = (0, omega) q / 2 = " +
                                 v4<T>(state_form::in_order<T>(right, f.attitude));
      const Vec4<T> shown_dot = ff.q_dot;
      if (same(q_dot, Vec4<T>(-right)))
        q_text = yq + " turns backwards, dq/dt = " + v4(shown_dot) + "; " + should;
      else if (same(q_dot, Vec4<T>(quaternion_times<T>(pure<T>(Omega), q) / T(2))))
        q_text = yq + " turns with the body's Omega on the left, dq/dt = (0, Omega) q / 2 = " + v4(shown_dot) +
                 ", as if it were the spatial omega; " + should;
      else if (same(q_dot, Vec4<T>(quaternion_times<T>(q, pure<T>(omega)) / T(2))))
        q_text = yq + " turns with the spatial omega on the right, dq/dt = q (0, omega) / 2 = " + v4(shown_dot) +
                 ", as if it were the body's Omega; " + should;
      else
        q_text = yq + " moves as dq/dt = " + v4(shown_dot) + "; " + should;
    }
  }
  Diagnosis d;
  d.field_right = notes.field_right && a_ok && q_ok;
  std::string own;
  if (a_ok && q_ok)
    own = std::string(f.has_quaternion() ? your_attitude(f) + " and " : "") + yours + " follow the notes";
  else
    own = a_text + (a_text.empty() || q_text.empty() ? "" : "; ") + q_text;
  d.text = intro + ": " + own + "; in the notes' (Pi, O): " + notes.text;
  return d;
}

}  // namespace gm::stepfield
