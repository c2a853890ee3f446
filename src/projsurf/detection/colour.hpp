#pragma once
// projsurf/detection/colour: colour registered to the depth image, and how suitable a surface's
// colour is for a picture.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/detection/colour/surface_suitability.hpp"
