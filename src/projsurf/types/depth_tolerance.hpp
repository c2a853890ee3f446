#pragma once
// How far off a plane a depth reading may be, as a function of its depth z (m):
// sigma_z = k z^2 (Khoshelham & Oude Elberink 2012, Kinect v1).

namespace projsurf {

struct DepthTolerance {
    double noise_k = 1.425e-3;    ///< [1e-6, 1] 1/m, sigma_z = k z^2 (K&OE 2012: 1.4 mm at 1 m, 12.8 mm at 3 m)
    double sigmas = 3.0;          ///< [0.01, 100] inlier band in sigmas of the depth noise
    double min_band = 0.01;       ///< [0.0001, 10] m, band floor (flat posters, 3 mm proud, stay inliers)
    double max_band = 0.06;       ///< [0.0001, 10] m, band ceiling (beyond 4 m the Kinect is outside its use range)
    double obstacle_bands = 2.0;  ///< [0.01, 100] beyond this many bands a point is an obstacle or a hole
    double min_obstacle = 0.03;   ///< [0, 10] m, and at least this far (paper 3.2.3 uses 0.05)

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

}  // namespace projsurf
