// One instantiation of the polynomial generators per scalar (see polynomial.hpp).
#include "properties/support/polynomial.hpp"

namespace gm::gen {

GM_POLYNOMIAL_GENERATORS_FOR(, double)
GM_POLYNOMIAL_GENERATORS_FOR(, Real50)
GM_POLYNOMIAL_GENERATORS_FOR(, Rational)

}  // namespace gm::gen
