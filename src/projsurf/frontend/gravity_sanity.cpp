#include "projsurf/frontend/gravity_sanity.hpp"

#include <cmath>
#include <cstdio>

#include "projsurf/detection/gravity.hpp"
#include "projsurf/frontend/gravity_choice.hpp"

namespace projsurf::frontend {
namespace {

std::string vec(const Eigen::Vector3d &v) {
    char buf[100];
    std::snprintf(buf, sizeof buf, "%g,%g,%g", v.x() + 0.0, v.y() + 0.0, v.z() + 0.0);  // no "-0"
    return buf;
}

}  // namespace

std::vector<std::string> gravityWarnings(const std::string &what, const Eigen::Vector3d &gravity, const Cloud &cloud) {
    std::vector<std::string> out;
    const Eigen::Vector3d g = gravity.normalized();
    const double to_axis_deg = std::acos(std::min(1.0, std::abs(g.z()))) * 180.0 / M_PI;
    if (to_axis_deg < kOpticalAxisWarningDeg) {
        out.push_back(what + " " + vec(gravity) +
                      " points along the camera's optical axis (a camera looking straight " +
                      (g.z() > 0 ? "down" : "up") +
                      "); gravity is in the camera's optical frame (x right, y down, z forward), where a level "
                      "camera's is 0,1,0 (a z-up world's 0,0,-1 is not this frame), or auto");
        return out;
    }
    // The floor: the biggest near-horizontal plane on the far side of the camera along a prior.
    // Found along -g but not along g (or with far more points): the floor is above the camera.
    const auto along = estimateGravityFromFloor(cloud, g);
    const auto against = estimateGravityFromFloor(cloud, -g);
    if (against && (!along || against->floor_points > 2 * along->floor_points))
        out.push_back(what + " " + vec(gravity) +
                      " puts the floor above the camera: gravity points down, towards the floor (a raw "
                      "accelerometer reading points up; give " +
                      vec(-gravity) + ", or auto)");
    return out;
}

std::optional<std::string> levelCameraWarning(const std::string &how_auto, const Cloud &cloud) {
    const auto deg = floorTiltFromLevelDeg(cloud);
    if (!deg || !(*deg > kTiltWarningDeg)) return std::nullopt;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.0f", *deg);
    return std::string("the floor says the camera is tilted ") + buf + " deg from level; give " + how_auto +
           " (or the robot's gravity) so that the picture stands upright";
}

}  // namespace projsurf::frontend
