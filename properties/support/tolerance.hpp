// Tolerance classes (DESIGN.md) and the comparisons properties use instead of bare literals.
//
//   exact      -- algebraic identities: the residual must be exactly 0 in Rational;
//                 in floats it must be <= k * eps(T) * scale.
//   roundoff   -- evaluations in floating point, exact conservation by a method that preserves an
//                 invariant: <= k * eps(T) * scale.
//   truncation -- integrators: the measured convergence slope against the claimed order.
//
// `scale` is the size of the quantities that were combined (a product of input norms, say) and
// k a small count of rounding errors taken from the formula; each call site says where its k
// comes from. A residual is reported in units of eps(T) * scale.
//
// Every comparison fails on NaN or Inf, with a message saying so: a NaN never passes.
// On failure the message shows both sides, their difference and the residual, all at full
// precision, and the property fails through RapidCheck (which then shrinks the input).
#pragma once

#include "core/linalg.hpp"
#include "properties/support/show.hpp"

#include <rapidcheck.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace gm {

// Fails the current RapidCheck case with exactly this message (RC_FAIL would prepend the
// source text of its argument).
[[noreturn]] inline void fail(const std::string& message) {
  throw rc::detail::CaseResult(rc::detail::CaseResult::Type::Failure, message);
}

// The worst residual seen while a property runs, in units of eps * scale: the runner resets it
// before each property and reports it with the verdict.
struct ResidualLog {
  double worst_eps_units = 0.0;  // max over checks of residual / (eps * scale); 0 when exact
  double worst_absolute = 0.0;   // the absolute residual of that check
  std::string worst_check;       // the check's description with both sides
  long checks = 0;

  void reset() { *this = ResidualLog{}; }
};
ResidualLog& residual_log();

// Whether residual r is worse than the worst so far: a non-finite residual (NaN, inf) is the worst
// of all and stays the worst (a bare `!(r <= worst)` would let a later finite r replace a NaN).
template <class T>
bool worse(const T& r, const T& worst) {
  return is_finite(worst) && !(r <= worst);
}

namespace detail {

template <class A, class T, bool = std::is_base_of_v<Eigen::EigenBase<A>, A>>
struct plain_of {
  using type = T;
};
template <class A, class T>
struct plain_of<A, T, true> {
  using type = typename Eigen::internal::plain_matrix_type<A>::type;
};

template <class X>
auto residual_of(const X& lhs, const X& rhs) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<X>, X>)
    return max_abs((lhs - rhs).eval());
  else
    return abs_value(X(lhs - rhs));
}

template <class X>
bool finite(const X& x) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<X>, X>)
    return all_finite(x);
  else
    return is_finite(x);
}

template <class X>
X difference(const X& lhs, const X& rhs) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<X>, X>)
    return (lhs - rhs).eval();
  else
    return X(lhs - rhs);
}

// Residual in units of eps(T) * scale, as a double (inf when scale is 0 and residual is not).
template <class T>
double eps_units(const T& residual, const T& scale) {
  if constexpr (is_exact_v<T>) {
    return residual == T(0) ? 0.0 : std::numeric_limits<double>::infinity();
  } else {
    if (residual == T(0)) return 0.0;
    const T unit = eps<T>() * scale;
    if (unit == T(0)) return std::numeric_limits<double>::infinity();
    return to_double(T(residual / unit));
  }
}

// How a failure names the two sides of a comparison: a definition check compares the
// subject's slot with the notes' formula and says "yours" and "the notes'"; the other properties
// compare two computations and say "lhs" and "rhs". The runner sets them for each property.
struct SideNames {
  std::string lhs = "lhs", rhs = "rhs";
};
SideNames& side_names();

std::string describe_failure(std::string_view what, std::string_view kind, const std::string& lhs,
                             const std::string& rhs, const std::string& diff, const std::string& residual, double units,
                             const std::string& allowed);

// A residual of the size of double round-off (relative 1e-19 .. 1e-11) in a 50-digit or
// exact run means part of the computation is done in double; the message says so. Empty otherwise.
std::string double_precision_hint(const char* scalar, double relative_residual);

}  // namespace detail

