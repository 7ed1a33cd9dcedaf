// Class-mode test: a student's own header beside the implementation.
#pragma once

#include <geomech/student.hpp>

namespace dave {
template <class T>
gm::Vec3<T> cross(const gm::Vec3<T>& a, const gm::Vec3<T>& b) {
  return gm::Vec3<T>(a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2), a(0) * b(1) - a(1) * b(0));
}
}  // namespace dave
