// The one compile of the Eigen kernels declared extern in core/eigen_kernels.hpp.
#include "core/eigen_kernels.hpp"

GM_EIGEN_KERNELS_QUIET_BEGIN
GM_EIGEN_KERNELS(, double);
GM_EIGEN_KERNELS(, gm::Real50);
GM_EIGEN_KERNELS(, gm::Rational);
GM_EIGEN_KERNELS_QUIET_END
