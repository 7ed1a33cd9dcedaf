// May use the low room.
#include "harness/low/a.hpp"
