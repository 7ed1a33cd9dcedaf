#include "core/scalar.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace gm {

const char* scalar_name(ScalarKind k) {
  switch (k) {
    case ScalarKind::Double:
      return "double";
    case ScalarKind::MP50:
      return "mp50";
    case ScalarKind::Exact:
      return "exact";
  }
  return "?";
}

std::string to_string_full(double x) {
  std::ostringstream os;
  os.precision(std::numeric_limits<double>::max_digits10);
  os << x;
  return os.str();
}

template <class F>
static std::string float_full(const F& x) {
  std::ostringstream os;
  os.precision(std::numeric_limits<F>::max_digits10);
  os << x;
  return os.str();
}

std::string to_string_full(const Real50& x) { return float_full(x); }
std::string to_string_full(const Real70& x) { return float_full(x); }

std::string to_string_full(const Rational& x) {
  std::ostringstream os;
  os << x;  // numerator/denominator, exact
  return os.str();
}

Rational parse_decimal_rational(std::string_view text) {
  auto bad = [&](const char* why) {
    return std::invalid_argument("not a finite decimal number (" + std::string(why) + "): '" + std::string(text) + "'");
  };
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  std::size_t end = n;
  while (end > i && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  if (i == end) throw bad("empty");
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') {
    negative = text[i] == '-';
    ++i;
  }
  std::string digits;
  long long frac_digits = 0;
  bool seen_point = false, seen_digit = false;
  for (; i < end; ++i) {
    char c = text[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      digits.push_back(c);
      seen_digit = true;
      if (seen_point) ++frac_digits;
    } else if (c == '.' && !seen_point) {
      seen_point = true;
    } else {
      break;
    }
  }
  if (!seen_digit) throw bad("no digits");
  long long exponent = 0;
  if (i < end && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const char* first = text.data() + i;
    const char* last = text.data() + end;
    if (first != last && *first == '+') ++first;
    auto [ptr, ec] = std::from_chars(first, last, exponent);
    if (ec != std::errc() || ptr != last) throw bad("malformed exponent");
    if (exponent > 5000 || exponent < -5000) throw bad("exponent out of range");
    i = end;
  }
  if (i != end) throw bad("unexpected character");
  // cpp_int reads a leading 0 as an octal prefix: strip leading zeros.
  const auto first_nonzero = digits.find_first_not_of('0');
  digits = first_nonzero == std::string::npos ? std::string("0") : digits.substr(first_nonzero);
  bmp::cpp_int mantissa(digits);
  long long shift = exponent - frac_digits;
  Rational value(mantissa);
  if (shift > 0)
    value *= Rational(bmp::pow(bmp::cpp_int(10), static_cast<unsigned>(shift)));
  else if (shift < 0)
    value /= Rational(bmp::pow(bmp::cpp_int(10), static_cast<unsigned>(-shift)));
  return negative ? Rational(-value) : value;
}

template <class F>
static F parse_float(std::string_view text) {
  // Validate with the exact parser (rejects nan, inf, garbage), then let Boost round.
  (void)parse_decimal_rational(text);
  std::string s(text);
  return F(s);
}

template <>
double from_decimal<double>(std::string_view text) {
  (void)parse_decimal_rational(text);
  std::string s(text);
  char* endp = nullptr;
  double v = std::strtod(s.c_str(), &endp);
  if (!std::isfinite(v)) throw std::invalid_argument("decimal number out of double range: '" + s + "'");
  return v;
}
template <>
Real50 from_decimal<Real50>(std::string_view text) {
  return parse_float<Real50>(text);
}
template <>
Real70 from_decimal<Real70>(std::string_view text) {
  return parse_float<Real70>(text);
}
template <>
Rational from_decimal<Rational>(std::string_view text) {
  return parse_decimal_rational(text);
}

}  // namespace gm
