// 2^e exactly, in any scalar: repeated doubling or halving, exact in double, in 50 digits and in
// the rationals alike (std::ldexp has no overload for the multiprecision and rational types).
#pragma once

namespace gm {

template <class T>
T pow2(int e) {
  T x(1);
  for (int i = 0; i < e; ++i) x *= T(2);
  for (int i = 0; i > e; --i) x /= T(2);
  return x;
}

}  // namespace gm
