// Full-precision printing of the suite's scalars, vectors and matrices, for RapidCheck's
// counterexamples (found by argument-dependent lookup) and for failure messages.
#pragma once

#include "core/linalg.hpp"

#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

namespace gm {

// Values are shown in the language of the implementation under test: C++ (and the
// suite's own tests) as [a, b, c] and [a, b; c, d]; Python as lists, [a, b, c] and [[a, b], [c, d]],
// with mpf('...') in 50 digits and Fraction(p, q) in rationals; Octave as MATLAB writes them,
// column vectors [a; b; c] and matrices [a, b; c, d]. The harness sets it before a check's
// processes are forked.
enum class ShowStyle { Cpp, Python, Octave };
inline ShowStyle& show_style() {
  static ShowStyle style = ShowStyle::Cpp;
  return style;
}

template <class T>
std::string show_scalar(const T& x) {
  std::string text = to_string_full(x);
  if constexpr (!std::is_arithmetic_v<T>) {
    if (show_style() != ShowStyle::Python) return text;
    if constexpr (is_exact_v<T>) {
      const auto slash = text.find('/');
      return slash == std::string::npos ? "Fraction(" + text + ")"
                                        : "Fraction(" + text.substr(0, slash) + ", " + text.substr(slash + 1) + ")";
    } else {
      return "mpf('" + text + "')";
    }
  }
  return text;
}

template <class Derived>
std::string show_matrix(const Eigen::MatrixBase<Derived>& m) {
  std::ostringstream os;
  const bool column = m.cols() == 1;
  const ShowStyle style = show_style();
  auto entry = [&](Eigen::Index i, Eigen::Index j) { return show_scalar(typename Derived::Scalar(m(i, j))); };
  if (style == ShowStyle::Python) {  // a list, or a list of rows
    os << "[";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      if (i) os << ", ";
      if (column) {
        os << entry(i, 0);
        continue;
      }
      os << "[";
      for (Eigen::Index j = 0; j < m.cols(); ++j) os << (j ? ", " : "") << entry(i, j);
      os << "]";
    }
    os << "]";
    return os.str();
  }
  const char* row_separator = column && style == ShowStyle::Cpp ? ", " : "; ";  // Octave: a column is rows
  os << "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (i) os << row_separator;
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j) os << ", ";
      os << entry(i, j);
    }
  }
  os << "]";
  return os.str();
}

template <class T>
std::string show_value(const T& x) {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<T>, T>)
    return show_matrix(x);
  else
    return show_scalar(x);
}

}  // namespace gm

namespace Eigen {
template <class S, int R, int C, int O, int MR, int MC>
void showValue(const Matrix<S, R, C, O, MR, MC>& m, std::ostream& os) {
  os << gm::show_matrix(m);
}
}  // namespace Eigen

namespace boost::multiprecision {
template <class Backend, expression_template_option ET>
void showValue(const number<Backend, ET>& x, std::ostream& os) {
  os << gm::show_scalar(x);
}
}  // namespace boost::multiprecision
