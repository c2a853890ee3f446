#pragma once
// Recorded depth cameras: the depth images (sensor_msgs/Image) and camera_infos of a ROS 1
// bag, read by projsurf's own bounded reader (bag_records.hpp), as the node takes them live.
#include <functional>
#include <string>
#include <vector>

#include "projsurf/io/rosbag/bag_records.hpp"
#include "projsurf/io/rosbag/ros_messages.hpp"
#include "projsurf/io/rosbag/rosbag_clouds.hpp"

namespace projsurf {

/// Every topic of the bag with its type. Throws InputError(path, problem) for a bag it cannot read.
std::vector<BagConnection> bagTopics(const std::string &path);

/// The camera_infos on `topic`, in bag time order. Throws InputError for a topic that is not
/// in the bag (the message lists the bag's CameraInfo topics) or of another type.
std::vector<CameraInfoMessage> readBagCameraInfos(const std::string &path, const std::string &topic);

/// Calls `visit` for every depth image (16UC1 mm or 32FC1 m) on `topic`, in bag time order;
/// checks as readBagCameraInfos. Returns the number of images.
std::size_t forEachBagDepthImage(const std::string &path, const std::string &topic,
                                 const std::function<void(const DepthImageMessage &, const BagCloudInfo &)> &visit);

}  // namespace projsurf
