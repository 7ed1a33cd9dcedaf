// Nothing above.
#include "core/subject.hpp"
