// In a folder that says nothing.
#include "harness/low/a.hpp"
