// A control of ctest layout.formatted: in the style.
#include "core/a.hpp"
#include "core/b.hpp"

int f() { return 1; }
