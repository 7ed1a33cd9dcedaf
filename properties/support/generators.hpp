// RapidCheck generators for the suite's inputs.
//
// Every real number drawn is a dyadic rational k / 2^bits with k a bounded integer: exactly
// representable in double, in Real50 and in Rational, so one drawn input means the same thing in
// all three scalars. Integers are drawn "zig-zag" (0, 1, -1, 2, -2, ...) so that RapidCheck
// shrinks them toward 0; positive quantities shrink toward their smallest allowed value.
//
// Rotations are exact rational orthogonal matrices (Cayley transform of a dyadic skew matrix),
// computed in Rational and then converted: exact in Rational, correctly rounded in the floats.
#pragma once

#include "core/linalg.hpp"
#include "properties/support/show.hpp"

#include <rapidcheck.h>

namespace gm::gen {

// Default ranges: reals in [-16, 16] on a grid of 1/64.
inline constexpr int kMaxInt = 1024;
inline constexpr int kBits = 6;

// 0, 1, -1, 2, -2, ... : index 0 is 0, so shrinking toward index 0 shrinks toward 0.
inline int zigzag(int i) { return (i % 2) ? (i + 1) / 2 : -(i / 2); }

inline rc::Gen<int> signed_int(int max_abs) { return rc::gen::map(rc::gen::inRange(0, 2 * max_abs + 1), zigzag); }

template <class T>
T dyadic(int k, int bits) {
  T x(k);
  for (int b = 0; b < bits; ++b) x /= T(2);
  return x;
}

// k / 2^bits, |k| <= max_abs.
template <class T>
rc::Gen<T> scalar(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(signed_int(max_abs), [bits](int k) { return dyadic<T>(k, bits); });
}

// k / 2^bits, 1 <= k <= max; shrinks toward 1 / 2^bits.
template <class T>
rc::Gen<T> positive(int max = kMaxInt, int bits = kBits) {
  return rc::gen::map(rc::gen::inRange(1, max + 1), [bits](int k) { return dyadic<T>(k, bits); });
}

template <class T>
rc::Gen<VecX<T>> vec(int n, int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n), signed_int(max_abs)),
                      [bits](const std::vector<int>& ks) {
                        VecX<T> v(static_cast<Eigen::Index>(ks.size()));
                        for (std::size_t i = 0; i < ks.size(); ++i)
                          v(static_cast<Eigen::Index>(i)) = dyadic<T>(ks[i], bits);
                        return v;
                      });
}

template <class T>
rc::Gen<Vec3<T>> vec3(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec<T>(3, max_abs, bits), [](const VecX<T>& v) { return Vec3<T>(v); });
}

template <class T>
rc::Gen<Vec6<T>> vec6(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec<T>(6, max_abs, bits), [](const VecX<T>& v) { return Vec6<T>(v); });
}

// A vector that is not zero (drawn, then nudged off zero deterministically so shrinking still
// converges to a simple value).
template <class T>
rc::Gen<Vec3<T>> nonzero_vec3(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec3<T>(max_abs, bits), [bits](Vec3<T> v) {
    if (v.isZero()) v(0) = dyadic<T>(1, bits);
    return v;
  });
}

template <class T>
rc::Gen<MatX<T>> mat(int rows, int cols, int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec<T>(rows * cols, max_abs, bits), [rows, cols](const VecX<T>& v) {
    MatX<T> m(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) m(i, j) = v(i * cols + j);
    return m;
  });
}

template <class T>
rc::Gen<Mat3<T>> mat3(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(mat<T>(3, 3, max_abs, bits), [](const MatX<T>& m) { return Mat3<T>(m); });
}

// Skew-symmetric n x n matrix with dyadic entries.
template <class T>
rc::Gen<MatX<T>> skew(int n, int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec<T>(n * (n - 1) / 2, max_abs, bits), [n](const VecX<T>& v) {
    MatX<T> m = MatX<T>::Zero(n, n);
    int k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        m(i, j) = v(k);
        m(j, i) = -v(k);
        ++k;
      }
    return m;
  });
}

template <class T>
rc::Gen<Mat3<T>> skew3(int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(skew<T>(3, max_abs, bits), [](const MatX<T>& m) { return Mat3<T>(m); });
}

