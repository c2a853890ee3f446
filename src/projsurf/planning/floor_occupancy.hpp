#pragma once
// Where on the floor the robot may stand and drive: floor cells (5 cm, in the levelled
// frame about the camera's foot) that the cloud shows occupied, i.e. holding two points or
// more that stand between `obstacle_height` and 2 m above the floor. Space the camera did
// not see counts as free (the robot may be sent into it: behind itself, round a corner).
#include <Eigen/Core>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/planning/levelled_frame.hpp"

namespace projsurf {

class FloorOccupancy {
public:
    /// `reach`: m each way from the camera's foot that the grid covers.
    FloorOccupancy(const Cloud &cloud, const Eigen::Vector3d &gravity, double reach, double obstacle_height);

    /// Whether a disc of `radius` about the floor position of `p` (camera frame) meets an occupied cell.
    bool occupied(const Eigen::Vector3d &p, double radius) const;
    /// Whether the disc, driven straight from the camera's foot to that of `p`, meets one (5 cm steps).
    bool pathBlocked(const Eigen::Vector3d &p, double radius) const;

    /// Height of `p` above the floor (m; the floor is the 99th percentile of the lowest points).
    double aboveFloor(const Eigen::Vector3d &p) const { return floor_ - p.dot(g_); }
    bool floorSeen() const { return floor_seen_; }
    const LevelledFrame &frame() const { return frame_; }

private:
    static constexpr double kCell = 0.05;  ///< m
    int index(const Eigen::Vector3d &p) const;
    Eigen::Vector3d g_;
    LevelledFrame frame_;
    double floor_ = 0.0;
    bool floor_seen_ = false;
    int half_ = 0, side_ = 1;
    std::vector<int> count_;
};

}  // namespace projsurf
