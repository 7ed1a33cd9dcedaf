#include "harness/remote/protocol_codec.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace gm::protocol {

// The shortest decimal that reads back as x (std::to_chars): exact like "%.17g", shorter on the
// wire, and several times cheaper to write than printf's conversion.
std::string encode_scalar(double x) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string encode_scalar(const Real50& x) { return x.str(60, std::ios_base::scientific); }

std::string encode_scalar(const Rational& x) {
  std::ostringstream os;
  os << numerator(x);
  if (denominator(x) != 1) os << "/" << denominator(x);
  return os.str();
}

const char* lie_algebra_word(LieAlgebraId g) {
  switch (g) {
    case LieAlgebraId::so3:
      return "so3";
    case LieAlgebraId::so4:
      return "so4";
    case LieAlgebraId::sl2:
      return "sl2";
  }
  return "?";
}

namespace {

std::string show(const json& j) {
  std::string s = j.dump();
  return s.size() > 80 ? s.substr(0, 77) + "..." : s;
}

// The text of a scalar: a string, or the JSON number as written.
std::string scalar_text(const json& j, const std::string& what, bool allow_float) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_integer()) return j.dump();
  if (j.is_number_float()) {
    if (!allow_float)
      throw ProtocolValueError(what + ": a JSON float (" + show(j) +
                               ") cannot carry this scalar exactly; send a decimal string");
    return j.dump();
  }
  throw ProtocolValueError(what + ": expected a number, got " + show(j));
}

Rational parse_rational(const std::string& s, const std::string& what) {
  try {
    const auto slash = s.find('/');
    if (slash == std::string::npos) return parse_decimal_rational(s);
    const Rational p = parse_decimal_rational(s.substr(0, slash));
    const Rational q = parse_decimal_rational(s.substr(slash + 1));
    if (q == 0) throw std::invalid_argument("zero denominator in '" + s + "'");
    return p / q;
  } catch (const std::invalid_argument& e) {
    throw ProtocolValueError(what + ": " + e.what());
  }
}

}  // namespace

bool decode_plain_double(const json& j, double& out) {
  if (j.is_number()) {
    out = j.get<double>();
    return true;
  }
  if (!j.is_string()) return false;
  const std::string& s = j.get_ref<const std::string&>();
  const char* end = s.data() + s.size();
  const auto r = std::from_chars(s.data(), end, out);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(out);
}

// A NaN or an infinity spelt as the languages spell them ("nan", "-inf", Octave's "NaN" and "Inf",
// mpmath's "+inf", C's "infinity"): true, with its value, for those words only.
namespace {
bool non_finite_word(const std::string& s, double& out) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || std::isfinite(x)) return false;
  // strtod also reads an overflowing decimal ("1e999") as an infinity: a number, not a word.
  if (s.find_first_of("0123456789") != std::string::npos) return false;
  out = x;
  return true;
}
}  // namespace

template <>
double decode_scalar<double>(const json& j, const std::string& what, Values values) {
  double x;
  if (decode_plain_double(j, x)) return x;
  // The rest: a fraction "p/q", text strtod reads but from_chars does not ("+1", " 1"), or an error.
  const std::string s = scalar_text(j, what, true);
  if (s.find('/') != std::string::npos) return to_double(parse_rational(s, what));
  char* end = nullptr;
  x = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0') throw ProtocolValueError(what + ": not a number: '" + s + "'");
  if (!std::isfinite(x) && !(values == Values::any && non_finite_word(s, x)))
    throw ProtocolValueError(what + ": not finite: '" + s + "'");
  return x;
}

template <>
Real50 decode_scalar<Real50>(const json& j, const std::string& what, Values values) {
  const std::string s = scalar_text(j, what, false);
  if (s.find('/') != std::string::npos) return convert<Real50>(parse_rational(s, what));
  double special;
  if (values == Values::any && non_finite_word(s, special))
    return std::isnan(special)
               ? std::numeric_limits<Real50>::quiet_NaN()
               : (special > 0 ? std::numeric_limits<Real50>::infinity() : -std::numeric_limits<Real50>::infinity());
  try {
    return from_decimal<Real50>(s);
  } catch (const std::invalid_argument& e) {
    throw ProtocolValueError(what + ": " + e.what());
  }
}

template <>
Rational decode_scalar<Rational>(const json& j, const std::string& what, Values) {
  return parse_rational(scalar_text(j, what, false), what);
}

}  // namespace gm::protocol
