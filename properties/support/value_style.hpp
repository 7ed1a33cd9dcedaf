// The style values are written in (support/show.hpp writes them): data alone, so that a language's
// row can hold one without what the printing itself needs (Eigen, the multiprecision types).
#pragma once

#include <string>

namespace gm {

// How values, and the types of counterexamples, are written in the language of the implementation
// under test: as data, so that the properties never learn which language that is. The default is
// the suite's own (C++, and the suite's tests): [a, b, c] and [a, b; c, d], Vec3<double>. A
// language's row (harness/languages/language.hpp) holds its own, and the harness sets it before a
// check's processes are forked: RapidCheck prints a counterexample through the showValue overloads
// of support/show.hpp, found by argument-dependent lookup and given no context, hence one style per process.
struct ValueStyle {
  bool nested_rows = false;             // a matrix as a list of rows, [[a, b], [c, d]]; else [a, b; c, d]
  std::string column_separator = ", ";  // between the entries of a column vector: [a, b, c] or [a; b; c]
  std::string mp50_before, mp50_after;  // around a 50-digit number's digits: mpf('...')
  // Around a rational's p and q (or its integer): Fraction(p, q), Fraction(n); "p/q" by default.
  std::string rational_before, rational_between = "/", rational_after;
  // A counterexample's type in the language's words ("3-list of float"): {n} stands for the
  // dimensions ("3", "3x3"), {s} for the scalar's name below; the "any" forms for dynamic sizes.
  // Empty vector_type: types as C++ writes them (Vec3<double>).
  std::string vector_type, any_vector_type, matrix_type, any_matrix_type;
  std::string double_name = "double", mp50_name = "Real50", rational_name = "Rational";
};
inline ValueStyle& value_style() {
  static ValueStyle style;
  return style;
}

}  // namespace gm
