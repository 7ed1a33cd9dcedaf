// Small text helpers of the integrator properties' messages: a printf-style number format and the
// scalar's tag, " (double)" / " (mp50)", that every finding ends with.
#pragma once

#include "core/scalar.hpp"

#include <cstdio>
#include <string>

namespace gm {

inline std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[300];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

template <class T>
std::string scalar_tag() {
  return std::string(" (") + ScalarInfo<T>::name + ")";
}

}  // namespace gm
