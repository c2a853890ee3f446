#pragma once
// Is a given gravity what the user meant? Two mistakes that still make valid input: an "up"
// vector (a raw accelerometer reading points up, against gravity) given as gravity, which
// puts the floor above the camera; and a vector along the optical axis (a world z-up
// convention, 0,0,-1 or 0,0,1, taken for the camera's optical frame, x right, y down, z forward).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

constexpr double kOpticalAxisWarningDeg = 30.0;  ///< deg, a gravity this near the optical axis is a camera
                                                 ///< looking straight up or down, unlikely on a projector robot

/// Warning texts (without "projsurf: warning: "), empty when none applies. `what` names the
/// option ("--gravity", "gravity="); `gravity` is the camera-frame vector as given.
std::vector<std::string> gravityWarnings(const std::string &what, const Eigen::Vector3d &gravity, const Cloud &cloud);

}  // namespace projsurf::frontend
