#include "properties/support/generators.hpp"

#include <Eigen/LU>

namespace gm::gen {

MatX<Rational> cayley_rational(const MatX<Rational>& S) {
  const auto n = S.rows();
  const MatX<Rational> Id = MatX<Rational>::Identity(n, n);
  // Id - S is invertible for skew S (its eigenvalues are 1 - i s with s real), so the LU
  // solve is exact in rational arithmetic.
  return Eigen::FullPivLU<MatX<Rational>>(Id - S).solve(Id + S);
}

GM_GENERATORS_FOR(, double)
GM_GENERATORS_FOR(, Real50)
GM_GENERATORS_FOR(, Rational)

}  // namespace gm::gen
