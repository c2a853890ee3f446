#pragma once
// The points the default method searches for planes on, and how densely a plane was seen.
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"

namespace projsurf {

/// About `target` finite points spread evenly: a pixel grid on organized clouds, every k-th
/// finite point otherwise. Indices into cloud.points.
std::vector<int> samplePoints(const Cloud &cloud, int target);

/// Typical distance (m) between neighbouring points `step` pixels apart on `plane`, measured at
/// its sampled inliers `inliers` (cloud indices) of an organized cloud: the size of the gaps a
/// support raster must close. Unorganized clouds (or too few neighbours): `spread_area` (m^2,
/// the area the inliers spread over) shared among `support_points` points.
double sampleSpacing(const Cloud &cloud, const std::vector<int> &inliers, const Plane &plane, int step,
                     const DepthTolerance &tolerance, double spread_area, int support_points);

}  // namespace projsurf
