// Double-double numbers: an unevaluated sum hi + lo of two doubles with |lo| <= ulp(hi)/2, about
// 106 bits (unit roundoff ~2^-104 after a few operations). The Taylor oracle (oracle/taylor.hpp)
// computes its middle-order coefficients in this type: they enter the solution multiplied by
// h^k, so they need fewer digits than the low orders, and a double-double product costs a few
// nanoseconds where a cpp_bin_float<50> product costs about a hundred.
//
// Built from the two error-free transformations (Knuth's TwoSum, Dekker's TwoProduct): the
// rounding error of a + b and of a * b is itself a double, computed exactly. Every operation is a
// fixed sequence of IEEE operations, so results are the same on every machine that rounds to
// nearest (which is why TwoProduct uses Dekker's splitting rather than an fma that may or may not
// exist in hardware: both are exact, and the splitting needs nothing).
#pragma once

namespace gm::oracle {

struct DoubleDouble {
  double hi = 0, lo = 0;

  // s + e == a + b exactly, s = fl(a + b).
  static DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double bb = s - a;
    const double e = (a - (s - bb)) + (b - bb);
    return {s, e};
  }
  // The same when |a| >= |b| (or a == 0).
  static DoubleDouble fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
  }
  // p + e == a * b exactly, p = fl(a * b) (no overflow assumed).
  static DoubleDouble two_product(double a, double b) {
    const double p = a * b;
    const auto [ah, al] = split(a);
    const auto [bh, bl] = split(b);
    const double e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return {p, e};
  }

  friend DoubleDouble operator+(const DoubleDouble& x, const DoubleDouble& y) {
    DoubleDouble s = two_sum(x.hi, y.hi);
    const DoubleDouble t = two_sum(x.lo, y.lo);
    s.lo += t.hi;
    s = fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return fast_two_sum(s.hi, s.lo);
  }
  friend DoubleDouble operator-(const DoubleDouble& x) { return {-x.hi, -x.lo}; }
  friend DoubleDouble operator-(const DoubleDouble& x, const DoubleDouble& y) { return x + (-y); }
  friend DoubleDouble operator*(const DoubleDouble& x, const DoubleDouble& y) {
    DoubleDouble p = two_product(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    return fast_two_sum(p.hi, p.lo);
  }
  friend DoubleDouble operator/(const DoubleDouble& x, double d) {
    const double q1 = x.hi / d;
    const DoubleDouble r = x - two_product(q1, d);
    const double q2 = (r.hi + r.lo) / d;
    return fast_two_sum(q1, q2);
  }
  DoubleDouble& operator+=(const DoubleDouble& y) { return *this = *this + y; }

 private:
  struct Halves {
    double high, low;
  };
  // Dekker's splitting: a == high + low, each with at most 26 significant bits.
  static Halves split(double a) {
    const double c = 134217729.0 * a;  // 2^27 + 1
    const double high = c - (c - a);
    return {high, a - high};
  }
};

}  // namespace gm::oracle
