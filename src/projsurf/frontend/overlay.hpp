#pragma once
// A picture of what detection found, readable at a glance: the scene, the wall's points,
// its free space, the projector workspace, the chosen rectangle, the surface outliers, and a
// legend.
#include <opencv2/core.hpp>

#include "projsurf/types/camera.hpp"
#include "projsurf/detector/detector.hpp"

namespace projsurf {

/// `camera`: intrinsics of an organized cloud (nullptr: estimated from the cloud itself, or a
/// virtual 640x480 Kinect-like view for unorganized clouds). `color`: BGR image registered to
/// the cloud, used as background when its size matches. `explain`: every candidate plane's seen
/// extent outlined and numbered, with why it lost in the status lines (`detect --explain`).
cv::Mat renderOverlay(const Cloud &cloud, const Detection &detection, const DetectorConfig &config,
                      const CameraIntrinsics *camera, const cv::Mat &color, bool explain = false);

/// Pinhole intrinsics that best explain an organized cloud (least squares on u = fx x/z + cx,
/// v = fy y/z + cy); nullopt-like default (fx = 0) when it cannot be estimated.
CameraIntrinsics estimateIntrinsics(const Cloud &cloud);

}  // namespace projsurf
