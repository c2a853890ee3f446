#include "projsurf/frontend/inputs/bag_frames.hpp"

#include <vector>

#include "projsurf/frontend/inputs/camera_info_intrinsics.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/frontend/inputs/stamp_pairing.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/rosbag_depth.hpp"

namespace projsurf::frontend {
namespace {

/// The topic to read: `topic`, else the bag's one usable topic, else an error that lists them.
BagConnection bagTopic(const BagRequest &q) {
    const std::string &bag = q.bag, &topic = q.topic;
    const std::vector<BagConnection> topics = bagTopics(bag);
    std::vector<BagConnection> usable;
    for (const BagConnection &c : topics) {
        if (!topic.empty() && c.topic == topic) return c;
        if (c.type == "sensor_msgs/PointCloud2" || (c.type == kImageType && c.topic.find("depth") != std::string::npos))
            usable.push_back(c);
    }
    std::string list;
    for (const BagConnection &c : usable) list += (list.empty() ? "" : ", ") + c.topic + " (" + c.type + ")";
    if (!topic.empty())
        throw InputError(bag,
                         "no topic '" + topic + "' in the bag (usable topics: " + (list.empty() ? "none" : list) + ")");
    if (usable.size() == 1) return usable.front();
    if (usable.empty())
        throw InputError(bag, "has no sensor_msgs/PointCloud2 topic and no depth sensor_msgs/Image topic");
    throw InputError(
        bag, "has " + std::to_string(usable.size()) + " usable topics, give one with " + q.topic_option + ": " + list);
}

/// The camera_info topic of a depth topic: `info_topic`, else camera_info beside it
/// (/camera/depth/image_rect -> /camera/depth/camera_info), else the bag's only CameraInfo topic.
std::string cameraInfoTopic(const BagRequest &q, const std::string &depth_topic) {
    const std::string &bag = q.bag;
    if (!q.info_topic.empty()) return q.info_topic;
    const std::string beside = depth_topic.substr(0, depth_topic.find_last_of('/') + 1) + "camera_info";
    std::vector<std::string> infos;
    for (const BagConnection &c : bagTopics(bag)) {
        if (c.type != kCameraInfoType) continue;
        if (c.topic == beside) return beside;
        infos.push_back(c.topic);
    }
    if (infos.size() == 1) return infos.front();
    throw InputError(bag,
                     "no camera_info for " + depth_topic + " (looked for " + beside + "; give " + q.info_option + ")");
}

/// The depth images of `r.topic`, each with the camera_info of its stamp (else the nearest).
void visitDepthImages(const BagRequest &q, BagFrames &r, const BagFrameVisit &visit) {
    const std::string &bag = q.bag;
    r.what = "depth images";
    const std::string info_topic = cameraInfoTopic(q, r.topic);
    const std::vector<CameraInfoMessage> all = readBagCameraInfos(bag, info_topic);
    StampedBuffer<CameraInfoMessage> infos(all.size() + 1);
    for (const CameraInfoMessage &c : all) infos.add(c.header.stamp(), c);
    std::size_t unpaired = 0;
    r.count = forEachBagDepthImage(bag, r.topic, [&](const DepthImageMessage &m, const BagCloudInfo &info) {
        const std::string source = bag + ":" + r.topic + "#" + std::to_string(info.index);
        const CameraInfoMessage *k = infos.exact(info.stamp);
        double at = 0.0;
        if (!k) {
            k = infos.nearest(info.stamp, at);
            ++unpaired;
        }
        if (!k) throw InputError(bag, "no camera_info on " + info_topic);
        const CameraIntrinsics cam =
            cameraInfoIntrinsics(source + " (camera_info)", k->width, k->height, k->K, m.encoding);
        visit(depthImageToCloud(source, m.depth, cam), info, r.topic);
    });
    if (unpaired > 0)
        r.warning = bag + ": " + std::to_string(unpaired) + " of " + std::to_string(r.count) +
                    " depth images had no camera_info of their stamp on " + info_topic + "; the nearest was used";
}

}  // namespace

BagFrames forEachBagFrame(const BagRequest &request, const BagFrameVisit &visit) {
    BagFrames r;
    const BagConnection connection = bagTopic(request);
    r.topic = connection.topic;
    if (connection.type == kImageType)
        visitDepthImages(request, r, visit);
    else
        r.count = forEachBagCloud(request.bag, r.topic,
                                  [&](const Cloud &cloud, const BagCloudInfo &info) { visit(cloud, info, r.topic); });
    return r;
}

}  // namespace projsurf::frontend
