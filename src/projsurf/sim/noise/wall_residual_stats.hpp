#pragma once
// How far a depth frame's wall is from flat, split into smooth (low-frequency) and local
// (per-pixel) error: the statistic that compares a sensor model with a real frame. Used
// identically on real and simulated clouds.
//
// Over the pixels of `region` (a box known to show one plain wall):
//  1. a robust plane fit: least squares, then refits on the points within 3 x 1.4826 MAD of
//     the current plane (at least `min_band`), 5 times; points more than `max_band` off the
//     first fit are not the wall;
//  2. residuals r = signed distance to that plane (m, positive towards the camera);
//  3. `rms` = RMS of r over the inliers (the "RMS about the fitted wall plane");
//  4. smooth part s = mean of r over a `smooth_px` x `smooth_px` window of inliers; `local_rms`
//     = RMS of r - s (per-pixel noise, quantisation included); `low_p1` / `low_p99` = the 1st
//     and 99th percentiles of s.
#include <optional>

#include <opencv2/core.hpp>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane.hpp"

namespace projsurf::sim {

struct WallStatsOptions {
    double max_band = 0.15;  ///< m, farther from the first fit is not the wall
    double min_band = 0.02;  ///< m, the refits keep at least this band
    /// px, window of the smooth fit: about 7 cm at 2.6 m on a VGA Kinect (our choice: wide
    /// enough to average the per-pixel noise, narrow enough to follow the distortion; with it
    /// the classroom frame's local noise is the ~10 mm the field notes give)
    int smooth_px = 15;
    int min_points = 500;
};

struct WallResidualStats {
    int points = 0;                      ///< inliers used
    Plane plane;                         ///< camera frame
    double distance = 0.0;               ///< m, perpendicular camera-wall distance
    double angle_deg = 0.0;              ///< wall normal vs optical axis
    double rms = 0.0;                    ///< m, about the plane
    double local_rms = 0.0;              ///< m, residual minus its smooth part
    double low_p1 = 0.0, low_p99 = 0.0;  ///< m, percentiles of the smooth part
};

/// Nullopt when the region holds fewer than min_points readings near one plane. The cloud
/// must be organized; `region` is clipped to it.
std::optional<WallResidualStats> wallResidualStats(const Cloud &cloud, cv::Rect region,
                                                   const WallStatsOptions &options = {});

}  // namespace projsurf::sim
