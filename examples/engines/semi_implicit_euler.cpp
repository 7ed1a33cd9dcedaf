// Semi-implicit Euler as physics engines write it, in three of the state forms engines keep
// (semi_implicit_euler.hpp): a quaternion (w, x, y, z) with the world's omega, a quaternion
// (x, y, z, w) with the body's Omega, a matrix with the spatial momentum pi. Each claims order 1
// and its attitude kept on SO(3) (unit_quaternion, orthogonality), and keeps both.
//   ./geomech check examples/engines/semi_implicit_euler.cpp
#include "semi_implicit_euler.hpp"

GEOMECH_STUDENT(engines::NoSlots, engines::WorldOmega, engines::BodyOmegaXYZW, engines::MatrixSpatialMomentum);
