// The three scalar types of the suite, in one place:
//   double    -- what users' code runs in;
//   Real50    -- a 50-digit binary float (168-bit mantissa, eps ~ 5.3e-51), expression templates off;
//   Rational  -- exact cpp_rational, for algebraic identities checked with tolerance zero.
// plus Real70, the working precision of golden-trajectory generation (>= 60 digits).
//
// For each scalar: its epsilon (zero for Rational), a name used in test labels and reports,
// full-precision printing, exact parsing of decimal strings, and Eigen NumTraits.
#pragma once

#include <Eigen/Core>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/traits/is_byte_container.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

// Boost 1.74 probes every type it might be constructed from as a possible byte container
// through `const_iterator`, which Eigen 3.4 defines as `void` for matrices and expressions;
// the probe then fails to compile inside `Rational * matrix`. Every Eigen expression derives
// from EigenBase<Derived> (including the bases MatrixBase<X> etc., whose Derived is X), so one
// constrained specialisation covers them all (TOOLCHAIN.md, pitfall 1).
namespace gm::detail {
template <class C>
concept eigen_object = requires(const C& c) {
  c.derived();
}
&&std::is_base_of_v<Eigen::EigenBase<std::decay_t<decltype(std::declval<const C&>().derived())>>, C>;
}  // namespace gm::detail

namespace boost::multiprecision::detail {
template <class C>
requires gm::detail::eigen_object<C>
struct is_byte_container<C> : boost::false_type {
};
}  // namespace boost::multiprecision::detail

namespace gm {

namespace bmp = boost::multiprecision;

using Real50 = bmp::number<bmp::cpp_bin_float<50>, bmp::et_off>;
using Real70 = bmp::number<bmp::cpp_bin_float<70>, bmp::et_off>;
using Rational = bmp::number<bmp::cpp_rational_backend, bmp::et_off>;

enum class ScalarKind { Double, MP50, Exact };

template <class T>
struct ScalarInfo;

template <>
struct ScalarInfo<double> {
  static constexpr ScalarKind kind = ScalarKind::Double;
  static constexpr const char* name = "double";
  static constexpr bool exact = false;
};
template <>
struct ScalarInfo<Real50> {
  static constexpr ScalarKind kind = ScalarKind::MP50;
  static constexpr const char* name = "mp50";
  static constexpr bool exact = false;
};
template <>
struct ScalarInfo<Real70> {
  static constexpr ScalarKind kind = ScalarKind::MP50;  // never a test scalar; golden only
  static constexpr const char* name = "mp70";
  static constexpr bool exact = false;
};
template <>
struct ScalarInfo<Rational> {
  static constexpr ScalarKind kind = ScalarKind::Exact;
  static constexpr const char* name = "exact";
  static constexpr bool exact = true;
};

template <class T>
inline constexpr bool is_exact_v = ScalarInfo<T>::exact;

const char* scalar_name(ScalarKind k);

// Machine epsilon of T (distance from 1 to the next representable number); 0 for Rational.
template <class T>
T eps() {
  if constexpr (is_exact_v<T>)
    return T(0);
  else
    return std::numeric_limits<T>::epsilon();
}

// eps as a double, for reporting residuals in units of eps.
template <class T>
double eps_double() {
  if constexpr (is_exact_v<T>)
    return 0.0;
  else
    return static_cast<double>(std::numeric_limits<T>::epsilon());
}

template <class T>
double to_double(const T& x) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return x.template convert_to<double>();
}

template <class T>
bool is_finite(const T& x) {
  if constexpr (is_exact_v<T>)
    return true;
  else {
    using boost::multiprecision::isfinite;
    using std::isfinite;
    return isfinite(x);
  }
}

// Every digit needed to read the value back exactly: 17 significant digits for double,
// 53 for Real50, an exact fraction p/q for Rational.
std::string to_string_full(double x);
std::string to_string_full(const Real50& x);
std::string to_string_full(const Real70& x);
std::string to_string_full(const Rational& x);

// Exact value of a decimal string ("-1.25e-3", "17", "0.5") as a rational. Throws
// std::invalid_argument naming the offending text when it is not a finite decimal number.
Rational parse_decimal_rational(std::string_view text);

// A decimal string converted to T: exact for Rational, correctly rounded for the floats.
template <class T>
T from_decimal(std::string_view text);

template <>
double from_decimal<double>(std::string_view text);
template <>
Real50 from_decimal<Real50>(std::string_view text);
template <>
Real70 from_decimal<Real70>(std::string_view text);
template <>
Rational from_decimal<Rational>(std::string_view text);

// Conversion between scalars (e.g. exact generator values into the float under test).
template <class To, class From>
To convert(const From& x) {
  if constexpr (std::is_same_v<To, From>)
    return x;
  else if constexpr (std::is_same_v<To, double>)
    return to_double(x);
  else if constexpr (std::is_same_v<From, double>)
    return To(x);
  else if constexpr (is_exact_v<To> && !is_exact_v<From>)
    return To(x);  // exact value of a binary float
  else
    return x.template convert_to<To>();
}

}  // namespace gm

// Eigen needs to know a few things about the multiprecision scalars. Its generic defaults
// take dummy_precision() = 0, which would turn every default isApprox into an exact
// comparison (TOOLCHAIN.md, pitfall 3); this suite never relies on isApprox, but the
// decompositions used for isospectrality read these values.
namespace gm::detail {
// NumTraits shared by the binary multiprecision floats (Real50, Real70).
template <class Real>
struct MpFloatNumTraits : Eigen::GenericNumTraits<Real> {
  typedef Real NonInteger;
  typedef Real Literal;
  typedef Real Nested;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 10,
    AddCost = 10,
    MulCost = 40
  };
  static inline Real epsilon() { return std::numeric_limits<Real>::epsilon(); }
  static inline Real dummy_precision() { return epsilon() * 1024; }
  static inline int digits10() { return std::numeric_limits<Real>::digits10; }
  static inline int digits() { return std::numeric_limits<Real>::digits; }
  static inline Real highest() { return (std::numeric_limits<Real>::max)(); }
  static inline Real lowest() { return std::numeric_limits<Real>::lowest(); }
  static inline Real infinity() { return std::numeric_limits<Real>::infinity(); }
  static inline Real quiet_NaN() { return std::numeric_limits<Real>::quiet_NaN(); }
};
}  // namespace gm::detail

namespace Eigen {
template <>
struct NumTraits<gm::Real50> : gm::detail::MpFloatNumTraits<gm::Real50> {
  typedef gm::Real50 Real;
};
template <>
struct NumTraits<gm::Real70> : gm::detail::MpFloatNumTraits<gm::Real70> {
  typedef gm::Real70 Real;
};
template <>
struct NumTraits<gm::Rational> : GenericNumTraits<gm::Rational> {
  typedef gm::Rational Real;
  typedef gm::Rational NonInteger;
  typedef gm::Rational Literal;
  typedef gm::Rational Nested;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 20,
    AddCost = 100,
    MulCost = 100
  };
  static inline Real epsilon() { return Real(0); }
  static inline Real dummy_precision() { return Real(0); }
  static inline int digits10() { return 0; }
};
}  // namespace Eigen
