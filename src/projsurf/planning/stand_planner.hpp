#pragma once
// Where the robot should stand (contract "Where to stand"): from one cloud, the rigid move on
// the floor (a rotation about gravity and a translation perpendicular to it) after which the
// projector shows the largest picture, or the smallest move that shows at least a width.
//
// The free surface comes from one detection with a virtual projector at the lens whose wide
// field of view (90 x 70 deg) covers everything the camera sees: so the surface is the wall
// the camera saw free, not only today's footprint. Only the surface that detection chooses
// (the one holding the largest picture seen) is planned on. Each candidate pose moves the real
// projector; its footprint on that surface, intersected with the free cells, holds the
// predicted rectangle. A pose is refused when the robot's disc, or the straight way there,
// meets space the cloud shows as occupied (points off the floor), when the surface is nearer
// than the robot's radius, or when the picture would lie beyond the depth camera's good range.
#include <Eigen/Core>
#include <string>

#include "projsurf/types/plane_frame.hpp"
#include "projsurf/detection/detector.hpp"

namespace projsurf {

struct PlanOptions {
    double max_move = 2.0;          ///< m, the translation's length at most (contract default)
    double width = 0.0;             ///< m; > 0: the smallest move giving at least this width
    double max_yaw_deg = 45.0;      ///< deg, turns tried either way (our choice)
    double yaw_step_deg = 5.0;      ///< deg (our choice)
    double step = 0.1;              ///< m, grid of translations tried (our choice; at least max_move / 20)
    double robot_radius = 0.3;      ///< m, the robot's footprint on the floor (a small mobile base)
    double cell = 0.02;             ///< m, free-surface raster of the plan (coarser than detection's 0.01: speed)
    double obstacle_height = 0.08;  ///< m above the floor: higher points occupy (floor noise and thresholds below)
    /// m, the picture's farthest corner from the moved camera at most: the depth camera must
    /// still see the wall to detect and track it (Kinect v1: 1.7 cm noise at 3.5 m, K&OE 2012).
    double max_distance = 3.5;
};

struct PlanResult {
    bool found = false;
    std::string reason;
    /// The moved camera's frame in today's: P_today = rotation * P_moved + translation.
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    Rectangle predicted;  ///< after the move, today's camera frame
    Rectangle today;      ///< the same prediction without moving (0 area when none fits)
    int poses_tried = 0, poses_occupied = 0;
};

/// `config.aspect` sets the picture's aspect (0 = the framebuffer's).
PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &options = {});

}  // namespace projsurf
