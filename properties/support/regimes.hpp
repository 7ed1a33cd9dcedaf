// Input regimes (DESIGN.md, "Input regimes: where bugs hide"): generators that mix the
// generic random box with the special inputs real code has branches for.
//
//   generic     the box of generators.hpp (every component of moderate size)
//   axis        a vector along a coordinate (principal) axis: relative equilibria of the notes
//   near axis   an axis vector plus a perturbation 2^-20 to 2^-60 times smaller
//   zero comp.  one component exactly zero
//   tiny        the generic box scaled by 2^-s, s in [10, 40]  (|x| down to ~1e-14: absolute cut-offs)
//   large       the generic box scaled by 2^s, s in [10, 40]   (overflow, hard-coded epsilons)
//   any binade  scaled by 2^s, s in [-40, 40]
//   thirds      k / (3 2^6): exact in rationals, not representable in double (a cast to double shows)
//
// Bodies: generic triaxial, symmetric tops (two equal moments), spherical tops, scaled by 2^s;
// dimensions n = 2..6 (so(n)) or 3..6 (Manakov); Manakov's A = R D R^T with an exact rational
// rotation R, or diagonal.
//
// Every value is a dyadic rational times a power of two (or, for thirds and rotated A, a rational
// rounded once on input in the floats), so it means the same thing in double, Real50 and Rational
// up to that one rounding of the input. The regime is drawn first from an integer
// range that shrinks toward 0, the generic regime: a failing case still shrinks to a simple one.
// Properties keep tolerances relative to the size of their inputs, so scaling is fair.
#pragma once

#include "properties/support/generators.hpp"
#include "properties/support/pow2.hpp"
#include "properties/support/show.hpp"

#include <ostream>
#include <string>

