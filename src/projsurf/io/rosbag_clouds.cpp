#include "projsurf/io/rosbag_clouds.hpp"

#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"

#ifdef PROJSURF_HAVE_ROSBAG
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include <set>

#include "projsurf/io/pointcloud2.hpp"
#endif

namespace projsurf {

#ifdef PROJSURF_HAVE_ROSBAG

bool haveRosbagSupport() { return true; }

namespace {

constexpr const char *kCloudType = "sensor_msgs/PointCloud2";

}  // namespace

std::size_t forEachBagCloud(const std::string &path, const std::string &topic,
                            const std::function<void(const Cloud &, const BagCloudInfo &)> &visit) {
    requireReadable(path);
    rosbag::Bag bag;
    try {
        bag.open(path, rosbag::bagmode::Read);
    } catch (const rosbag::BagException &e) {
        throw InputError(path, std::string("not a readable ROS bag (") + e.what() + ")");
    }

    // Check the topic against what the bag holds before reading any message.
    std::set<std::string> cloud_topics;
    std::string topic_type;
    try {
        rosbag::View all(bag);
        for (const rosbag::ConnectionInfo *c : all.getConnections()) {
            if (c->datatype == kCloudType) cloud_topics.insert(c->topic);
            if (c->topic == topic) topic_type = c->datatype;
        }
    } catch (const rosbag::BagException &e) {
        throw InputError(path, std::string("corrupt ROS bag (") + e.what() + ")");
    }
    if (topic_type.empty()) {
        std::string have;
        for (const auto &t : cloud_topics) have += (have.empty() ? "" : ", ") + t;
        throw InputError(path, "no topic '" + topic + "' in the bag (PointCloud2 topics: " +
                                   (have.empty() ? "none" : have) + ")");
    }
    if (topic_type != kCloudType)
        throw InputError(path, "topic '" + topic + "' holds " + topic_type + ", not " + kCloudType);

    std::size_t index = 0;
    try {
        rosbag::View view(bag, rosbag::TopicQuery(topic));
        for (const rosbag::MessageInstance &m : view) {
            const auto msg = m.instantiate<sensor_msgs::PointCloud2>();
            if (!msg) throw InputError(path, "message " + std::to_string(index) + " on '" + topic + "' cannot be read");
            BagCloudInfo info;
            info.stamp = msg->header.stamp.isZero() ? m.getTime().toSec() : msg->header.stamp.toSec();
            info.frame_id = msg->header.frame_id;
            info.index = index;
            const Cloud cloud =
                cloudFromPointCloud2(viewOfMessage(*msg), path + ":" + topic + "#" + std::to_string(index));
            visit(cloud, info);
            ++index;
        }
    } catch (const rosbag::BagException &e) {
        throw InputError(path, std::string("corrupt ROS bag (") + e.what() + ")");
    } catch (const ros::Exception &e) {
        throw InputError(path, std::string("corrupt ROS bag message (") + e.what() + ")");
    }
    return index;
}

#else  // no rosbag_storage in this build

bool haveRosbagSupport() { return false; }

std::size_t forEachBagCloud(const std::string &path, const std::string &,
                            const std::function<void(const Cloud &, const BagCloudInfo &)> &) {
    throw InputError(path, "this build of projsurf cannot read ROS bags (install ROS 1, see scripts/setup.sh, and rebuild)");
}

#endif

}  // namespace projsurf
