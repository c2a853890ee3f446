#pragma once
// "Which way is down" as a user chooses it: a vector in the camera frame (gx,gy,gz; default a
// level camera, 0,1,0), or `auto`: from the floor in each cloud, else a level camera.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "projsurf/detector/detector.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

struct GravityChoice {
    Eigen::Vector3d gravity =
        SurfaceDetector::levelGravity();  ///< camera frame, not necessarily unit; the fallback of `from_floor`
    bool from_floor = false;              ///< `auto`: estimated from the floor of each cloud
};

/// "" (a level camera), "auto", or three numbers "gx,gy,gz" (commas or spaces) -> the choice.
/// Throws InputError(what, problem) for anything else, a non-finite or a zero vector.
GravityChoice parseGravityChoice(const std::string &what, const std::string &text);
/// Three numbers (a ROS list, a numpy array) -> the choice; same checks.
GravityChoice gravityChoiceFrom(const std::string &what, const double *values, std::size_t count);

struct ResolvedGravity {
    Eigen::Vector3d gravity;   ///< camera frame; what the detector is given
    bool floor_found = false;  ///< `auto` found a floor (false: the fallback is used)
};

/// The gravity for one cloud: with `from_floor`, the floor's down when a floor is in view
/// (detection/gravity.hpp, searched near choice.gravity), else choice.gravity.
ResolvedGravity resolveGravity(const GravityChoice &choice, const Cloud &cloud);

/// Degrees between a level camera's down and the floor's, when a floor is in view: a level
/// camera was assumed, and the floor says by how much it is not.
std::optional<double> floorTiltFromLevelDeg(const Cloud &cloud);

}  // namespace projsurf::frontend
