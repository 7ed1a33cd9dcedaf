// One instantiation of the dynamic properties' draws and flows per floating scalar
// (see GM_DYNAMICS_FOR in dynamics.hpp).
#include "properties/support/dynamics.hpp"

namespace gm::dyn {

GM_DYNAMICS_FOR(, double)
GM_DYNAMICS_FOR(, Real50)

}  // namespace gm::dyn
