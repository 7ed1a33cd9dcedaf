// Full-precision printing of the suite's scalars, vectors and matrices, for RapidCheck's
// counterexamples (found by argument-dependent lookup) and for failure messages.
#pragma once

#include "core/linalg.hpp"
#include "properties/support/value_style.hpp"

#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

namespace gm {

template <class T>
std::string show_scalar(const T& x) {
  std::string text = to_string_full(x);
  if constexpr (!std::is_arithmetic_v<T>) {
    const ValueStyle& style = value_style();
    if constexpr (is_exact_v<T>) {
      if (style.rational_before.empty() && style.rational_after.empty()) return text;
      const auto slash = text.find('/');
      return style.rational_before +
             (slash == std::string::npos ? text
                                         : text.substr(0, slash) + style.rational_between + text.substr(slash + 1)) +
             style.rational_after;
    } else {
      return style.mp50_before + text + style.mp50_after;
    }
  }
  return text;
}

template <class Derived>
std::string show_matrix(const Eigen::MatrixBase<Derived>& m) {
  std::ostringstream os;
  const bool column = m.cols() == 1;
  const ValueStyle& style = value_style();
  auto entry = [&](Eigen::Index i, Eigen::Index j) { return show_scalar(typename Derived::Scalar(m(i, j))); };
  if (style.nested_rows && !column) {  // a list of rows
    os << "[";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      os << (i ? ", [" : "[");
      for (Eigen::Index j = 0; j < m.cols(); ++j) os << (j ? ", " : "") << entry(i, j);
      os << "]";
    }
    os << "]";
    return os.str();
  }
  const char* row_separator = column ? style.column_separator.c_str() : "; ";
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
