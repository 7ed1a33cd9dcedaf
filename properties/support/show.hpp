// Full-precision printing of the suite's scalars, vectors and matrices, for RapidCheck's
// counterexamples (found by argument-dependent lookup) and for failure messages.
#pragma once

#include "core/linalg.hpp"

#include <ostream>
#include <sstream>
#include <string>

namespace gm {

template <class T>
std::string show_scalar(const T& x) {
  return to_string_full(x);
}

template <class Derived>
std::string show_matrix(const Eigen::MatrixBase<Derived>& m) {
  std::ostringstream os;
  const bool column = m.cols() == 1;
  os << "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (i) os << (column ? ", " : "; ");
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j) os << ", ";
      os << to_string_full(typename Derived::Scalar(m(i, j)));
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
  os << gm::to_string_full(x);
}
}  // namespace boost::multiprecision
