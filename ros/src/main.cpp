// projsurf_node: see node.hpp and the ROS section of README.md.
#include <ros/ros.h>

#include "node.hpp"
#include "params.hpp"
#include "projsurf/io/files/errors.hpp"

int main(int argc, char **argv) {
    ros::init(argc, argv, "projsurf_node");
    ros::NodeHandle nh;
    ros::NodeHandle pnh("~");
    projsurf::ros_node::NodeParams params;
    try {
        params = projsurf::ros_node::loadParams(pnh);
    } catch (const projsurf::InputError &e) {
        ROS_FATAL("projsurf_node: error: %s", e.what());
        return 2;
    }
    try {
        projsurf::ros_node::ProjsurfNode node(nh, pnh, params);
        ros::spin();
    } catch (const projsurf::InputError &e) {
        ROS_FATAL("projsurf_node: error: %s", e.what());
        return 2;
    }
    return 0;
}
