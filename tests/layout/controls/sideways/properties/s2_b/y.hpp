// One part using another: refused.
#include "properties/s1_a/x.hpp"
