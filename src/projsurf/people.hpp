#pragma once
// projsurf/people: what stands in the beam (blanking) and the focus distances of a detection.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/people/beam_blanking.hpp"
#include "projsurf/people/focus.hpp"
