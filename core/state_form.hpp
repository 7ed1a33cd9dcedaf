// The forms in which real code keeps a rigid body's state (DESIGN.md, "Real code keeps its own
// state"), and the conversions between each of them and the notes' (Pi, O) of (2.20).
//
// Attitude: the notes' O in SO(3), mapping body coordinates to space coordinates (2.10), or a unit
// quaternion q = (w, v) doing the same (Hamilton's product, x_space = q x_body q^-1, so O = R(q)),
// written (w, x, y, z) or (x, y, z, w). q and -q are one attitude; a q that is not of unit norm
// stands for the attitude of q / |q| (its norm is judged on its own, properties/integrators/integrator_quaternion.cpp).
//
// Angular state: the body angular momentum Pi (the notes'), the body angular velocity
// Omega = I^-1 Pi (3.5), the spatial angular velocity omega = O Omega (Omega_hat = O^-1 dO/dt, so
// dO/dt O^-1 = hat(omega)), or the spatial angular momentum pi = O Pi (2.30, erratum s2.noether).
//
// The conversions need I (the principal moments) for Omega and omega, and a square root for a
// quaternion of a matrix: they are written for the float scalars (integrators never run in
// rationals).
#pragma once

#include "core/linalg.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gm {

template <class T>
using Vec4 = Eigen::Matrix<T, 4, 1>;

enum class Attitude : unsigned char { matrix, quaternion_wxyz, quaternion_xyzw };
enum class Angular : unsigned char { Pi, Omega, omega, pi };

// How an integrator keeps its state; the notes' (Pi, O) unless it declares another form.
struct StateForm {
  Attitude attitude = Attitude::matrix;
  Angular angular = Angular::Pi;
  bool is_notes() const { return attitude == Attitude::matrix && angular == Angular::Pi; }
  bool has_quaternion() const { return attitude != Attitude::matrix; }
  friend bool operator==(const StateForm&, const StateForm&) = default;
};

// The words of a declaration, in every language: "ATTITUDE ANGULAR", e.g. "quaternion_wxyz omega"
// (attitude: matrix, quaternion_wxyz, quaternion_xyzw; angular: Pi, Omega, omega, pi; the case
// matters, as in the notes: Omega is the body's, omega the spatial one). Throws std::invalid_argument
// naming the word that is not one of these and listing them.
StateForm parse_state_form(std::string_view text);
// The declaration's words ("quaternion_wxyz omega").
std::string state_form_words(const StateForm& f);
// The keys of the two parts in a state (EngineState's members, the protocol's JSON keys):
// "O" or "q"; "Pi", "Omega", "omega" or "pi".
const char* attitude_key(Attitude a);
const char* angular_key(Angular a);
// For people: "a unit quaternion q = (w, x, y, z) and the spatial angular velocity omega".
std::string describe_state_form(const StateForm& f);
// The declared parts as a message speaks to their owner: "your quaternion q = (w, x, y, z)",
// "your omega (the spatial angular velocity)".
std::string your_attitude(const StateForm& f);
std::string your_angular(const StateForm& f);
// How the suite reads the declared state as the notes' (Pi, O): "O = R(q / |q|), Pi = I O^T omega".
std::string state_form_conversion(const StateForm& f);

// A state in a declared form: `form` says which attitude (O or q) and which angular vector (Pi,
// Omega, omega or pi) hold it; the other members are not part of it (the suite leaves them NaN).
template <class T>
struct EngineState {
  StateForm form;
  Mat3<T> O;      // Attitude::matrix
  Vec4<T> q;      // a quaternion, in the declared order
  Vec3<T> Pi;     // Angular::Pi: body angular momentum
  Vec3<T> Omega;  // Angular::Omega: body angular velocity, I^-1 Pi
  Vec3<T> omega;  // Angular::omega: spatial angular velocity, O Omega
  Vec3<T> pi;     // Angular::pi: spatial angular momentum, O Pi

  Vec3<T>& angular() {
    switch (form.angular) {
      case Angular::Omega:
        return Omega;
      case Angular::omega:
        return omega;
      case Angular::pi:
        return pi;
      case Angular::Pi:
        break;
    }
    return Pi;
  }
  const Vec3<T>& angular() const { return const_cast<EngineState*>(this)->angular(); }
};

