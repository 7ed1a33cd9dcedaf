// May use the shared helpers.
#include "properties/support/h.hpp"
