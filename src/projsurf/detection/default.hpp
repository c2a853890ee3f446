#pragma once
// projsurf/detection/default: the default method's top function (detectDefault; usually reached
// through projsurf/detector.hpp) and the observed free space a plan reads.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/detection/default/observed_free_space.hpp"
