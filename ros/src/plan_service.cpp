#include "plan_service.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/Marker.h>

#include "projsurf/frontend/answer/plan_json.hpp"

namespace projsurf::ros_node {

NodePlanner::NodePlanner(ros::NodeHandle &pnh, const Projector &projector, const DetectorConfig &config,
                         const PlanOptions &options)
    : projector_(projector), config_(config), options_(options) {
    pose_pub_ = pnh.advertise<geometry_msgs::PoseStamped>("plan_pose", 1, true);
    marker_pub_ = pnh.advertise<visualization_msgs::Marker>("plan_marker", 1, true);
}

NodePlanner::Answer NodePlanner::plan(const Cloud &cloud, const Eigen::Vector3d &gravity, const Detection &today,
                                      const Eigen::Isometry3d &fixed_from_camera, const std::string &frame,
                                      const ros::Time &stamp) {
    Answer a;
    const PlanResult r = planStand(cloud, projector_, config_, gravity, options_, today);
    if (!r.found) {
        a.message = "no plan: " + r.reason + "; " + frontend::planToJson(r).dump();
        return a;
    }
    a.found = true;
    // The moved camera in the fixed frame: fixed_from_camera * today_from_moved.
    Eigen::Isometry3d today_from_moved = Eigen::Isometry3d::Identity();
    today_from_moved.linear() = r.rotation;
    today_from_moved.translation() = r.translation;
    const Eigen::Isometry3d pose = fixed_from_camera * today_from_moved;
    geometry_msgs::PoseStamped p;
    p.header.frame_id = frame;
    p.header.stamp = stamp;
    p.pose = tf2::toMsg(pose);
    pose_pub_.publish(p);

    visualization_msgs::Marker m;
    m.header = p.header;
    m.ns = "projsurf_plan";
    m.id = 0;
    m.type = visualization_msgs::Marker::LINE_STRIP;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = 0.02;
    m.color.r = 1.0f;
    m.color.g = 0.6f;
    m.color.a = 1.0f;
    for (int i = 0; i <= 4; ++i) {
        const Eigen::Vector3d c = fixed_from_camera * r.predicted.corners[i % 4];
        geometry_msgs::Point pt;
        pt.x = c.x();
        pt.y = c.y();
        pt.z = c.z();
        m.points.push_back(pt);
    }
    marker_pub_.publish(m);

    a.message = frontend::planSummary(r) + "; " + frontend::planToJson(r).dump();
    return a;
}

}  // namespace projsurf::ros_node
