// A control of ctest layout.formatted: its project includes out of order.
#include "core/a.hpp"
#include "core/b.hpp"

int f() { return 1; }
