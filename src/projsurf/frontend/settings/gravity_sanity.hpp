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

/// deg: an unorganized cloud whose largest planes all lie this far from both level and
/// vertical, for a level camera, is not in a level camera's frame (walls and floors are one or
/// the other; a pitched camera's frame tilts them all alike).
constexpr double kObliquePlanesWarningDeg = 15.0;

/// No gravity was given, so a level camera is assumed, but the floor in view says the camera
/// is tilted by more than kTiltWarningDeg, or (an unorganized cloud, where no floor within the
/// level camera's reach was found) its largest planes all lie more than
/// kObliquePlanesWarningDeg from level and from vertical: the warning text, naming `how_auto`
/// (the front end's way to ask for the floor's gravity, "--gravity auto" or "gravity='auto'").
std::optional<std::string> levelCameraWarning(const std::string &how_auto, const Cloud &cloud);

/// The largest planes of `cloud` (up to 3, each holding at least 10 % of a sample of its
/// points), as each one's angle (deg) between its normal and the level camera's gravity
/// (0, 1, 0): 0 for a floor or ceiling, 90 for a wall. Biggest first.
std::vector<double> largestPlanesToLevelDeg(const Cloud &cloud);

}  // namespace projsurf::frontend
