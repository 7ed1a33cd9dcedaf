// Negative controls for integrators that are wrong only outside the generic case:
// each wraps a reference integrator and keeps its claims, the way a real mistake sits in an
// otherwise working step.
#include "impl/integrators.hpp"
#include "impl/so3.hpp"
#include "tests/mutants/mutants.hpp"

#include <cmath>

namespace gm {
namespace mutants_integrator_regimes {
namespace {

// exp(theta hat(e_axis)): the rotation by theta about a coordinate axis.
template <class T>
Mat3<T> axis_rotation(int axis, const T& theta) {
  using std::cos;
  using std::sin;
  Mat3<T> R = Mat3<T>::Identity();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  R(i, i) = cos(theta);
  R(j, j) = cos(theta);
  R(j, i) = sin(theta);
  R(i, j) = -sin(theta);
  return R;
}

template <class T>
int principal_axis_of(const Vec3<T>& P) {
  int nonzero = 0, axis = -1;
  for (int i = 0; i < 3; ++i)
    if (P(i) != T(0)) ++nonzero, axis = i;
  return nonzero == 1 ? axis : -1;
}

}  // namespace

// A "fast path" for steady rotation: with Pi along a principal axis the student returns the
// exact steady rotation, but turns O the wrong way, O exp(-h hat(Omega)) (the sign of (2.10)
// mixed up in the special case only). Generic states never take the branch.
GM_MUTANT(principal_axis_fast_path,
          "implicit midpoint with a fast path for Pi along a principal axis that turns O the wrong way", [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& in : s.integrators)
                if (in.name == "implicit_midpoint")
                  in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x,
                                          const T& h) -> RigidBodyState<T> {
                    const int axis = principal_axis_of(x.Pi);
                    if (axis < 0) return ref::implicit_midpoint_step<T>(I, x, h);
                    const T omega = x.Pi(axis) / I(axis);
                    return {x.Pi, (x.O * axis_rotation<T>(axis, T(-h * omega))).eval()};
                  };
            }
          });

// A branch for the symmetric top: when two moments are equal the student treats the body as a
// sphere with the mean moment (Pi constant): right for a sphere, wrong for a symmetric top.
GM_MUTANT(symmetric_top_branch,
          "Lie-Poisson splitting with a branch for I1 = I2 (or any two equal moments) that freezes Pi as for a sphere",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& in : s.integrators)
                if (in.name == "lie_poisson_splitting")
                  in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x,
                                          const T& h) -> RigidBodyState<T> {
                    if (I(0) != I(1) && I(1) != I(2) && I(0) != I(2))
                      return ref::lie_poisson_splitting_step<T>(I, x, h);
                    const T mean = (I(0) + I(1) + I(2)) / T(3);
                    const Vec3<T> sphere(mean, mean, mean);
                    return ref::lie_poisson_splitting_step<T>(sphere, x, h);
                  };
            }
          });

// RK4 with every stage computed in double: exact in double, and stalled near 1e-16 in 50 digits.
GM_MUTANT(rk4_double_inside, "classical RK4 computing its stages in double precision whatever the scalar", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  if constexpr (!is_exact_v<T>) {
    for (auto& in : s.integrators)
      if (in.name == "rk4") {
        in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) -> RigidBodyState<T> {
          const RigidBodyState<double> y = ref::rk4_step<double>(
              convert_matrix<double>(I), {convert_matrix<double>(x.Pi), convert_matrix<double>(x.O)}, to_double(h));
          return {convert_matrix<T>(y.Pi), convert_matrix<T>(y.O)};
        };
        in.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) -> ManakovState<T> {
          const ManakovState<double> y = ref::manakov_rk4_step<double>(
              convert_matrix<double>(A), {convert_matrix<double>(x.M), convert_matrix<double>(x.O)}, to_double(h));
          return {convert_matrix<T>(y.M), convert_matrix<T>(y.O)};
        };
      }
  }
});
GM_MUTANT_WRONG_ONLY_IN(rk4_double_inside, ScalarKind::MP50);

// A "body at rest" guard: the step returns the state unchanged when |Pi| < 1e-10 (or, for an
// SO(n) body, |M| < 1e-10), as if such a body did not move. It does, in other units: Euler's
// equations and (2.34) are homogeneous, and O turns at |Omega| however small. Seen only where a
// state is drawn that small with its time scaled to match (integrator_converges_in_every_regime,
// manakov_integrator_converges_in_every_frame); every other check draws entries >= 1/8.
GM_MUTANT(midpoint_at_rest_below_1e_10, "implicit midpoint that leaves a body with |Pi| or |M| < 1e-10 at rest",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& in : s.integrators)
                if (in.name == "implicit_midpoint") {
                  in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x,
                                          const T& h) -> RigidBodyState<T> {
                    if (x.Pi.cwiseAbs().maxCoeff() < T(1e-10)) return x;
                    return ref::implicit_midpoint_step<T>(I, x, h);
                  };
                  in.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) -> ManakovState<T> {
                    if (x.M.cwiseAbs().maxCoeff() < T(1e-10)) return x;
                    return ref::manakov_implicit_midpoint_step<T>(A, x, h);
                  };
                }
            }
          });

