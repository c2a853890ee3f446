#pragma once
// The 3-D surface checker (paper 3.2.3): are the points that fall inside the rectangle on
// the plane?
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

/// Default: points seen through the rectangle (camera ray meets the plane inside it);
/// outlier when the distance to the plane exceeds max(min_band, sigmas * k z^2) (depth-noise
/// model), reject when the outlier share exceeds max_fraction. Independent of range and
/// sensor resolution.
/// `step` checks every step-th point (1 = all).
SurfaceCheckResult checkSurface(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                double noise_k, double sigmas, double min_band, double max_fraction, int step = 1);

/// Distance band (m) within which a point at depth z counts as on a plane:
/// clamp(sigmas * k * z^2, min_band, max_band) (sigma_z = k z^2, Khoshelham & Oude Elberink 2012).
inline float depthBand(float z, double noise_k, double sigmas, double min_band, double max_band) {
    const double b = sigmas * noise_k * static_cast<double>(z) * z;
    return static_cast<float>(b < min_band ? min_band : (b > max_band ? max_band : b));
}

}  // namespace projsurf
