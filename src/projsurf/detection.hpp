#pragma once
// projsurf/detection: paper 3.2: what both methods share: every setting (DetectorConfig), what a
// detection returns, gravity, the projector footprint, the plane raster, the largest upright
// rectangle and the surface check.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/gravity.hpp"
#include "projsurf/detection/method_names.hpp"
#include "projsurf/detection/rectangle_search.hpp"