namespace state_form {

template <class T>
T not_a_number() {
  return std::numeric_limits<T>::quiet_NaN();
}

// (w, x, y, z) from the declared order, and back.
template <class T>
Vec4<T> wxyz(const Vec4<T>& q, Attitude a) {
  if (a == Attitude::quaternion_xyzw) return Vec4<T>(q(3), q(0), q(1), q(2));
  return q;
}
template <class T>
Vec4<T> in_order(const Vec4<T>& wxyz, Attitude a) {
  if (a == Attitude::quaternion_xyzw) return Vec4<T>(wxyz(1), wxyz(2), wxyz(3), wxyz(0));
  return wxyz;
}

// The rotation of q / |q|, q = (w, v) = (w, x, y, z): R = ((w^2 - v.v) Id + 2 v v^T + 2 w hat(v)) / |q|^2
// (for a unit q, R v' = q v' q^-1; rational in q, so q and -q give the same R).
template <class T>
Mat3<T> rotation_of(const Vec4<T>& q) {
  const T w = q(0), x = q(1), y = q(2), z = q(3);
  const T n2 = w * w + x * x + y * y + z * z;
  Mat3<T> R;
  R << w * w + x * x - y * y - z * z, T(2) * (x * y - w * z), T(2) * (x * z + w * y),  //
      T(2) * (x * y + w * z), w * w - x * x + y * y - z * z, T(2) * (y * z - w * x),   //
      T(2) * (x * z - w * y), T(2) * (y * z + w * x), w * w - x * x - y * y + z * z;
  return R / n2;
}

// A unit quaternion (w, x, y, z) of a rotation O, w >= 0 (Shepperd's choice of the largest of
// w^2, x^2, y^2, z^2 from the trace and the diagonal: no division by a small number). q and -q are
// both right; this one is the suite's when it has no quaternion of the user's to keep.
template <class T>
Vec4<T> quaternion_of(const Mat3<T>& O) {
  using std::sqrt;
  const T tr = O(0, 0) + O(1, 1) + O(2, 2);
  Vec4<T> q;
  if (tr >= O(0, 0) && tr >= O(1, 1) && tr >= O(2, 2)) {
    const T w = T(sqrt(T(T(1) + tr))) / T(2), f = T(4) * w;
    q << w, (O(2, 1) - O(1, 2)) / f, (O(0, 2) - O(2, 0)) / f, (O(1, 0) - O(0, 1)) / f;
  } else if (O(0, 0) >= O(1, 1) && O(0, 0) >= O(2, 2)) {
    const T x = T(sqrt(T(T(1) + O(0, 0) - O(1, 1) - O(2, 2)))) / T(2), f = T(4) * x;
    q << (O(2, 1) - O(1, 2)) / f, x, (O(0, 1) + O(1, 0)) / f, (O(0, 2) + O(2, 0)) / f;
  } else if (O(1, 1) >= O(2, 2)) {
    const T y = T(sqrt(T(T(1) - O(0, 0) + O(1, 1) - O(2, 2)))) / T(2), f = T(4) * y;
    q << (O(0, 2) - O(2, 0)) / f, (O(0, 1) + O(1, 0)) / f, y, (O(1, 2) + O(2, 1)) / f;
  } else {
    const T z = T(sqrt(T(T(1) - O(0, 0) - O(1, 1) + O(2, 2)))) / T(2), f = T(4) * z;
    q << (O(1, 0) - O(0, 1)) / f, (O(0, 2) + O(2, 0)) / f, (O(1, 2) + O(2, 1)) / f, z;
  }
  if (q(0) < T(0)) q = -q;
  return q;
}

// Of q and -q, the one nearer to `near` (both in the same order): a difference of two quaternions
// of nearby attitudes is small only when they are on the same side.
template <class T>
Vec4<T> same_side(const Vec4<T>& q, const Vec4<T>& near) {
  return q.dot(near) < T(0) ? Vec4<T>(-q) : q;
}

// O^-1 of an attitude matrix: O^T for the rotation of a quaternion, the inverse for a declared
// matrix (which may have drifted from SO(3): (Pi, O) -> pi = O Pi -> O^-1 pi is then still Pi).
template <class T>
Mat3<T> inverse_of(const Mat3<T>& O, const StateForm& f) {
  if (f.has_quaternion()) return O.transpose();
  return O.inverse();
}

}  // namespace state_form

