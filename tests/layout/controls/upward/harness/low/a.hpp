// A low room reaching up: refused.
#include "harness/high/b.hpp"
