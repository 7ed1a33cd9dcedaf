// The golden-fixture file format (golden/README.md): one self-describing text file per
// trajectory. This header is the reader and writer only; it knows the format, not the
// dynamics (golden/systems.hpp validates what a file says about its system).
//
// Shape of a file:
//   # free comment lines
//   #: format geomech-golden 1          <- header fields, "#: key value...", fixed order
//   #: name ...
//   ...
//   #: columns t Pi1 Pi2 Pi3
//   0 1.000...e-01 ...                   <- one data row per sample time: t, then the state
//   ...
//   #: end
// Data rows are plain whitespace-separated decimals, so numpy.loadtxt, Julia's readdlm and
// MATLAB's readmatrix read them directly (every other line starts with '#').
//
// Numbers. Parameters and initial data are exact: an integer, a finite decimal ("0.125",
// "-1.5e-3") or a fraction of integers ("2/3"); the reader keeps them as exact Rationals.
// Sample times are finite decimals (exact as written). State values are decimals with `digits`
// significant digits, kept as the strings of the file so that one table feeds every precision
// (values<T>() converts: correctly rounded for double/Real50/Real70, exact for Rational).
//
// Errors. Anything malformed raises InputError naming the file and line (or the command-line
// argument) and saying what is wrong; nothing else escapes the reader.
#pragma once

#include "core/scalar.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gm::golden {

inline constexpr const char* kFormatName = "geomech-golden";
// Version 2 adds the certificate: a "#: certificate ..." line after the checks and,
// after the data rows, one "#: certified_radius T R" line per row. Version 1 files (no
// certificate) are still read.
inline constexpr int kFormatVersion = 2;

// Limits on what a fixture or a request may contain (golden/README.md, "Limits").
inline constexpr int kMinDigits = 17;
inline constexpr int kMaxDigits = 55;
inline constexpr std::size_t kMaxSamples = 10000;
inline constexpr std::size_t kMaxColumns = 1 + 2 * 9 * 9;  // t and Manakov SO(9) with attitude
inline constexpr std::size_t kMaxLineLength = 1 << 16;

// A bad fixture file or a bad argument. `where` is a file name or an argument as typed;
// `line` is 1-based, 0 when the problem is not on one line (or `where` is an argument).
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, int line, const std::string& message);
  const std::string& where() const { return where_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string where_;
  int line_;
  std::string message_;
};

// A named block of exact numbers: a parameter ("I" = 2 1 2/3) or a part of the initial state
// ("Pi", "O"). `where`/`line` say where it was read, for messages.
struct NamedValues {
  std::string name;
  std::vector<Rational> values;
  std::string where;
  int line = 0;
};

// A generator or check line: "#: generator taylor order=73 tolerance=1e-62 steps=39".
struct MethodRecord {
  std::string method;
  std::vector<std::pair<std::string, std::string>> settings;  // in file order
  const std::string* setting(std::string_view key) const;
};

struct Fixture {
  std::string name;       // identifier, also the file's base name
  std::string system;     // a name known to golden/systems.hpp
  std::string title;      // one line of free text
  std::string equations;  // one line of free text: the equations and their numbers in the notes
  std::vector<NamedValues> parameters;
  std::vector<NamedValues> initial;
  std::vector<std::string> columns;  // the state columns (without "t")
  int digits = 0;                    // significant digits of every state value
  int working_precision = 0;         // decimal digits of the generating arithmetic
  MethodRecord generator;
  std::vector<MethodRecord> checks;           // independent reproductions, each with max_abs_diff
  bool certified = false;                     // version 2 with a certificate
  MethodRecord certificate;                   // how the enclosures were computed (golden/certify.hpp)
  std::vector<std::string> certified_radius;  // per row: a proved bound on |value - exact| (decimal)
  int format_version = kFormatVersion;
  std::string accuracy;                        // bound on |value - exact| for every value (decimal)
  std::string condition;                       // max over samples of |dx(t)/dx(0)|_inf (decimal)
  std::vector<std::string> times;              // sample times, canonical decimals
  std::vector<std::vector<std::string>> rows;  // rows[i][j]: column j at times[i], as in the file

  // Where the fixture was read from (empty when built in memory) and the line of each row.
  std::string source;
  int system_line = 0, columns_line = 0;
  std::vector<int> row_lines;

  const NamedValues* parameter(std::string_view n) const;
  const NamedValues* initial_block(std::string_view n) const;

  // The sample times and state values in scalar T (double, Real50, Real70 or Rational).
  template <class T>
  std::vector<T> times_as() const;
  template <class T>
  std::vector<std::vector<T>> values_as() const;
};

// Reads a fixture from text; `source` names it in messages. Checks the format and the numbers
// (not the dynamics: see golden/systems.hpp, validate_fixture).
Fixture parse_fixture(std::string_view text, const std::string& source);
// Reads a fixture file (InputError if it cannot be read or is malformed).
Fixture load_fixture(const std::string& path);
// The file text of a fixture: fixed formatting, so equal fixtures give equal bytes.
std::string write_fixture(const Fixture& f);

// --- exact and decimal numbers --------------------------------------------------------------

// An exact number: integer, finite decimal or "p/q". Throws std::invalid_argument with a
// message saying what is wrong (callers wrap it into an InputError with the place).
Rational parse_exact(std::string_view text);
// The shortest exact text of a Rational: "2", "-0.125", "2/3".
std::string format_exact(const Rational& x);
// A finite decimal (no fractions): validates and returns its exact value.
Rational parse_decimal(std::string_view text);
// True when x is a finite decimal (its denominator has no prime factors but 2 and 5).
bool is_finite_decimal(const Rational& x);
// x rounded (half to even) to `digits` significant digits, in scientific notation with a fixed
// layout: "-1.2345e-01"; zero is "0.0000e+00". Exact and platform independent.
std::string format_significant(const Rational& x, int digits);
// Half a unit in the last place of `digits` significant digits at the magnitude of x.
Rational half_ulp_decimal(const Rational& x, int digits);
// 10^e as a Rational (e may be negative).
Rational pow10(int e);
// The smallest number with one significant digit that is >= x (x >= 0), as text:
// 3.2e-51 -> "4e-51", 0 -> "0".
std::string round_up_1digit(const Rational& x);

}  // namespace gm::golden