// An engine's "nothing to integrate" shortcut: the attitude is left as it is when the step turns it
// by |Omega h| <= 1e-6 rad (Pi still moves). A slowly turning body never turns; every check but
// integrator_small_turns turns it by 2^-10 rad a step or more.
GM_MUTANT(midpoint_skips_small_turns, "implicit midpoint that leaves O unchanged when |Omega h| <= 1e-6 rad",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& in : s.integrators)
                if (in.name == "implicit_midpoint")
                  in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x,
                                          const T& h) -> RigidBodyState<T> {
                    RigidBodyState<T> y = ref::implicit_midpoint_step<T>(I, x, h);
                    using std::abs;
                    if (abs(h) * Vec3<T>(x.Pi.cwiseQuotient(I)).cwiseAbs().maxCoeff() <= T(1e-6)) y.O = x.O;
                    return y;
                  };
            }
          });

// Omega from M_ij / (A_ii + A_jj) inside the Manakov step: the solution of A Omega + Omega A = M
// (2.34) for a diagonal A, the body every Manakov integrator check drew before. For a body whose
// A is not diagonal (the same body in a rotated frame) the step integrates another system.
GM_MUTANT(manakov_midpoint_diagonal_A_only, "implicit midpoint whose Manakov step reads only the diagonal of A",
          [](auto& s) {
            using T = scalar_of<decltype(s)>;
            if constexpr (!is_exact_v<T>) {
              for (auto& in : s.integrators)
                if (in.name == "implicit_midpoint")
                  in.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) -> ManakovState<T> {
                    return ref::manakov_implicit_midpoint_step<T>(MatX<T>(A.diagonal().asDiagonal()), x, h);
                  };
            }
          });

// Iterates x = F(x) until the change is at most 4 eps (1 + |x|): an absolute floor of eps, the
// tolerance of the examples before 2026-11-25 and of the reference's Manakov fixed point.
template <class X, class F>
X iterate_to_absolute_tolerance(X x, const F& F_) {
  using T = typename X::Scalar;
  for (int iter = 0; iter < 400; ++iter) {
    X next = F_(x);
    const bool done = (next - x).cwiseAbs().maxCoeff() <= T(4) * eps<T>() * (T(1) + next.cwiseAbs().maxCoeff());
    x = std::move(next);
    if (done) break;
  }
  return x;
}

// The implicit midpoint rule by fixed-point iteration stopped at an absolute tolerance,
// 4 eps (1 + |Pi|) (and 4 eps (1 + |M|) for Manakov): right for |Pi| of order 1, but for a
// slowly turning body the first change is already below eps, so the step is one iteration from
// the explicit half step: second order still, but neither symmetric nor keeping |Pi|^2 or the
// energy. Generic states (|Pi_i| >= 1/8) never show it; the invariant claims' scaled states do.
GM_MUTANT(
    midpoint_absolute_tolerance, "implicit midpoint iterated until the change is below 4 eps (1 + |Pi|)", [](auto& s) {
      using T = scalar_of<decltype(s)>;
      if constexpr (!is_exact_v<T>) {
        for (auto& in : s.integrators)
          if (in.name == "implicit_midpoint") {
            in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) -> RigidBodyState<T> {
              const T half = h / T(2);
              auto F = [&](const Vec3<T>& P) { return Vec3<T>(x.Pi + half * P.cross(Vec3<T>(P.cwiseQuotient(I)))); };
              const Vec3<T> P = iterate_to_absolute_tolerance(F(x.Pi), F);
              return {(T(2) * P - x.Pi).eval(), (x.O * ref::cayley3<T>(Vec3<T>(half * P.cwiseQuotient(I)))).eval()};
            };
            in.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) -> ManakovState<T> {
              const T half = h / T(2);
              auto F = [&](const MatX<T>& P) {
                const MatX<T> W = ref::manakov_Omega<T>(A, P);
                return MatX<T>(x.M + half * (P * W - W * P));
              };
              const MatX<T> Mmid = iterate_to_absolute_tolerance(F(x.M), F);
              const MatX<T> W = ref::manakov_Omega<T>(A, Mmid);
              return {(T(2) * Mmid - x.M).eval(), (x.O * ref::cayley_half<T>((h * W).eval())).eval()};
            };
          }
      }
    });

// The time step kept in a float (a `float dt` field, a single-precision setting): h is rounded to
// 24 bits before the step, a relative change of up to 2^-24 that the dyadic steps 1/4 and 1/N of
// the other checks never show (they are exact in a float). The local error gains a term
// (float(h) - h) f, first order in h. Wrong in double and in 50 digits alike.
GM_MUTANT(midpoint_step_size_in_float, "implicit midpoint that keeps the time step h in a float", [](auto& s) {
  using T = scalar_of<decltype(s)>;
  if constexpr (!is_exact_v<T>) {
    for (auto& in : s.integrators)
      if (in.name == "implicit_midpoint") {
        in.rigid_body_step = [](const Vec3<T>& I, const RigidBodyState<T>& x, const T& h) -> RigidBodyState<T> {
          return ref::implicit_midpoint_step<T>(I, x, T(static_cast<float>(to_double(h))));
        };
        in.manakov_step = [](const MatX<T>& A, const ManakovState<T>& x, const T& h) -> ManakovState<T> {
          return ref::manakov_implicit_midpoint_step<T>(A, x, T(static_cast<float>(to_double(h))));
        };
      }
  }
});

}  // namespace mutants_integrator_regimes
}  // namespace gm
