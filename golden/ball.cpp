#include "golden/ball.hpp"

#include <flint/fmpq.h>

namespace gm::golden {

thread_local long Ball::bits_ = 256;

namespace {

// The exact rational q as Flint's fmpq (through its decimal numerator and denominator: exact).
struct ExactRational {
  fmpq_t q;
  explicit ExactRational(const Rational& r) {
    fmpq_init(q);
    const std::string text = numerator(r).str() + "/" + denominator(r).str();
    fmpq_set_str(q, text.c_str(), 10);
  }
  ~ExactRational() { fmpq_clear(q); }
  ExactRational(const ExactRational&) = delete;
  ExactRational& operator=(const ExactRational&) = delete;
};

double rounded_up(const arf_t a) { return arf_get_d(a, ARF_RND_UP); }

}  // namespace

Ball::Ball(const Rational& r) {
  arb_init(x_);
  const ExactRational q(r);
  arb_set_fmpq(x_, q.q, bits_);
}

Ball Ball::times_unit_interval() const {
  Ball zero(0L);
  return hull(zero);
}

Ball Ball::hull(const Ball& o) const {
  Ball r;
  arb_union(r.x_, x_, o.x_, bits_);
  return r;
}

Ball Ball::inflated(double extra) const {
  Ball r(*this);
  mag_t m;
  mag_init(m);
  mag_set_d(m, extra);  // rounds up
  arb_add_error_mag(r.x_, m);
  mag_clear(m);
  return r;
}

double Ball::magnitude_bound() const {
  arf_t u;
  arf_init(u);
  arb_get_abs_ubound_arf(u, x_, 64);
  const double d = rounded_up(u);
  arf_clear(u);
  return d;
}

double Ball::radius_bound() const { return mag_get_d(arb_radref(x_)); }

double Ball::distance_bound(const Rational& q) const {
  const Ball exact(q);  // at the working precision: a ball around q, itself enclosing q
  return (*this - exact).magnitude_bound();
}

std::string Ball::to_string(int digits) const {
  char* s = arb_get_str(x_, digits, 0);
  std::string out(s);
  flint_free(s);
  return out;
}

}  // namespace gm::golden
