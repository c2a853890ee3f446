#pragma once
// The clouds of a recorded ROS 1 bag as `detect --bag` and Python's read_bag() take them: one
// topic (a PointCloud2, or a depth sensor_msgs/Image with the camera_info of its stamp), each
// message as a cloud in the camera frame.
#include <functional>
#include <string>

#include "projsurf/io/rosbag/rosbag_clouds.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

/// What was read: the topic, how many messages, and the warning to give (empty: none).
struct BagFrames {
    std::string topic;
    const char *what = "clouds";  ///< "clouds" or "depth images"
    std::size_t count = 0;
    std::string warning;  ///< depth images without a camera_info of their own stamp (the nearest was used)
};

/// Which topic of which bag, and what the front end calls its options in messages.
struct BagRequest {
    std::string bag;
    std::string topic;       ///< "" for the bag's one usable topic (a PointCloud2, or an Image whose name says depth)
    std::string info_topic;  ///< a depth topic's camera_info; "" for the one beside it, or the bag's only one
    std::string topic_option = "--topic", info_option = "--camera-info-topic";
};

/// A message as a cloud, what the bag says of it and the topic read.
using BagFrameVisit = std::function<void(const Cloud &, const BagCloudInfo &, const std::string &topic)>;

/// Calls `visit` for every message of the requested topic as a cloud, in bag time order. A
/// depth image's depth is 16UC1 mm (REP 118) or 32FC1 m. Throws InputError(bag, problem): an
/// unreadable bag, no such topic (the usable ones listed), several usable topics and none
/// given, no camera_info.
BagFrames forEachBagFrame(const BagRequest &request, const BagFrameVisit &visit);

}  // namespace projsurf::frontend
