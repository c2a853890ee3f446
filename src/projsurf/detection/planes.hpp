#pragma once
// projsurf/detection/planes: paper 3.2.1: vertical planes by sequential RANSAC on a sample of the
// cloud, and an unorganized cloud seen as the depth image a pinhole would have taken of it.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detection/planes/point_sampling.hpp"
#include "projsurf/detection/planes/vertical_planes.hpp"
#include "projsurf/detection/planes/virtual_depth_image.hpp"
