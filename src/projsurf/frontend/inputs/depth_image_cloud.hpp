#pragma once
// A depth image and its pinhole as a cloud, as cameras and ROS drivers deliver them: 16-bit
// integers in depth_scale units per metre, or 32-bit floats in metres.
#include <opencv2/core.hpp>
#include <string>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

/// The pinhole of a depth image: fx, fy > 0 and cx, cy finite (px), depth_scale > 0 (units
/// per metre, for 16-bit images). Throws InputError(what, problem) otherwise.
CameraIntrinsics pinholeCamera(const std::string &what, int width, int height, double fx, double fy, double cx,
                               double cy, double depth_scale = 1000.0);

/// Organized cloud (camera optical frame, m; NaN where there is no reading) from a CV_16UC1
/// image (camera.depth_scale units per metre, 0 = no reading) or a CV_32FC1 one (metres; 0,
/// negative and NaN = no reading). Throws InputError(what, problem) for another type or a size
/// that is not the camera's.
Cloud depthImageToCloud(const std::string &what, const cv::Mat &depth, const CameraIntrinsics &camera);

}  // namespace projsurf::frontend
