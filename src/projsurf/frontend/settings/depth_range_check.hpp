#pragma once
// Is the cloud in metres? The median depth of a cloud against what an RGB-D camera reads:
// nearer than its minimum range or farther than its useful range means a wrong depth_scale
// (a depth PNG) or a cloud written in millimetres. A warning, not an error: the input is valid.
#include <optional>
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

constexpr double kMinSensorRange = 0.4;  ///< m, the minimum range of structured-light / stereo RGB-D cameras
                                         ///< (Kinect v1 0.4-0.5 m, RealSense D435 ~0.3 m at 848x480)
constexpr double kCloseUpDepth = 0.75;   ///< m, a median nearer than this is a close-up no projector robot works
                                         ///< at (a 39 deg picture there is under 0.55 m wide), and what a
                                         ///< depth_scale 3-10x too large makes of rooms seen from 1.3-4 m
constexpr double kMaxSensorRange = 8.0;  ///< m, beyond the useful range of the same cameras (Kinect v1 ~4-6 m,
                                         ///< clamped at 10 m by NYU; RealSense D435 ~10 m rated, noisy past 6)

/// The median z (m) of the cloud's finite points, sampled; nullopt with fewer than 100 samples.
std::optional<double> medianDepth(const Cloud &cloud);

/// The warning text (without "projsurf: warning: ") when the median depth is outside
/// [kMinSensorRange, kMaxSensorRange], or inside it but nearer than kCloseUpDepth (said as a
/// close-up to check), else nullopt. `source` names the file to fix: the
/// camera YAML of a depth PNG (`from_depth_image`: its depth_scale is the usual cause), or the
/// cloud file (a median of 100 to 100000 "m" is named as millimetres).
std::optional<std::string> depthRangeWarning(const Cloud &cloud, const std::string &source, bool from_depth_image);

}  // namespace projsurf::frontend
