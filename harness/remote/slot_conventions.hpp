// The convention each slot is checked in, as `geomech slots` prints it: what the notes
// fix (the hat map (2.11), the pairing (2.15), the sign of (3.8), ...) and what they leave to the
// student (the order and signs of the coordinates of so(n), the basis of sl(2, R)), which the
// suite then learns from the student's own hat (properties/support/coordinates.hpp). Also the
// integrators' state, in words.
#pragma once

#include <string>
#include <string_view>

namespace gm::harness {

// "fixed by (2.11): ..." or "free: ..." for a slot that has a convention worth stating; "" for the
// others (their signature and formula say everything).
std::string slot_convention(std::string_view slot);

// The integrators' interface in words, as every language shares it: the state, what O maps,
// dO/dt = O Omega_hat; each language's row gives it as code (Language::integrator_interface).
std::string integrator_state();

}  // namespace gm::harness
