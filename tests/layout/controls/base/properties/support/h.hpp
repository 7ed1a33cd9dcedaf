// A shared helper reaching into a part: refused.
#include "properties/s9_part/p.hpp"
