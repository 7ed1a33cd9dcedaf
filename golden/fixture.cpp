#include "golden/fixture.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gm::golden {

namespace {

std::string place_text(const std::string& where, int line) {
  return line > 0 ? where + ":" + std::to_string(line) : where;
}

bool is_space(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_space(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

// Shows a piece of input in a message: quoted, control bytes escaped, long text shortened.
std::string quote(std::string_view s) {
  std::string out = "'";
  const std::size_t n = std::min<std::size_t>(s.size(), 60);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (s.size() > n) out += "...";
  return out + "'";
}

bool is_identifier(std::string_view s, std::size_t max_len) {
  if (s.empty() || s.size() > max_len || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

bool parse_int(std::string_view s, long long lo, long long hi, long long& out) {
  if (s.empty() || s.size() > 18) return false;
  long long v = 0;
  for (char c : s) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    v = v * 10 + (c - '0');
  }
  if (v < lo || v > hi) return false;
  out = v;
  return true;
}

// The layout written by format_significant with `digits` digits: -?d.d{digits-1}e[+-]d{2,}
// with a nonzero leading digit; zero is written 0.0...0e+00 (no sign).
bool has_significant_layout(std::string_view s, int digits) {
  if (s.size() > 0 && s[s[0] == '-' ? 1 : 0] == '0') {
    const std::string zero = "0." + std::string(static_cast<std::size_t>(digits - 1), '0') + "e+00";
    return s == (digits > 1 ? zero : std::string("0e+00"));
  }
  std::size_t i = 0;
  if (i < s.size() && s[i] == '-') ++i;
  if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  ++i;
  if (digits > 1) {
    if (i >= s.size() || s[i] != '.') return false;
    ++i;
    for (int k = 1; k < digits; ++k, ++i)
      if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  }
  if (i >= s.size() || s[i] != 'e') return false;
  ++i;
  if (i >= s.size() || (s[i] != '+' && s[i] != '-')) return false;
  ++i;
  const std::size_t exp_digits = s.size() - i;
  if (exp_digits < 2) return false;
  for (; i < s.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

const Rational& max_state_magnitude() {
  static const Rational m = pow10(20);
  return m;
}
const Rational& max_time() {
  static const Rational m = pow10(4);
  return m;
}

bmp::cpp_int pow10_int(unsigned e) { return bmp::pow(bmp::cpp_int(10), e); }

Rational abs_q(const Rational& x) { return x < 0 ? Rational(-x) : x; }

}  // namespace

InputError::InputError(std::string where, int line, const std::string& message)
    : std::runtime_error(place_text(where, line) + ": " + message),
      where_(std::move(where)),
      line_(line),
      message_(message) {}

const std::string* MethodRecord::setting(std::string_view key) const {
  for (const auto& [k, v] : settings)
    if (k == key) return &v;
  return nullptr;
}

const NamedValues* Fixture::parameter(std::string_view n) const {
  for (const auto& p : parameters)
    if (p.name == n) return &p;
  return nullptr;
}
const NamedValues* Fixture::initial_block(std::string_view n) const {
  for (const auto& p : initial)
    if (p.name == n) return &p;
  return nullptr;
}

template <class T>
std::vector<T> Fixture::times_as() const {
  std::vector<T> out;
  out.reserve(times.size());
  for (const auto& t : times) out.push_back(from_decimal<T>(t));
  return out;
}

template <class T>
std::vector<std::vector<T>> Fixture::values_as() const {
  std::vector<std::vector<T>> out;
  out.reserve(rows.size());
  for (const auto& r : rows) {
    std::vector<T> v;
    v.reserve(r.size());
    for (const auto& s : r) v.push_back(from_decimal<T>(s));
    out.push_back(std::move(v));
  }
  return out;
}

template std::vector<double> Fixture::times_as<double>() const;
template std::vector<Real50> Fixture::times_as<Real50>() const;
template std::vector<Real70> Fixture::times_as<Real70>() const;
template std::vector<Rational> Fixture::times_as<Rational>() const;
template std::vector<std::vector<double>> Fixture::values_as<double>() const;
template std::vector<std::vector<Real50>> Fixture::values_as<Real50>() const;
template std::vector<std::vector<Real70>> Fixture::values_as<Real70>() const;
template std::vector<std::vector<Rational>> Fixture::values_as<Rational>() const;

// ---------------------------------------------------------------------------------------------
// Numbers

Rational pow10(int e) {
  if (e >= 0) return Rational(pow10_int(static_cast<unsigned>(e)));
  return Rational(bmp::cpp_int(1), pow10_int(static_cast<unsigned>(-e)));
}

Rational parse_decimal(std::string_view text) {
  // parse_decimal_rational accepts surrounding spaces; a token never has them, and a bare sign,
  // "1e", ".e1" etc. are rejected there.
  if (text.empty()) throw std::invalid_argument("empty number");
  for (char c : text)
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
      throw std::invalid_argument("not a finite decimal number: " + quote(text));
  try {
    return parse_decimal_rational(text);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("not a finite decimal number: " + quote(text));
  }
}

Rational parse_exact(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_decimal(text);
  const std::string_view num = text.substr(0, slash), den = text.substr(slash + 1);
  auto integer = [&](std::string_view s, bool allow_sign) {
    std::size_t i = 0;
    if (allow_sign && !s.empty() && (s[0] == '-' || s[0] == '+')) i = 1;
    if (i == s.size() || s.size() > 200) return false;
    for (; i < s.size(); ++i)
      if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    return true;
  };
  if (!integer(num, true) || !integer(den, false))
    throw std::invalid_argument("not an exact number (integer, decimal or p/q with integers p, q > 0): " + quote(text));
  const Rational p = parse_decimal_rational(num), q = parse_decimal_rational(den);
  if (q == 0) throw std::invalid_argument("zero denominator in " + quote(text));
  return p / q;
}

bool is_finite_decimal(const Rational& x) {
  bmp::cpp_int d = bmp::denominator(x);
  while (d % 2 == 0) d /= 2;
  while (d % 5 == 0) d /= 5;
  return d == 1;
}

std::string format_exact(const Rational& x) {
  const bmp::cpp_int num = bmp::numerator(x), den = bmp::denominator(x);
  if (den == 1) return num.str();
  if (!is_finite_decimal(x)) return num.str() + "/" + den.str();
  // den = 2^a 5^b: x = num * (10^k / den) / 10^k with k = max(a, b).
  bmp::cpp_int d = den;
  unsigned a = 0, b = 0;
  while (d % 2 == 0) d /= 2, ++a;
  while (d % 5 == 0) d /= 5, ++b;
  const unsigned k = std::max(a, b);
  bmp::cpp_int scaled = num * (pow10_int(k) / den);
  const bool negative = scaled < 0;
  if (negative) scaled = -scaled;
  std::string digits = scaled.str();
  if (digits.size() <= k) digits = std::string(k + 1 - digits.size(), '0') + digits;
  std::string out = digits.substr(0, digits.size() - k) + "." + digits.substr(digits.size() - k);
  return negative ? "-" + out : out;
}

namespace {

// floor(log10 |x|) for x != 0, exactly.
int decimal_exponent(const Rational& a) {
  // Estimate from the sizes of numerator and denominator, then correct by exact comparison.
  const std::string n = bmp::numerator(a).str(), d = bmp::denominator(a).str();
  int e = static_cast<int>(n.size()) - static_cast<int>(d.size());
  while (a >= pow10(e + 1)) ++e;
  while (a < pow10(e)) --e;
  return e;
}

// Round the non-negative rational q to the nearest integer, ties to even.
bmp::cpp_int round_half_even(const Rational& q) {
  const bmp::cpp_int n = bmp::numerator(q), d = bmp::denominator(q);
  bmp::cpp_int whole = n / d;
  const bmp::cpp_int twice_rem = 2 * (n % d);
  if (twice_rem > d || (twice_rem == d && whole % 2 == 1)) ++whole;
  return whole;
}

}  // namespace

std::string format_significant(const Rational& x, int digits) {
  if (digits < 1) throw std::invalid_argument("format_significant: digits must be positive");
  std::string mantissa;
  int e = 0;
  bool negative = false;
  if (x == 0) {
    mantissa = std::string(static_cast<std::size_t>(digits), '0');
  } else {
    negative = x < 0;
    const Rational a = negative ? Rational(-x) : x;
    e = decimal_exponent(a);
    bmp::cpp_int m = round_half_even(a * pow10(digits - 1 - e));
    if (m == pow10_int(static_cast<unsigned>(digits))) {
      m /= 10;
      ++e;
    }
    mantissa = m.str();
  }
  std::string out = negative ? "-" : "";
  out += mantissa[0];
  if (digits > 1) out += "." + mantissa.substr(1);
  char buf[16];
  std::snprintf(buf, sizeof buf, "e%c%02d", e < 0 ? '-' : '+', e < 0 ? -e : e);
  return out + buf;
}

Rational half_ulp_decimal(const Rational& x, int digits) {
  if (x == 0) return Rational(0);
  const Rational a = x < 0 ? Rational(-x) : x;
  return pow10(decimal_exponent(a) - digits + 1) / 2;
}

std::string round_up_1digit(const Rational& x) {
  if (x <= 0) return "0";
  const int e = decimal_exponent(x);
  const Rational unit = pow10(e);
  bmp::cpp_int m = bmp::numerator(x / unit) / bmp::denominator(x / unit);  // floor, in 1..9
  if (Rational(m) * unit < x) ++m;
  int exponent = e;
  if (m == 10) {
    m = 1;
    ++exponent;
  }
  return m.str() + "e" + (exponent < 0 ? "-" : "+") + (std::abs(exponent) < 10 ? "0" : "") +
         std::to_string(std::abs(exponent));
}

// ---------------------------------------------------------------------------------------------
// Reading

namespace {

struct Line {
  int number;
  std::string_view text;
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& source) : source_(source) { split_lines(text); }

  Fixture read() {
    Fixture f;
    f.source = source_;
    if (std::none_of(lines_.begin(), lines_.end(), [](const Line& l) { return l.text[0] != '#' || is_field(l.text); }))
      throw error(0,
                  "empty file (nothing but comments or blank lines): not a " + std::string(kFormatName) + " fixture");

    // format
    {
      const Line& l = expect_field("format");
      const auto tok = split(rest_);
      if (tok.size() != 2 || tok[0] != kFormatName)
        throw error(l.number, "expected '#: format " + std::string(kFormatName) + " " + std::to_string(kFormatVersion) +
                                  "', found " + quote(l.text));
      long long v = 0;
      if (!parse_int(tok[1], 1, 1000000, v) || v < 1 || v > kFormatVersion)
        throw error(l.number, "unsupported format version " + quote(tok[1]) + " (this reader reads versions 1 to " +
                                  std::to_string(kFormatVersion) + ")");
      f.format_version = static_cast<int>(v);
    }
    f.name = identifier_field("name", 64);
    f.system = identifier_field("system", 64);
    f.system_line = lines_[pos_ - 1].number;
    f.title = text_field("title");
    f.equations = text_field("equations");
    read_blocks("parameter", f.parameters);
    read_blocks("initial", f.initial);
    f.working_precision = static_cast<int>(int_field("working_precision", 17, 10000));
    f.generator = method_field("generator");
    while (peek_field() == "check") {
      f.checks.push_back(method_field("check"));
      const Line& l = lines_[pos_ - 1];
      const std::string* d = f.checks.back().setting("max_abs_diff");
      if (!d) throw error(l.number, "a check must give its max_abs_diff=<decimal> against the generator");
      nonnegative_decimal(*d, l.number, "max_abs_diff");
    }
    if (f.format_version >= 2 && peek_field() == "certificate") {
      f.certificate = method_field("certificate");
      f.certified = true;
    }
    {
      const Line& l = expect_field("accuracy");
      f.accuracy = single_token(l);
      nonnegative_decimal(f.accuracy, l.number, "accuracy");
      for (const auto& c : f.checks)
        if (parse_decimal(*c.setting("max_abs_diff")) > parse_decimal(f.accuracy))
          throw error(l.number, "accuracy " + f.accuracy + " is smaller than the disagreement max_abs_diff=" +
                                    *c.setting("max_abs_diff") + " of check '" + c.method + "'");
    }
    {
      const Line& l = expect_field("condition");
      f.condition = single_token(l);
      nonnegative_decimal(f.condition, l.number, "condition");
    }
    f.digits = static_cast<int>(int_field("digits", kMinDigits, kMaxDigits));
    if (f.working_precision < f.digits)
      throw error(0, "working_precision " + std::to_string(f.working_precision) + " is below digits " +
                         std::to_string(f.digits));
    const std::size_t samples = static_cast<std::size_t>(int_field("samples", 1, static_cast<long long>(kMaxSamples)));
    {
      const Line& l = expect_field("columns");
      f.columns_line = l.number;
      const auto tok = split(rest_);
      if (tok.empty() || tok[0] != "t") throw error(l.number, "the first column must be 't'");
      if (tok.size() < 2) throw error(l.number, "no state columns after 't'");
      if (tok.size() > kMaxColumns)
        throw error(l.number, std::to_string(tok.size()) + " columns; at most " + std::to_string(kMaxColumns));
      for (std::size_t i = 1; i < tok.size(); ++i) {
        if (!is_identifier(tok[i], 16)) throw error(l.number, "bad column name " + quote(tok[i]));
        for (std::size_t j = 1; j < i; ++j)
          if (tok[j] == tok[i]) throw error(l.number, "column " + quote(tok[i]) + " appears twice");
        f.columns.emplace_back(tok[i]);
      }
    }
    // data rows
    Rational previous_t;
    while (true) {
      skip_comments();
      if (pos_ >= lines_.size())
        throw error(lines_.back().number, "truncated: the file ends after " + std::to_string(f.rows.size()) + " of " +
                                              std::to_string(samples) + " data rows, without its '#: end' line");
      const Line& l = lines_[pos_];
      if (is_field(l.text) && f.certified && field_key(l.text) == "certified_radius") {
        // "#: certified_radius T R" after the data rows, one per row in order (version 2).
        const auto tok = split(l.text.substr(2));
        if (tok.size() != 3) throw error(l.number, "'#: certified_radius' takes a time and a radius");
        const std::size_t i = f.certified_radius.size();
        if (i >= f.rows.size() || f.rows.size() != samples)
          throw error(l.number, "a certified_radius line before the data rows end, or more of them than rows");
        if (tok[1] != f.times[i])
          throw error(l.number, "certified_radius for t = " + quote(tok[1]) + ", expected the row t = " + f.times[i]);
        nonnegative_decimal(std::string(tok[2]), l.number, "certified_radius");
        f.certified_radius.emplace_back(tok[2]);
        ++pos_;
        continue;
      }
      if (is_field(l.text)) {
        const std::string key = field_key(l.text);
        if (key != "end") throw error(l.number, "unexpected header field '" + key + "' among the data rows");
        if (f.certified && f.certified_radius.size() != f.rows.size())
          throw error(l.number, "the certificate gives a certified_radius for " +
                                    std::to_string(f.certified_radius.size()) + " of the " +
                                    std::to_string(f.rows.size()) + " rows");
        if (f.rows.size() != samples)
          throw error(l.number, "truncated: " + std::to_string(f.rows.size()) + " data rows, the header says samples " +
                                    std::to_string(samples));
        if (split(l.text.substr(2)).size() != 1) throw error(l.number, "'#: end' takes no value");
        ++pos_;
        break;
      }
      if (f.rows.size() == samples)
        throw error(l.number, "more data rows than the " + std::to_string(samples) + " the header announces");
      if (!f.certified_radius.empty()) throw error(l.number, "a data row after the certified_radius lines");
      const auto tok = split(l.text);
      if (tok.size() != f.columns.size() + 1)
        throw error(l.number, "wrong number of columns: " + std::to_string(tok.size()) + " values, expected " +
                                  std::to_string(f.columns.size() + 1) + " (t and " + std::to_string(f.columns.size()) +
                                  " state columns)");
      Rational t;
      try {
        t = parse_decimal(tok[0]);
      } catch (const std::invalid_argument& e) {
        throw error(l.number, "column t: " + std::string(e.what()));
      }
      if (t < 0 || t > max_time()) throw error(l.number, "time " + quote(tok[0]) + " outside [0, 1e4]");
      if (!f.rows.empty() && !(t > previous_t))
        throw error(l.number, "sample times must increase: " + quote(tok[0]) + " after " + f.times.back());
      if (format_exact(t) != tok[0])
        throw error(l.number, "time " + quote(tok[0]) + " is not in canonical form (write " + format_exact(t) + ")");
      previous_t = t;
      std::vector<std::string> row;
      row.reserve(f.columns.size());
      for (std::size_t j = 1; j < tok.size(); ++j) {
        const std::string& col = f.columns[j - 1];
        Rational v;
        try {
          v = parse_decimal(tok[j]);
        } catch (const std::invalid_argument& e) {
          throw error(l.number, "column " + col + ": " + e.what());
        }
        const Rational a = abs_q(v);
        if (a > max_state_magnitude())
          throw error(l.number, "column " + col + ": absurd magnitude " + quote(tok[j]) + " (|value| > 1e20)");
        if (!has_significant_layout(tok[j], f.digits))
          throw error(l.number, "column " + col + ": " + quote(tok[j]) + " is not written with exactly " +
                                    std::to_string(f.digits) + " significant digits as d.ddd...e+XX");
        row.emplace_back(tok[j]);
      }
      f.times.emplace_back(tok[0]);
      f.rows.push_back(std::move(row));
      f.row_lines.push_back(l.number);
      ++pos_;
    }
    // After '#: end' only comments or blank lines.
    skip_comments();
    if (pos_ < lines_.size()) throw error(lines_[pos_].number, "text after the '#: end' line");
    return f;
  }

 private:
  void split_lines(std::string_view text) {
    int number = 0;
    std::size_t i = 0;
    while (i < text.size()) {
      std::size_t j = text.find('\n', i);
      if (j == std::string_view::npos) j = text.size();
      std::string_view line = text.substr(i, j - i);
      ++number;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.size() > kMaxLineLength)
        throw error(number, "line longer than " + std::to_string(kMaxLineLength) + " characters");
      for (char c : line) {
        const unsigned char u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u == 0x7f) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "control character (byte 0x%02x) in the text", u);
          throw error(number, buf);
        }
      }
      if (!trim(line).empty()) lines_.push_back(Line{number, line});
      i = j + 1;
    }
  }

  InputError error(int line, const std::string& message) const { return InputError(source_, line, message); }

  static bool is_field(std::string_view s) { return s.size() >= 2 && s[0] == '#' && s[1] == ':'; }
  static std::string field_key(std::string_view s) {
    const auto tok = split(s.substr(2));
    return tok.empty() ? std::string() : std::string(tok[0]);
  }

  void skip_comments() {
    while (pos_ < lines_.size() && lines_[pos_].text[0] == '#' && !is_field(lines_[pos_].text)) ++pos_;
  }

  std::string peek_field() {
    skip_comments();
    if (pos_ >= lines_.size() || !is_field(lines_[pos_].text)) return {};
    return field_key(lines_[pos_].text);
  }

  // Consumes the next header line, which must be "#: key ..."; rest_ is what follows the key.
  const Line& expect_field(const std::string& key) {
    skip_comments();
    if (pos_ >= lines_.size())
      throw error(lines_.back().number, "truncated: the file ends where '#: " + key + "' was expected");
    const Line& l = lines_[pos_];
    if (!is_field(l.text))
      throw error(l.number, "expected the header field '#: " + key + "', found data or text " + quote(l.text));
    const std::string found = field_key(l.text);
    if (found != key) {
      static const char* known[] = {"format",           "name",      "system",      "title",
                                    "equations",        "parameter", "initial",     "working_precision",
                                    "generator",        "check",     "certificate", "accuracy",
                                    "condition",        "digits",    "samples",     "columns",
                                    "certified_radius", "end"};
      const bool is_known = std::find(std::begin(known), std::end(known), found) != std::end(known);
      throw error(l.number, std::string(is_known ? "header field '" : "unknown header field '") + found +
                                "' where '#: " + key + "' was expected (fields come in the order of golden/README.md)");
    }
    std::string_view rest = l.text.substr(2);
    rest = trim(rest);
    rest_ = trim(rest.substr(key.size()));
    ++pos_;
    return l;
  }

  std::string single_token(const Line& l) {
    const auto tok = split(rest_);
    if (tok.size() != 1) throw error(l.number, "expected exactly one value after the field name");
    return std::string(tok[0]);
  }

  std::string identifier_field(const std::string& key, std::size_t max_len) {
    const Line& l = expect_field(key);
    const std::string v = single_token(l);
    if (!is_identifier(v, max_len))
      throw error(l.number, key + " " + quote(v) + " is not an identifier (a letter, then letters, digits, _)");
    return v;
  }

  std::string text_field(const std::string& key) {
    const Line& l = expect_field(key);
    if (rest_.empty()) throw error(l.number, "'#: " + key + "' needs a text");
    return std::string(rest_);
  }

  long long int_field(const std::string& key, long long lo, long long hi) {
    const Line& l = expect_field(key);
    const std::string v = single_token(l);
    long long out = 0;
    if (!parse_int(v, lo, hi, out))
      throw error(l.number, key + " " + quote(v) + " is not an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]");
    return out;
  }

  void nonnegative_decimal(const std::string& v, int line, const std::string& what) {
    Rational x;
    try {
      x = parse_decimal(v);
    } catch (const std::invalid_argument& e) {
      throw error(line, what + ": " + e.what());
    }
    if (x < 0) throw error(line, what + " " + quote(v) + " is negative");
  }

  void read_blocks(const std::string& key, std::vector<NamedValues>& out) {
    do {
      const Line& l = expect_field(key);
      const auto tok = split(rest_);
      if (tok.size() < 2) throw error(l.number, "'#: " + key + "' needs a name and at least one value");
      if (!is_identifier(tok[0], 16)) throw error(l.number, key + " name " + quote(tok[0]) + " is not an identifier");
      NamedValues nv;
      nv.name = std::string(tok[0]);
      nv.where = source_;
      nv.line = l.number;
      for (const auto& o : out)
        if (o.name == nv.name) throw error(l.number, key + " '" + nv.name + "' appears twice");
      if (tok.size() - 1 > 81) throw error(l.number, key + " '" + nv.name + "' has more than 81 values");
      for (std::size_t i = 1; i < tok.size(); ++i) {
        const std::string what = key + " " + nv.name + ", value " + std::to_string(i) + ": ";
        try {
          nv.values.push_back(parse_exact(tok[i]));
        } catch (const std::invalid_argument& e) {
          throw error(l.number, what + e.what());
        }
        const Rational a = abs_q(nv.values.back());
        if (a > max_state_magnitude() || (a != 0 && a < 1 / max_state_magnitude()))
          throw error(l.number, what + "absurd magnitude " + quote(tok[i]) + " (outside 1e-20 <= |value| <= 1e20)");
        if (format_exact(nv.values.back()) != tok[i])
          throw error(l.number, what + quote(tok[i]) + " is not in canonical form (write " +
                                    format_exact(nv.values.back()) + ")");
      }
      out.push_back(std::move(nv));
    } while (peek_field() == key);
  }

  MethodRecord method_field(const std::string& key) {
    const Line& l = expect_field(key);
    const auto tok = split(rest_);
    if (tok.empty()) throw error(l.number, "'#: " + key + "' needs a method name");
    MethodRecord m;
    for (char c : tok[0])
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
        throw error(l.number, "method name " + quote(tok[0]) + " has a character other than letters, digits, _ and -");
    m.method = std::string(tok[0]);
    for (std::size_t i = 1; i < tok.size(); ++i) {
      const auto eq = tok[i].find('=');
      if (eq == std::string_view::npos || eq == 0 || eq + 1 == tok[i].size())
        throw error(l.number, "setting " + quote(tok[i]) + " is not key=value");
      m.settings.emplace_back(std::string(tok[i].substr(0, eq)), std::string(tok[i].substr(eq + 1)));
    }
    return m;
  }

  std::string source_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  std::string_view rest_;
};

}  // namespace

