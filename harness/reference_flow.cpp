#include "harness/reference_flow.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

namespace gm::harness {

namespace {

using R = Real50;
constexpr int kOrder = 36;

// Taylor coefficients (normalised: x(t0 + s) = sum_k c_k s^k) of Pi and O to order kOrder.
struct Coefficients {
  std::array<Vec3<R>, kOrder + 1> Pi;
  std::array<Mat3<R>, kOrder + 1> O;
};

Vec3<R> cross(const Vec3<R>& a, const Vec3<R>& b) {
  return Vec3<R>(a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2), a(0) * b(1) - a(1) * b(0));
}

// O hat(w), hat(w) v = w x v, written out so the truth depends on no subject's hat map.
Mat3<R> times_hat(const Mat3<R>& O, const Vec3<R>& w) {
  Mat3<R> out;
  for (int i = 0; i < 3; ++i) {
    const Vec3<R> row(O(i, 0), O(i, 1), O(i, 2));
    // (row^T hat(w))_k = sum_j row_j hat(w)_jk = (row x w)_k
    const Vec3<R> r = cross(row, w);
    out(i, 0) = r(0);
    out(i, 1) = r(1);
    out(i, 2) = r(2);
  }
  return out;
}

void coefficients(const Vec3<R>& Iinv, const RigidBodyState<R>& x, Coefficients& c) {
  std::array<Vec3<R>, kOrder + 1> W;
  c.Pi[0] = x.Pi;
  c.O[0] = x.O;
  for (int k = 0; k < kOrder; ++k) {
    W[k] = c.Pi[k].cwiseProduct(Iinv);
    Vec3<R> dPi = Vec3<R>::Zero();
    Mat3<R> dO = Mat3<R>::Zero();
    for (int j = 0; j <= k; ++j) {
      dPi += cross(c.Pi[j], W[k - j]);
      dO += times_hat(c.O[j], W[k - j]);
    }
    const R inv = R(1) / R(k + 1);
    c.Pi[k + 1] = dPi * inv;
    c.O[k + 1] = dO * inv;
  }
}

R size(const Coefficients& c, int k) {
  return std::max(max_abs(c.Pi[k]), max_abs(c.O[k]));
}

RigidBodyState<R> evaluate(const Coefficients& c, const R& s) {
  RigidBodyState<R> x{c.Pi[kOrder], c.O[kOrder]};
  for (int k = kOrder - 1; k >= 0; --k) {
    x.Pi = (x.Pi * s + c.Pi[k]).eval();
    x.O = (x.O * s + c.O[k]).eval();
  }
  return x;
}

// Step size from the last two coefficients (Jorba and Zou's rule): their terms stay below the
// tolerance, and the terms decay geometrically beyond them.
R step_size(const Coefficients& c, const R& tol) {
  R h(1e6);
  for (int k : {kOrder - 1, kOrder}) {
    const R ck = size(c, k);
    if (ck > R(0)) h = std::min(h, R(pow(tol / ck, R(1) / R(k))));
  }
  return h * R(0.9);
}

std::string estimate_text(const R& n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", n.convert_to<double>());
  return buf;
}

}  // namespace

std::vector<RigidBodyState<R>> reference_rigid_body(const Vec3<R>& I, const RigidBodyState<R>& x0, const R& t0,
                                                   const std::vector<R>& times, const ReferenceLimits& limits) {
  for (int i = 0; i < 3; ++i)
    if (!(I(i) > R(0))) throw std::invalid_argument("the moments of inertia must be positive");
  if (!all_finite(x0.Pi) || !all_finite(x0.O)) throw std::invalid_argument("the initial state is not finite");
  const Vec3<R> Iinv(R(1) / I(0), R(1) / I(1), R(1) / I(2));
  const R scale = std::max(R(1), std::max(max_abs(x0.Pi), max_abs(x0.O)));
  const R tol = R(limits.tolerance) * scale;

  for (std::size_t i = 0; i < times.size(); ++i)
    if (times[i] < (i == 0 ? t0 : times[i - 1]))
      throw std::invalid_argument("reference times must be non-decreasing and not before t0");

  // Step from t to t + h; every requested time inside the step is evaluated from the same
  // polynomial (dense output), so many output times cost little more than the steps.
  std::vector<RigidBodyState<R>> out;
  out.reserve(times.size());
  R t = t0;
  RigidBodyState<R> x = x0;
  Coefficients c;
  long steps = 0;
  std::size_t next = 0;
  while (next < times.size() && times[next] == t) out.push_back(x), ++next;
  const R last = times.empty() ? t0 : times.back();
  bool estimated = false;
  while (next < times.size()) {
    coefficients(Iinv, x, c);
    R h = step_size(c, tol);
    // The step size barely changes along a free rigid body (|Omega| is bounded by the invariants):
    // refuse at once what would take too long, rather than after minutes.
    if (!estimated) {
      estimated = true;
      if (R((last - t) / h) > R(limits.max_steps))
        throw std::length_error("the reference solution would need about " + estimate_text(R((last - t) / h)) +
                                " Taylor steps to reach t = " + to_string_full(last) + " (the limit is " +
                                std::to_string(limits.max_steps) + "); shorten the run or scale it down");
    }
    if (t + h > last) h = last - t;
    while (next < times.size() && times[next] <= t + h) out.push_back(evaluate(c, times[next] - t)), ++next;
    x = evaluate(c, h);
    t += h;
    if (++steps > limits.max_steps)
      throw std::length_error("the reference solution would need more than " + std::to_string(limits.max_steps) +
                              " Taylor steps to reach t = " + to_string_full(last));
  }
  return out;
}

}  // namespace gm::harness
