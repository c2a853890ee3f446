#include "projsurf/core/surface_check.hpp"
