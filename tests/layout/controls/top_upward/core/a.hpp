#pragma once
#include "harness/b.hpp"
