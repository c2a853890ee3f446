#pragma once
// The node's ~plan (contract "Where to stand"): on the latest cloud, where the
// robot should stand for the largest picture (or ~plan_width). Answered through
// std_srvs/Trigger (success = found, message = the summary in words and the plan JSON, as
// `projsurf plan` writes them); the moved camera's
// pose is published as ~plan_pose (geometry_msgs/PoseStamped, camera optical frame's pose in
// ~fixed_frame, else in the cloud's frame) and the predicted rectangle as ~plan_marker.
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <string>

#include "projsurf/planning/stand_planner.hpp"

namespace projsurf::ros_node {

class NodePlanner {
public:
    NodePlanner(ros::NodeHandle &pnh, const Projector &projector, const DetectorConfig &config,
                const PlanOptions &options);

    struct Answer {
        bool found = false;
        std::string message;
    };
    /// Plans on `cloud` (camera frame `camera_frame`), `today` being ~detect's answer on it;
    /// `fixed_from_camera` maps it into `frame`.
    Answer plan(const Cloud &cloud, const Eigen::Vector3d &gravity, const Detection &today,
                const Eigen::Isometry3d &fixed_from_camera, const std::string &frame, const ros::Time &stamp);

private:
    Projector projector_;
    DetectorConfig config_;
    PlanOptions options_;
    ros::Publisher pose_pub_, marker_pub_;
};

}  // namespace projsurf::ros_node