Fixture parse_fixture(std::string_view text, const std::string& source) { return Reader(text, source).read(); }

Fixture load_fixture(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a directory, not a fixture file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "read error");
  const std::string text = ss.str();
  if (text.size() > (std::size_t(64) << 20)) throw InputError(path, 0, "file larger than 64 MiB");
  return parse_fixture(text, path);
}

// ---------------------------------------------------------------------------------------------
// Writing

std::string write_fixture(const Fixture& f) {
  std::ostringstream o;
  o << "# A golden trajectory of geomech-spec. Format: golden/README.md. Do not edit: regenerate\n"
    << "# with `./geomech golden regenerate` (fixtures) or `./geomech golden trajectory` (your own).\n";
  o << "#: format " << kFormatName << " " << kFormatVersion << "\n";
  o << "#: name " << f.name << "\n";
  o << "#: system " << f.system << "\n";
  o << "#: title " << f.title << "\n";
  o << "#: equations " << f.equations << "\n";
  auto block = [&](const char* key, const NamedValues& nv) {
    o << "#: " << key << " " << nv.name;
    for (const auto& v : nv.values) o << " " << format_exact(v);
    o << "\n";
  };
  for (const auto& p : f.parameters) block("parameter", p);
  for (const auto& p : f.initial) block("initial", p);
  o << "#: working_precision " << f.working_precision << "\n";
  auto method = [&](const char* key, const MethodRecord& m) {
    o << "#: " << key << " " << m.method;
    for (const auto& [k, v] : m.settings) o << " " << k << "=" << v;
    o << "\n";
  };
  method("generator", f.generator);
  for (const auto& c : f.checks) method("check", c);
  if (f.certified) method("certificate", f.certificate);
  o << "#: accuracy " << f.accuracy << "\n";
  o << "#: condition " << f.condition << "\n";
  o << "#: digits " << f.digits << "\n";
  o << "#: samples " << f.rows.size() << "\n";
  o << "#: columns t";
  for (const auto& c : f.columns) o << " " << c;
  o << "\n";
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    o << f.times[i];
    for (const auto& v : f.rows[i]) o << " " << v;
    o << "\n";
  }
  if (f.certified)
    for (std::size_t i = 0; i < f.rows.size(); ++i)
      o << "#: certified_radius " << f.times[i] << " " << f.certified_radius[i] << "\n";
  o << "#: end\n";
  return o.str();
}

}  // namespace gm::golden