// The sign of the quaternion the suite gives a step kept in one, for the states it converts (q and
// -q are one attitude): +1, w >= 0 (quaternion_of's choice), or -1, its negative. Code that assumes
// w >= 0 (a step storing only q's vector part and recovering w = sqrt(1 - |v|^2), a log map without
// the sign test) is wrong for half of the quaternions an engine meets; the attitude regimes of the
// checks draw the sign per case (properties/support/dynamics.hpp, draw_attitude), and the runner
// sets it back to +1 before each case. Per thread, like a case.
int& quaternion_sign_given();

// The notes' (Pi, O) in the declared form; `near`, when given, is a quaternion (declared order) whose
// side q takes (q and -q being one attitude); otherwise q's sign is quaternion_sign_given().
template <class T>
EngineState<T> to_declared(const StateForm& f, const Vec3<T>& I, const Mat3<T>& O, const Vec3<T>& Pi,
                           const Vec4<T>* near = nullptr) {
  using namespace state_form;
  const T nan = not_a_number<T>();
  EngineState<T> u;
  u.form = f;
  u.O = Mat3<T>::Constant(nan);
  u.q = Vec4<T>::Constant(nan);
  u.Pi = u.Omega = u.omega = u.pi = Vec3<T>::Constant(nan);
  if (f.has_quaternion()) {
    u.q = in_order<T>(quaternion_of<T>(O), f.attitude);
    if (near)
      u.q = same_side<T>(u.q, *near);
    else if (quaternion_sign_given() < 0)
      u.q = -u.q;
  } else {
    u.O = O;
  }
  switch (f.angular) {
    case Angular::Pi:
      u.Pi = Pi;
      break;
    case Angular::Omega:
      u.Omega = Pi.cwiseQuotient(I);
      break;  // (3.5)
    case Angular::omega:
      u.omega = O * Vec3<T>(Pi.cwiseQuotient(I));
      break;  // omega = O Omega
    case Angular::pi:
      u.pi = O * Pi;
      break;  // (2.30): pi = O Pi
  }
  return u;
}

namespace state_form {
// The declared state with q of sign w >= 0 whatever quaternion_sign_given() says (for experiments
// that choose the sign themselves).
template <class T>
EngineState<T> canonical_declared(const StateForm& f, const Vec3<T>& I, const Mat3<T>& O, const Vec3<T>& Pi) {
  const int given = quaternion_sign_given();
  quaternion_sign_given() = 1;
  EngineState<T> u = to_declared<T>(f, I, O, Pi);
  quaternion_sign_given() = given;
  return u;
}
}  // namespace state_form

// The attitude matrix of a declared state: its O, or R(q / |q|).
template <class T>
Mat3<T> attitude_of(const EngineState<T>& u) {
  if (!u.form.has_quaternion()) return u.O;
  return state_form::rotation_of<T>(state_form::wxyz<T>(u.q, u.form.attitude));
}

// The body momentum of a declared state whose attitude matrix is O (attitude_of).
template <class T>
Vec3<T> body_momentum_of(const EngineState<T>& u, const Vec3<T>& I, const Mat3<T>& O) {
  switch (u.form.angular) {
    case Angular::Omega:
      return I.cwiseProduct(u.Omega);  // (3.1)
    case Angular::omega:
      return I.cwiseProduct(Vec3<T>(state_form::inverse_of<T>(O, u.form) * u.omega));  // Omega = O^-1 omega
    case Angular::pi:
      return state_form::inverse_of<T>(O, u.form) * u.pi;  // Pi = O^-1 pi
    case Angular::Pi:
      break;
  }
  return u.Pi;
}

}  // namespace gm
