#pragma once
// projsurf/tracking: a rectangle held steady over a stream (continuous mode).
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/tracking/continuous_tracker.hpp"
#include "projsurf/tracking/steady_tracker.hpp"
