#pragma once
#include "core/a.hpp"
