#pragma once
// The 3-D surface checker (paper 3.2.3): are the points that fall inside the rectangle on
// the plane?
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

struct SurfaceCheckResult {
    int points = 0;    ///< points of the original cloud inside the rectangle
    int outliers = 0;  ///< of those, off the surface
    bool accepted = false;
    std::vector<int> outlier_indices;
};

/// Paper: points whose orthogonal projection falls inside the rectangle; outlier when
/// (z - mean z)^2 > threshold^2 in the plane-aligned frame; reject above max_outliers.
SurfaceCheckResult checkSurfaceAgainstMeanDepth(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                                double threshold, int max_outliers);

/// The default method's rule, point by point: points seen through the rectangle (camera ray
/// meets the plane inside it); outlier when farther from the plane than tolerance.margin(z);
/// reject when the outlier share exceeds max_fraction. Independent of range and sensor
/// resolution. The detector reads the same counts off its free-space pass
/// (checkObservedSurface in plane_observation.hpp); this is the reference it is tested against.
/// `step` checks every step-th point (every step-th row and column of an organized cloud);
/// a non-empty `roi` limits an organized cloud to those pixels (where the plane is seen).
SurfaceCheckResult checkSurface(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                const DepthTolerance &tolerance, double max_fraction, int step = 1,
                                const cv::Rect &roi = cv::Rect());

}  // namespace projsurf
