#pragma once
// projsurf/detector: paper 3.2 on a frame: SurfaceDetector and detectSurface, the configured method
// over a cloud.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detector/detector.hpp"
