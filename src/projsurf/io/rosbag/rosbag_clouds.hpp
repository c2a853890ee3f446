#pragma once
// Recorded robot data: the point clouds of one topic of a ROS 1 bag (format 2.0), in order.
// Read by projsurf's own bounded reader (io/rosbag/bag_records.hpp), not the rosbag library; chunks
// may be uncompressed or bz2, and lz4 when the build found ROS (roslz4).
#include <functional>
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// True: every build reads bags (kept for the callers that asked).
bool haveRosbagSupport();

/// What each message of the topic brings besides its points.
struct BagCloudInfo {
    double stamp = 0.0;     ///< header stamp, s (the bag's receive time when the header's is zero)
    std::string frame_id;   ///< header frame_id
    std::size_t index = 0;  ///< 0-based message number on the topic
};

/// Calls `visit` for every sensor_msgs/PointCloud2 on `topic` in `path`, in bag time order.
/// Throws InputError(path, problem) for a missing, unreadable or corrupt bag, a topic that is
/// not in the bag (the message lists the PointCloud2 topics it has), a topic of another type,
/// a message whose layout cannot be read, or a bag beyond io/files/limits.hpp. Returns the number of messages visited.
std::size_t forEachBagCloud(const std::string &path, const std::string &topic,
                            const std::function<void(const Cloud &, const BagCloudInfo &)> &visit);

}  // namespace projsurf
