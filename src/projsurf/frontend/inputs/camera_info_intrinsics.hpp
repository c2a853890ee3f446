#pragma once
// A ROS depth image's pinhole from its camera_info (sensor_msgs/CameraInfo), one conversion for
// the node's topics and a bag's messages: the size, K, and the depth image's encoding, which
// fixes the depth's unit (REP 118: 16UC1 in millimetres, 32FC1 in metres).
#include <array>
#include <cstdint>
#include <string>

#include "projsurf/types/camera.hpp"

namespace projsurf::frontend {

/// Units per metre of a 16UC1 (or mono16) depth image: millimetres (REP 118).
constexpr double kRosDepthMillimetres = 1000.0;
/// Units per metre of a 32FC1 depth image: metres (REP 118).
constexpr double kRosDepthMetres = 1.0;

/// The depth scale (units per metre) of a depth image's encoding: kRosDepthMillimetres for
/// 16UC1 and mono16, kRosDepthMetres for 32FC1. Throws InputError(what, problem) for another.
double rosDepthScale(const std::string &what, const std::string &encoding);

/// The pinhole of a depth image of `encoding` whose camera_info gives `width` x `height` and
/// K (row-major: fx K[0], cx K[2], fy K[4], cy K[5]; the depth is taken as rectified, so D is
/// not read). Throws InputError(what, problem) for a focal length that is zero, negative or not
/// finite, a centre that is not finite, or an encoding that is not depth (pinholeCamera's checks).
CameraIntrinsics cameraInfoIntrinsics(const std::string &what, std::uint32_t width, std::uint32_t height,
                                      const std::array<double, 9> &K, const std::string &encoding);

}  // namespace projsurf::frontend
