#pragma once
// A picture of what detection found, readable at a glance: the scene, the wall's points,
// its free space, the projector workspace, the chosen rectangle, the surface outliers, and a
// legend.
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/detector/detector.hpp"
#include "projsurf/types/camera.hpp"

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

/// `--explain`'s outline of a candidate's seen extent (`box`, camera frame) on a picture of
/// `size` drawn at `scale` picture pixels per camera pixel: the box cut to what lies before
/// the camera, projected and clipped to the picture; empty when none of it is in view.
std::vector<cv::Point2f> outlineInView(const std::array<Eigen::Vector3d, 4> &box, const CameraIntrinsics &camera,
                                       double scale, cv::Size size);

/// Where the legend's right column starts (px) for `entries` (left, right, left, ...) on a
/// picture `cols` wide: half-way, or further right when an entry of the left column would run
/// into it; 0 when the two do not fit side by side (one column).
int legendSecondColumn(const std::vector<std::string> &entries, int cols);

}  // namespace projsurf
