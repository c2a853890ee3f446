#pragma once
// A small simulated scene for the node tests: a room corner seen by a depth camera on a robot.
// World frame "odom": x forward, y left, z up (ROS REP 103). The scene: a front wall x = 2 m,
// a side wall y = -1.2 m (on the robot's right) and the floor z = 0. The camera sits 1 m above
// the floor; its optical frame is x right, y down, z forward.
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::sim_test {

struct SceneOptions {
    bool front_wall = true;
    bool side_wall = true;
    double noise_k = 1.425e-3;  ///< 1/m, sigma_z = k z^2 (Kinect-like)
    unsigned seed = 1;
    /// A person: the slab x = person_x (odom), |y - person_y| <= 0.22 m, 0 <= z <= 1.7 m.
    bool person = false;
    double person_x = 1.2, person_y = 0.0;
    /// A framed picture hung flat on the front wall (no depth of its own): odom y in
    /// [picture_y0, picture_y1], z in [picture_z0, picture_z1]; only the colour shows it.
    bool picture = false;
    double picture_y0 = 0.15, picture_y1 = 0.65, picture_z0 = 1.0, picture_z1 = 1.45;
};

/// Whether the ray origin + t dir (odom, t > 0) meets the person (it stands in front of every wall).
bool hitsPerson(const SceneOptions &options, const Eigen::Vector3d &origin, const Eigen::Vector3d &dir);

/// Pose of the camera's optical frame in odom for a robot at (x, y) with heading yaw (rad),
/// camera 1 m above the floor, looking along the robot's heading.
Eigen::Isometry3d cameraPose(double x, double y, double yaw);

/// Organized 320x240 cloud (fx = fy = 262.5) of the scene from `odom_from_camera`, in the
/// camera frame, NaN where a ray hits nothing within 8 m.
Cloud renderScene(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &options);

/// The colour image registered to renderScene's cloud (same pixels, BGR CV_8UC3): white wall,
/// beige side wall, grey floor, a dark person, the framed picture (a dark 4 cm frame round
/// blocks of colour 4 cm across), with sensor noise (sigma 2 grey levels); black where nothing is hit.
cv::Mat renderColour(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &options);

/// The projector the tests calibrate with (the contract's example).
Projector testProjector();
/// Writes it as a calibration YAML.
void writeTestCalibration(const std::string &path);

}  // namespace projsurf::sim_test
