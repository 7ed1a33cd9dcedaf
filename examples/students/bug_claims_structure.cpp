// Buggy claims about structure: three integrators that each claim a property of
// geometric integrators they do not have. The claims table reports each as FALSE CLAIM:
//
//   rk4_rows_normalised   classical RK4 on (Pi, O), then each row of O scaled to length 1 "to keep
//                         O a rotation". RK4 keeps no quadratic invariant, so O Pi drifts; and
//                         the rows of R O are not R times the rows of O, so the normalisation does
//                         not commute with rotating the attitude. Claims Noether and equivariance
//                         (and order 4, which holds: the normalisation moves O by RK4's own error).
//   explicit_verlet       Stormer-Verlet for the Clebsch system (3.21) written explicitly, as one
//                         would for H = T(P) + V(Q). H(Q, P) = h(P x Q) is not separable, and then
//                         Stormer-Verlet's first two stages are implicit: the explicit version is
//                         not symplectic. Claims symplectic.
//   explicit_euler        Pi <- Pi + h Pi x Omega grows |Pi|^2, and the energy with it, at every
//                         step. Claims bounded long-time energy (and order 1, which holds).
#include <geomech/student.hpp>

using namespace gm;

namespace {

template <class T>
Mat3<T> hat(const Vec3<T>& w) {
  Mat3<T> W;
  W << T(0), -w(2), w(1), w(2), T(0), -w(0), -w(1), w(0), T(0);
  return W;
}

}  // namespace

struct Rk4RowsNormalised {
  static constexpr const char* name = "rk4_rows_normalised";
  static constexpr gm::student::Claims claims{.order = 4, .noether = true, .equivariant = true};

  template <class T>
  static RigidBodyState<T> field(const Vec3<T>& I, const RigidBodyState<T>& x) {
    const Vec3<T> Omega = x.Pi.cwiseQuotient(I);
    return {x.Pi.cross(Omega), x.O * hat<T>(Omega)};
  }

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    auto plus = [](const RigidBodyState<T>& a, const RigidBodyState<T>& d, const T& c) {
      return RigidBodyState<T>{a.Pi + c * d.Pi, a.O + c * d.O};
    };
    const auto k1 = field<T>(I, x);
    const auto k2 = field<T>(I, plus(x, k1, h / T(2)));
    const auto k3 = field<T>(I, plus(x, k2, h / T(2)));
    const auto k4 = field<T>(I, plus(x, k3, h));
    RigidBodyState<T> y{x.Pi + h / T(6) * (k1.Pi + T(2) * k2.Pi + T(2) * k3.Pi + k4.Pi),
                        x.O + h / T(6) * (k1.O + T(2) * k2.O + T(2) * k3.O + k4.O)};
    using std::sqrt;
    for (int r = 0; r < 3; ++r) y.O.row(r) /= sqrt(y.O.row(r).squaredNorm());  // rows, in a fixed frame
    return y;
  }
};

struct ExplicitVerlet {
  static constexpr const char* name = "explicit_verlet";
  static constexpr gm::student::Claims claims{.symplectic = true};

  // (dQ/dt, dP/dt) of (3.21) = (dH/dP, -dH/dQ).
  template <class T>
  static Vec3Pair<T> field(const Vec3<T>& I, const Vec3<T>& Q, const Vec3<T>& P) {
    const Vec3<T> W = P.cross(Q).cwiseQuotient(I);
    return {-W.cross(Q), -W.cross(P)};
  }

  template <class T>
  static Vec3Pair<T> clebsch_step(const Vec3<T>& I, const Vec3Pair<T>& z, const T& h) {
    const auto [Q, P] = z;
    const Vec3<T> P_half = P + h / T(2) * field<T>(I, Q, P).second;  // should be implicit in P_half
    const Vec3<T> Q1 = Q + h * field<T>(I, Q, P_half).first;         // should average two evaluations
    const Vec3<T> P1 = P_half + h / T(2) * field<T>(I, Q1, P_half).second;
    return {Q1, P1};
  }
};

struct ExplicitEuler {
  static constexpr const char* name = "explicit_euler";
  static constexpr gm::student::Claims claims{.order = 1, .bounded_energy = true};

  template <class T>
  static RigidBodyState<T> rigid_body_step(const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) {
    const Vec3<T> Omega = x.Pi.cwiseQuotient(I);
    return {x.Pi + h * x.Pi.cross(Omega), x.O + h * x.O * hat<T>(Omega)};
  }
};

struct Nothing {};

GEOMECH_STUDENT(Nothing, Rk4RowsNormalised, ExplicitVerlet, ExplicitEuler);
