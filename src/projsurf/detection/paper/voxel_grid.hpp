#pragma once
// Voxel-grid downsampling (paper 3.2.1): every occupied cube of side `leaf` becomes the
// centroid of its points.
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// Centroids of the occupied voxels; NaN points are ignored. Output order is by voxel key.
std::vector<Point> voxelDownsample(const std::vector<Point> &points, double leaf);

}  // namespace projsurf
