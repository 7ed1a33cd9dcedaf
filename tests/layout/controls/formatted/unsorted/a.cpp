// A control of ctest layout.formatted: its project includes out of order.
#include "core/b.hpp"
#include "core/a.hpp"

int f() { return 1; }