namespace gm::gen {

// An integer in [lo, hi) drawn uniformly whatever RapidCheck's size: gen::inRange scales its range
// with the size, which ramps from 0 over a run, so a regime index drawn with it would reach the
// last regimes only in the last cases. Still shrinks toward lo (the generic regime).
inline rc::Gen<int> uniform(int lo, int hi) { return rc::gen::resize(100, rc::gen::inRange(lo, hi)); }

using gm::pow2;  // 2^e exactly, in any scalar (pow2.hpp)

// The scale lambda of a motion seen in other units: 2^k, k = 0, 1, -1, ..., 64, -64, in `in`
// cases of `of`, else 1 (both shrink toward 1). Euler's equations, (2.20) and (2.34) are
// homogeneous of degree 2: x(t) solves them iff lambda x(lambda t) does, with the same attitude,
// so a step from lambda x with h / lambda must give lambda times the step from x (exact in binary
// floating point); a cut-off on the size of the state, or an absolute tolerance, breaks that.
template <class T>
rc::Gen<T> motion_scale(int in, int of) {
  return rc::gen::map(rc::gen::pair(uniform(0, of), uniform(0, 129)), [in, of](const std::pair<int, int>& p) {
    return p.first >= of - in ? pow2<T>(zigzag(p.second)) : T(1);
  });
}

// One side of it: 2^(sign j), j = 0..64, shrinking toward 1; sign -1 for a slowly turning body
// (cut-offs, absolute tolerances), +1 for a fast one (overflow, hard-coded step limits).
template <class T>
rc::Gen<T> motion_scale_side(int sign) {
  return rc::gen::map(uniform(0, 65), [sign](int j) { return pow2<T>(sign * j); });
}

inline constexpr int kVectorRegimes = 8;

// Non-dyadic values k / (3 * 2^bits): exact in rationals, correctly rounded in Real50 and double,
// and not representable in double: a 50-digit computation that passes through double changes
// them in the 17th digit (regime "thirds", of the precision class: it catches a cast to double).
template <class T>
T third(const T& x) {
  return x / T(3);
}

// A Vec3 from one of the regimes above (see the table at the top).
template <class T>
rc::Gen<Vec3<T>> regime_vec3() {
  return rc::gen::mapcat(uniform(0, kVectorRegimes), [](int regime) -> rc::Gen<Vec3<T>> {
    switch (regime) {
      case 1:  // along a principal axis
        return rc::gen::map(rc::gen::pair(uniform(0, 3), signed_int(kMaxInt)), [](const std::pair<int, int>& p) {
          Vec3<T> v = Vec3<T>::Zero();
          v(p.first) = dyadic<T>(p.second == 0 ? 1 : p.second, kBits);
          return v;
        });
      case 2:  // near a principal axis: off it by 2^-s of the box, s in [20, 60]
        return rc::gen::map(rc::gen::tuple(uniform(0, 3), uniform(1, kMaxInt + 1), vec3<T>(), uniform(20, 61)),
                            [](const std::tuple<int, int, Vec3<T>, int>& t) {
                              const auto& [axis, k, w, s] = t;
                              Vec3<T> v = (w * pow2<T>(-s)).eval();
                              v(axis) += dyadic<T>(k, kBits);
                              return v;
                            });
      case 3:  // one component exactly zero
        return rc::gen::map(rc::gen::pair(uniform(0, 3), vec3<T>()), [](std::pair<int, Vec3<T>> p) {
          p.second(p.first) = T(0);
          return p.second;
        });
      case 4:  // tiny
        return rc::gen::map(rc::gen::pair(nonzero_vec3<T>(), uniform(10, 41)),
                            [](const std::pair<Vec3<T>, int>& p) { return Vec3<T>(p.first * pow2<T>(-p.second)); });
      case 5:  // large
        return rc::gen::map(rc::gen::pair(vec3<T>(), uniform(10, 41)),
                            [](const std::pair<Vec3<T>, int>& p) { return Vec3<T>(p.first * pow2<T>(p.second)); });
      case 6:  // any binade
        return rc::gen::map(rc::gen::pair(vec3<T>(), uniform(-40, 41)),
                            [](const std::pair<Vec3<T>, int>& p) { return Vec3<T>(p.first * pow2<T>(p.second)); });
      case 7:  // thirds: not representable in double
        return rc::gen::map(vec3<T>(),
                            [](const Vec3<T>& v) { return Vec3<T>(v.unaryExpr([](const T& x) { return third(x); })); });
      default:
        return vec3<T>();
    }
  });
}

// A VecX of length d, scaled by 2^s for s in [-40, 40] (regime 1) or generic (regime 0); one
// component may be zeroed (regime 2); thirds (regime 3).
template <class T>
rc::Gen<VecX<T>> regime_vec(int d) {
  return rc::gen::mapcat(uniform(0, 4), [d](int regime) -> rc::Gen<VecX<T>> {
    if (regime == 3)  // thirds: not representable in double
      return rc::gen::map(vec<T>(d),
                          [](const VecX<T>& v) { return VecX<T>(v.unaryExpr([](const T& x) { return third(x); })); });
    if (regime == 1)
      return rc::gen::map(rc::gen::pair(vec<T>(d), uniform(-40, 41)),
                          [](const std::pair<VecX<T>, int>& p) { return VecX<T>(p.first * pow2<T>(p.second)); });
    if (regime == 2)
      return rc::gen::map(rc::gen::pair(uniform(0, d), vec<T>(d)), [](std::pair<int, VecX<T>> p) {
        p.second(p.first) = T(0);
        return p.second;
      });
    return vec<T>(d);
  });
}

inline constexpr int kBodyRegimes = 5;

// Principal moments: generic (0), symmetric top with a random pair equal (1), spherical top (2),
// scaled by 2^s, s in [-40, 40] (3), a flat body close to the triangle inequality's edge (4).
template <class T>
rc::Gen<Vec3<T>> regime_inertia() {
  return rc::gen::mapcat(uniform(0, kBodyRegimes), [](int regime) -> rc::Gen<Vec3<T>> {
    switch (regime) {
      case 1:
        return rc::gen::map(rc::gen::tuple(uniform(0, 3), positive<T>(64, 2), positive<T>(64, 2)),
                            [](const std::tuple<int, T, T>& t) {
                              const auto& [axis, a, c] = t;  // the two moments other than `axis` are equal
                              Vec3<T> I;
                              I(axis) = a + a;
                              I((axis + 1) % 3) = a + c;
                              I((axis + 2) % 3) = a + c;
                              return I;
                            });
      case 2:
        return rc::gen::map(positive<T>(64, 2), [](const T& a) { return Vec3<T>(a + a, a + a, a + a); });
      case 3:
        return rc::gen::map(rc::gen::pair(inertia<T>(), uniform(-40, 41)),
                            [](const std::pair<Vec3<T>, int>& p) { return Vec3<T>(p.first * pow2<T>(p.second)); });
      case 4:  // a = b large, c = 1/4: I = (b + c, c + a, a + b), two moments nearly half the third
        return rc::gen::map(positive<T>(256, 2), [](const T& a) {
          const T c = dyadic<T>(1, 2);
          return Vec3<T>(a + c, c + a, a + a);
        });
      default:
        return inertia<T>();
    }
  });
}

// A rotation: the identity (regime 1), a quarter turn about an axis (regime 2), or an exact
// rational rotation (generic).
template <class T>
rc::Gen<Mat3<T>> regime_rotation3() {
  return rc::gen::mapcat(uniform(0, 3), [](int regime) -> rc::Gen<Mat3<T>> {
    if (regime == 1) return rc::gen::just(Mat3<T>(Mat3<T>::Identity()));
    if (regime == 2)
      return rc::gen::map(uniform(0, 3), [](int axis) {
        Mat3<T> R = Mat3<T>::Zero();
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;
        R(axis, axis) = T(1);
        R(i, j) = T(-1);
        R(j, i) = T(1);
        return R;
      });
    return rotation3<T>();
  });
}

// Manakov's body: A = R D R^T, symmetric positive definite, with D = diag(d) and R an exact
// rational rotation (or the identity). `spread` = max d / min d bounds the condition of
// X -> A X + X A, which the tolerances of properties that solve for Omega scale with.
template <class T>
struct ManakovBody {
  MatX<T> A;
  VecX<T> d;
  MatX<T> R;
  T spread;
};

// A counterexample shows the body as the notes name it: A, and the D and R it was made from.
template <class T>
void showValue(const ManakovBody<T>& b, std::ostream& os) {
  os << "A = " << show_matrix(b.A) << " (R diag(d) R^T with d = " << show_matrix(b.d) << ", R = " << show_matrix(b.R)
     << ")";
}

// n in [3, 6]; regimes: diagonal (0), rotated (1), rotated with two equal entries of D (2),
// scaled by 2^s, s in [-20, 20] (3).
template <class T>
rc::Gen<ManakovBody<T>> manakov_body(int n) {
  return rc::gen::mapcat(uniform(0, 4), [n](int regime) -> rc::Gen<ManakovBody<T>> {
    return rc::gen::map(
        rc::gen::tuple(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n), uniform(1, 129)),
                       skew<Rational>(n, 8, 2), uniform(-20, 21)),
        [n, regime](const std::tuple<std::vector<int>, MatX<Rational>, int>& t) {
          const auto& [ks, S, s] = t;
          VecX<Rational> d(n);
          for (int i = 0; i < n; ++i) d(i) = dyadic<Rational>(ks[static_cast<std::size_t>(i)], 2);
          if (regime == 2) d(1) = d(0);
          if (regime == 3) d *= pow2<Rational>(s);
          const MatX<Rational> R = regime == 0 ? MatX<Rational>(MatX<Rational>::Identity(n, n)) : cayley_rational(S);
          const MatX<Rational> A = R * d.asDiagonal() * R.transpose();
          ManakovBody<T> b;
          b.A = convert_matrix<T>(A);
          b.d = convert_matrix<T>(d);
          b.R = convert_matrix<T>(R);
          b.spread = convert<T>(Rational(d.maxCoeff() / d.minCoeff()));
          return b;
        });
  });
}

}  // namespace gm::gen
