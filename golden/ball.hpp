// A real number enclosed in a ball [mid - rad, mid + rad]: a thin C++ wrapper of Arb's
// arb_t (Debian's libflint-arb-dev), for the certified enclosures of golden/certify.hpp.
//
// Every operation returns a ball that contains every result of the operation on members of its
// operands (Arb's guarantee, with the rounding of the midpoint accounted for in the radius), so a
// computation written with Ball proves what it computes. The working precision of the midpoints
// (bits) is per thread: Ball::Precision scopes it. Only what the oracle's fields
// (oracle/fields.hpp) and the validated Taylor method need is here: +, -, *, /, negation,
// construction from integers and exact rationals, and the queries of the certificate.
#pragma once

#include "core/scalar.hpp"

#include <string>

#include <arb.h>

namespace gm::golden {

class Ball {
 public:
  Ball() { arb_init(x_); }
  Ball(long v) {  // NOLINT(google-explicit-constructor): the fields write T(0), T(1)
    arb_init(x_);
    arb_set_si(x_, v);
  }
  // The exact rational q, enclosed at the working precision (exact when q is dyadic and fits).
  explicit Ball(const Rational& q);
  Ball(const Ball& o) {
    arb_init(x_);
    arb_set(x_, o.x_);
  }
  Ball(Ball&& o) noexcept {
    arb_init(x_);
    arb_swap(x_, o.x_);
  }
  Ball& operator=(const Ball& o) {
    if (this != &o) arb_set(x_, o.x_);
    return *this;
  }
  Ball& operator=(Ball&& o) noexcept {
    arb_swap(x_, o.x_);
    return *this;
  }
  ~Ball() { arb_clear(x_); }

  // The working precision of this thread, in bits, while an object of this class lives.
  class Precision {
   public:
    explicit Precision(long bits) : saved_(bits_) { bits_ = bits; }
    ~Precision() { bits_ = saved_; }
    Precision(const Precision&) = delete;
    Precision& operator=(const Precision&) = delete;

   private:
    long saved_;
  };
  static long bits() { return bits_; }

  friend Ball operator+(const Ball& a, const Ball& b) {
    Ball r;
    arb_add(r.x_, a.x_, b.x_, bits_);
    return r;
  }
  friend Ball operator-(const Ball& a, const Ball& b) {
    Ball r;
    arb_sub(r.x_, a.x_, b.x_, bits_);
    return r;
  }
  friend Ball operator*(const Ball& a, const Ball& b) {
    Ball r;
    arb_mul(r.x_, a.x_, b.x_, bits_);
    return r;
  }
  friend Ball operator/(const Ball& a, const Ball& b) {
    Ball r;
    arb_div(r.x_, a.x_, b.x_, bits_);
    return r;
  }
  friend Ball operator-(const Ball& a) {
    Ball r;
    arb_neg(r.x_, a.x_);
    return r;
  }
  Ball& operator+=(const Ball& b) {
    arb_add(x_, x_, b.x_, bits_);
    return *this;
  }
  Ball& operator-=(const Ball& b) {
    arb_sub(x_, x_, b.x_, bits_);
    return *this;
  }
  // this += a * b, with one rounding.
  void add_product(const Ball& a, const Ball& b) { arb_addmul(x_, a.x_, b.x_, bits_); }
  // Equal for certain (both exact and equal); a ball that may or may not be zero is not == 0.
  friend bool operator==(const Ball& a, const Ball& b) { return arb_eq(a.x_, b.x_) != 0; }
  friend bool operator!=(const Ball& a, const Ball& b) { return !(a == b); }

  // [0, 1] * this: the hull of 0 and this ball.
  Ball times_unit_interval() const;
  // The smallest ball containing this one and o.
  Ball hull(const Ball& o) const;
  // This ball with its radius grown by `extra` (a nonnegative double, rounded up).
  Ball inflated(double extra) const;
  // True when o lies inside this ball (every member of o is a member of this).
  bool contains(const Ball& o) const { return arb_contains(x_, o.x_) != 0; }
  bool is_finite() const { return arb_is_finite(x_) != 0; }

  // Upper bounds, as doubles rounded up: of |x| for every member x, and of the radius.
  double magnitude_bound() const;
  double radius_bound() const;
  // An upper bound of |q - x| over the members x: how far the exact rational q may be from the
  // number this ball encloses.
  double distance_bound(const Rational& q) const;
  // The midpoint to about `digits` significant digits (for messages and the uncertified value).
  std::string to_string(int digits) const;

  const arb_struct* raw() const { return x_; }
  arb_struct* raw() { return x_; }

 private:
  arb_t x_;
  static thread_local long bits_;
};

}  // namespace gm::golden
