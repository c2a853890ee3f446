#pragma once
// The 3-D surface checker (paper 3.2.3): are the points that fall inside the rectangle on
// the plane?
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/core/cloud.hpp"
#include "projsurf/core/plane_frame.hpp"

namespace projsurf {

struct SurfaceCheckResult {
    int points = 0;     ///< points of the original cloud inside the rectangle
    int outliers = 0;   ///< of those, off the surface
    bool accepted = false;
    std::vector<int> outlier_indices;
};

/// Paper: points whose orthogonal projection falls inside the rectangle; outlier when
/// (z - mean z)^2 > threshold^2 in the plane-aligned frame; reject above max_outliers.
SurfaceCheckResult checkSurfacePaper(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                     double threshold, int max_outliers);

/// How far off a plane a depth reading may be, as a function of its depth z (m).
/// sigma_z = k z^2 (Khoshelham & Oude Elberink 2012, Kinect v1).
struct DepthTolerance {
    double noise_k = 1.425e-3;   ///< 1/m
    double sigmas = 3.0;         ///< inlier band in sigmas
    double min_band = 0.01;      ///< m
    double max_band = 0.06;      ///< m
    double obstacle_bands = 2.0; ///< beyond this many bands: an obstacle or a hole
    double min_obstacle = 0.03;  ///< m, and at least this far

    /// Within this distance a point is on the plane.
    float band(float z) const {
        const double b = sigmas * noise_k * static_cast<double>(z) * z;
        return static_cast<float>(b < min_band ? min_band : (b > max_band ? max_band : b));
    }
    /// Beyond this distance a point is off the plane for sure (obstacle in front, hole behind).
    float margin(float z) const {
        const float m = static_cast<float>(obstacle_bands) * band(z);
        return m > min_obstacle ? m : static_cast<float>(min_obstacle);
    }
};

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