template <class T>
rc::Gen<MatX<T>> symmetric(int n, int max_abs = kMaxInt, int bits = kBits) {
  return rc::gen::map(vec<T>(n * (n + 1) / 2, max_abs, bits), [n](const VecX<T>& v) {
    MatX<T> m(n, n);
    int k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j) {
        m(i, j) = v(k);
        m(j, i) = v(k);
        ++k;
      }
    return m;
  });
}

// Cayley transform R = (Id - S)^-1 (Id + S) of a skew S: orthogonal with det R = +1, exactly,
// when computed in Rational. Entries of S are k / 4 with |k| <= 8 to keep denominators small.
MatX<Rational> cayley_rational(const MatX<Rational>& S);

template <class T>
rc::Gen<MatX<T>> rotation(int n) {
  return rc::gen::map(skew<Rational>(n, 8, 2),
                      [](const MatX<Rational>& S) { return convert_matrix<T>(cayley_rational(S)).eval(); });
}

template <class T>
rc::Gen<Mat3<T>> rotation3() {
  return rc::gen::map(rotation<T>(3), [](const MatX<T>& m) { return Mat3<T>(m); });
}

// Principal moments of inertia (I1, I2, I3) = (b + c, c + a, a + b) with a, b, c > 0: positive
// and satisfying the strict triangle inequalities (any such triple has this form). Values in
// [1/2, 32]; shrinks toward the sphere a = b = c.
template <class T>
rc::Gen<Vec3<T>> inertia(int max = 64, int bits = 2) {
  return rc::gen::map(rc::gen::tuple(positive<T>(max, bits), positive<T>(max, bits), positive<T>(max, bits)),
                      [](const std::tuple<T, T, T>& abc) {
                        const auto& [a, b, c] = abc;
                        return Vec3<T>(b + c, c + a, a + b);
                      });
}

// Principal moments that are pairwise distinct (a generic, triaxial body).
template <class T>
rc::Gen<Vec3<T>> triaxial_inertia(int max = 64, int bits = 2) {
  return rc::gen::suchThat(inertia<T>(max, bits),
                           [](const Vec3<T>& I) { return I(0) != I(1) && I(1) != I(2) && I(0) != I(2); });
}

// A full inertia tensor R diag(I) R^T with R an exact rational rotation.
template <class T>
rc::Gen<Mat3<T>> inertia_tensor() {
  return rc::gen::map(rc::gen::pair(inertia<Rational>(), rotation<Rational>(3)),
                      [](const std::pair<Vec3<Rational>, MatX<Rational>>& p) {
                        const Mat3<Rational> R = p.second;
                        const Mat3<Rational> J = R * p.first.asDiagonal() * R.transpose();
                        return Mat3<T>(convert_matrix<T>(J));
                      });
}

// Each generator is instantiated once, in generators.cpp, for the three scalars: without this,
// every property file would instantiate RapidCheck's generator machinery over Real50 and Rational
// again (measured: ~3 s of compilation per file).
#define GM_GENERATORS_FOR(PREFIX, T)                              \
  PREFIX template rc::Gen<T> scalar<T>(int, int);                 \
  PREFIX template rc::Gen<T> positive<T>(int, int);               \
  PREFIX template rc::Gen<VecX<T>> vec<T>(int, int, int);         \
  PREFIX template rc::Gen<Vec3<T>> vec3<T>(int, int);             \
  PREFIX template rc::Gen<Vec6<T>> vec6<T>(int, int);             \
  PREFIX template rc::Gen<Vec3<T>> nonzero_vec3<T>(int, int);     \
  PREFIX template rc::Gen<MatX<T>> mat<T>(int, int, int, int);    \
  PREFIX template rc::Gen<Mat3<T>> mat3<T>(int, int);             \
  PREFIX template rc::Gen<MatX<T>> skew<T>(int, int, int);        \
  PREFIX template rc::Gen<Mat3<T>> skew3<T>(int, int);            \
  PREFIX template rc::Gen<MatX<T>> symmetric<T>(int, int, int);   \
  PREFIX template rc::Gen<MatX<T>> rotation<T>(int);              \
  PREFIX template rc::Gen<Mat3<T>> rotation3<T>();                \
  PREFIX template rc::Gen<Vec3<T>> inertia<T>(int, int);          \
  PREFIX template rc::Gen<Vec3<T>> triaxial_inertia<T>(int, int); \
  PREFIX template rc::Gen<Mat3<T>> inertia_tensor<T>();

GM_GENERATORS_FOR(extern, double)
GM_GENERATORS_FOR(extern, Real50)
GM_GENERATORS_FOR(extern, Rational)

}  // namespace gm::gen