namespace detail {

// The comparison on plain values (a scalar T or a plain Eigen matrix over T); instantiated once
// for the common shapes in tolerance.cpp (see the extern declarations below).
template <class X, class T>
void require_close_plain(std::string_view what, const X& lhs, const X& rhs, const T& scale, double k) {
  auto& log = residual_log();
  ++log.checks;
  if (!detail::finite(lhs) || !detail::finite(rhs)) {
    fail(std::string(what) + ": non-finite value (NaN or Inf); a NaN is never a pass\n  " + detail::side_names().lhs +
         " = " + show_value(lhs) + "\n  " + detail::side_names().rhs + " = " + show_value(rhs));
  }
  const T residual = T(detail::residual_of(lhs, rhs));
  T allowed(0);
  if constexpr (!is_exact_v<T>) allowed = T(k) * eps<T>() * scale;
  const double units = detail::eps_units<T>(residual, scale);
  if (units >= log.worst_eps_units) {
    log.worst_eps_units = units;
    log.worst_absolute = to_double(residual);
    log.worst_check = std::string(what);
  }
  if (residual > allowed) {
    std::string hint;
    if constexpr (!std::is_same_v<T, double>)
      if (scale != T(0)) hint = double_precision_hint(ScalarInfo<T>::name, to_double(T(residual / scale)));
    fail(detail::describe_failure(what, is_exact_v<T> ? "exact" : "roundoff", show_value(lhs), show_value(rhs),
                                  show_value(detail::difference(lhs, rhs)), to_string_full(residual), units,
                                  is_exact_v<T> ? std::string("0 (exact arithmetic)")
                                                : to_string_full(allowed) + " = " + std::to_string(k) +
                                                      " eps * scale, scale = " + to_string_full(scale)) +
         hint);
  }
}

#define GM_REQUIRE_CLOSE_FOR(PREFIX, T)                                                                            \
  PREFIX template void require_close_plain<T, T>(std::string_view, const T&, const T&, const T&, double);          \
  PREFIX template void require_close_plain<Vec3<T>, T>(std::string_view, const Vec3<T>&, const Vec3<T>&, const T&, \
                                                       double);                                                    \
  PREFIX template void require_close_plain<Vec6<T>, T>(std::string_view, const Vec6<T>&, const Vec6<T>&, const T&, \
                                                       double);                                                    \
  PREFIX template void require_close_plain<Mat3<T>, T>(std::string_view, const Mat3<T>&, const Mat3<T>&, const T&, \
                                                       double);                                                    \
  PREFIX template void require_close_plain<VecX<T>, T>(std::string_view, const VecX<T>&, const VecX<T>&, const T&, \
                                                       double);                                                    \
  PREFIX template void require_close_plain<MatX<T>, T>(std::string_view, const MatX<T>&, const MatX<T>&, const T&, \
                                                       double);

GM_REQUIRE_CLOSE_FOR(extern, double)
GM_REQUIRE_CLOSE_FOR(extern, Real50)
GM_REQUIRE_CLOSE_FOR(extern, Rational)

}  // namespace detail

// |lhs - rhs| <= k eps(T) scale (entrywise max), exactly 0 in Rational.
// Use for the `exact` class (algebraic identities) and the `roundoff` class alike: the class
// is declared by the property; in rationals only exact identities are ever instantiated.
// lhs and rhs may be scalars of type T or Eigen matrices/expressions over T (rhs is converted to
// the plain type of lhs).
template <class A, class B, class T>
void require_close(std::string_view what, const A& lhs_in, const B& rhs_in, const T& scale, double k) {
  using X = typename detail::plain_of<A, T>::type;
  const X lhs = lhs_in;
  const X rhs = rhs_in;
  detail::require_close_plain<X, T>(what, lhs, rhs, scale, k);
}

// A condition that is not a comparison of two values (e.g. a definiteness test); `detail` says
// what was seen.
inline void require(std::string_view what, bool ok, const std::string& detail_text = {}) {
  ++residual_log().checks;
  if (!ok) fail(std::string(what) + (detail_text.empty() ? "" : "\n  " + detail_text));
}

// |x|_inf for scalars and matrices, as T (used to build scales).
template <class X>
auto norm_inf(const X& x) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<X>, X>)
    return max_abs(x);
  else
    return abs_value(x);
}

}  // namespace gm
