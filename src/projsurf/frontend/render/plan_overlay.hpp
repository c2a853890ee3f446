#pragma once
// A picture of a plan: on the frame, today's rectangle (detect's answer, with what detect's
// overlay shows) and the proposed one; beside it, a top-down sketch of what the camera saw on
// the floor with the robot now and after the move.
#include <opencv2/core.hpp>

#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/types/camera.hpp"

namespace projsurf {

/// `camera`: intrinsics of an organized cloud (nullptr: estimated from the cloud); `gravity`:
/// the plan's; `robot_radius`: m, the disc drawn; `colour`: BGR image registered to the cloud,
/// the frame's background as in detect's overlay (empty: the depth). A proposed picture that
/// relies on wall not seen is drawn dashed, and the line above says how much.
cv::Mat renderPlanOverlay(const Cloud &cloud, const PlanResult &plan, const DetectorConfig &config,
                          const CameraIntrinsics *camera, const Eigen::Vector3d &gravity, double robot_radius,
                          const cv::Mat &colour = cv::Mat());

}  // namespace projsurf
