#pragma once
// Is a given gravity what the user meant? Two mistakes that still make valid input: an "up"
// vector (a raw accelerometer reading points up, against gravity) given as gravity, which
// puts the floor above the camera; and a vector along the optical axis (a world z-up
// convention, 0,0,-1 or 0,0,1, taken for the camera's optical frame, x right, y down, z forward).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

constexpr double kTiltWarningDeg = 5.0;          ///< deg, a floor this far from level means the camera is not level
constexpr double kOpticalAxisWarningDeg = 30.0;  ///< deg, a gravity this near the optical axis is a camera
                                                 ///< looking straight up or down, unlikely on a projector robot

/// Warning texts (without "projsurf: warning: "), empty when none applies. `what` names the
/// option ("--gravity", "gravity="); `gravity` is the camera-frame vector as given.
std::vector<std::string> gravityWarnings(const std::string &what, const Eigen::Vector3d &gravity, const Cloud &cloud);

/// No gravity was given, so a level camera is assumed, but the floor in view says the camera
/// is tilted by more than kTiltWarningDeg: the warning text, naming `how_auto` (the front end's
/// way to ask for the floor's gravity, "--gravity auto" or "gravity='auto'").
std::optional<std::string> levelCameraWarning(const std::string &how_auto, const Cloud &cloud);

}  // namespace projsurf::frontend
