#pragma once
// Where the robot should stand (contract "Where to stand"): from one cloud, the rigid move on
// the floor (a rotation about gravity and a translation perpendicular to it) after which the
// projector shows the largest picture, or the shortest move that shows at least a width.
//
// Today's answer is the detection's (the caller's, or detectSurface's): the plan never
// disagrees with `detect` about where the robot stands. The stances: every vertical surface
// detection considers, seen free over all of the camera's view (plan_surfaces.hpp), searched
// over every turn and every position on the free floor within the longest move
// (stance_search.hpp), each judged from the stance itself: the moved projector's footprint,
// the shadows of what stands in front from the moved projector and camera, the depth
// camera's range (stance_view.hpp). The move is said in the gravity-levelled robot frame
// (levelled_frame.hpp).
#include <Eigen/Core>
#include <string>

#include "projsurf/detector/detector.hpp"
#include "projsurf/planning/levelled_frame.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

struct PlanOptions {
    double max_move = 2.0;      ///< m, the translation's length at most (contract default)
    double width = 0.0;         ///< m; > 0: the shortest move giving at least this width
    double step = 0.25;         ///< m, the coarse grid of positions (at least max_move / 8; refined to 3 cm)
    double turn_step_deg = 15;  ///< deg, the coarse turns, all the way round (refined to 1.9 deg)
    double robot_radius = 0.3;  ///< m, the robot's footprint on the floor (a small mobile base)
    double cell = 0.03;         ///< m, the plan's free-surface raster (coarser than detection's 0.01: speed)
    double obstacle_height = 0.08;  ///< m above the floor: higher points occupy (floor noise and thresholds below)
    /// m, the picture's farthest corner from the moved camera at most: the depth camera must
    /// still see the wall to detect and track it (Kinect v1: 1.7 cm noise at 3.5 m, K&OE 2012).
    double max_distance = 3.5;
    double beyond_view = 0.75;  ///< m of wall assumed free beyond the camera's view (plan_surfaces.hpp)
    /// A m^2 of that assumed wall counts this much of a seen one when pictures are ranked
    /// (stance_search.hpp; our choice: a picture on seen wall wins over a similar one on unseen).
    double assumed_weight = 0.75;
    /// A picture more than half on that assumed wall is not proposed (stance_search.hpp).
    double max_assumed_share = 0.5;
    /// A move is proposed only for a picture this many times today's (our choice: 5 % more is
    /// not worth driving for).
    double min_gain = 1.05;
};

struct PlanResult {
    bool found = false;
    std::string reason;  ///< why not found (empty when found)
    std::string limit;   ///< what keeps the picture from being larger (or wider): range, floor space, ...
    /// The moved camera's frame in today's: P_today = rotation * P_moved + translation.
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    LevelledMove move;    ///< the same move in the gravity-levelled robot frame
    Rectangle predicted;  ///< after the move, today's camera frame
    /// The share of `predicted` on wall assumed beyond the camera's view, not seen (0 = all
    /// seen; today's picture is always seen).
    double assumed_share = 0.0;
    Detection today;      ///< where the robot stands: the detection's answer
    int surfaces = 0;     ///< vertical surfaces searched
    int poses_tried = 0, poses_occupied = 0, pictures_evaluated = 0;

    double todayArea() const { return today.found ? today.rectangle.area() : 0.0; }
    /// The picture relies on wall that was not seen (more than 1 % of it: a cell's sliver at its edge is not).
    bool assumed() const { return found && assumed_share > 0.01; }
    bool moves() const { return translation.norm() > 1e-9 || (rotation - Eigen::Matrix3d::Identity()).norm() > 1e-9; }
};

/// Today's answer from `today` (the caller's detection of this cloud with this projector and
/// configuration); `config.aspect` sets the picture's aspect (0 = the framebuffer's).
PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &options, const Detection &today);

/// The same with today's answer from detectSurface.
PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &options = {});

}  // namespace projsurf
