#include "projsurf/io/rosbag/rosbag_depth.hpp"

#include <set>

#include "projsurf/io/files/errors.hpp"

namespace projsurf {
namespace {

/// `topic` is in the bag and holds `type` (of this md5sum, when the bag says).
void requireTopic(const BagFile &bag, const std::string &path, const std::string &topic, const std::string &type,
                  const std::string &md5) {
    std::set<std::string> of_type;
    std::string topic_type, topic_md5;
    for (const BagConnection &c : bag.connections()) {
        if (c.type == type) of_type.insert(c.topic);
        if (c.topic == topic) topic_type = c.type, topic_md5 = c.md5sum;
    }
    if (topic_type.empty()) {
        std::string have;
        for (const auto &t : of_type) have += (have.empty() ? "" : ", ") + t;
        throw InputError(path, "no topic '" + topic + "' in the bag (" + type.substr(type.find('/') + 1) +
                                   " topics: " + (have.empty() ? "none" : have) + ")");
    }
    if (topic_type != type) throw InputError(path, "topic '" + topic + "' holds " + topic_type + ", not " + type);
    if (!topic_md5.empty() && topic_md5 != "*" && topic_md5 != md5)
        throw InputError(path, "topic '" + topic + "' holds a " + type + " of another definition (md5sum " +
                                   topic_md5.substr(0, 32) + ")");
}

}  // namespace

std::vector<BagConnection> bagTopics(const std::string &path) { return BagFile(path, "").connections(); }

std::vector<CameraInfoMessage> readBagCameraInfos(const std::string &path, const std::string &topic) {
    BagFile bag(path, topic);
    requireTopic(bag, path, topic, kCameraInfoType, kCameraInfoMd5);
    std::vector<CameraInfoMessage> out;
    for (const BagMessageRef &m : bag.messages()) {
        CameraInfoMessage info = parseCameraInfo(bag.read(m), path + ":" + topic + "#" + std::to_string(out.size()));
        if (info.header.sec == 0 && info.header.nsec == 0) info.header.sec = m.sec, info.header.nsec = m.nsec;
        out.push_back(std::move(info));
    }
    return out;
}

std::size_t forEachBagDepthImage(const std::string &path, const std::string &topic,
                                 const std::function<void(const DepthImageMessage &, const BagCloudInfo &)> &visit) {
    BagFile bag(path, topic);
    requireTopic(bag, path, topic, kImageType, kImageMd5);
    std::size_t index = 0;
    for (const BagMessageRef &m : bag.messages()) {
        DepthImageMessage depth = parseDepthImage(bag.read(m), path + ":" + topic + "#" + std::to_string(index));
        if (depth.header.sec == 0 && depth.header.nsec == 0) depth.header.sec = m.sec, depth.header.nsec = m.nsec;
        BagCloudInfo info;
        info.stamp = depth.header.stamp();
        info.frame_id = depth.header.frame_id;
        info.index = index;
        visit(depth, info);
        ++index;
    }
    return index;
}

}  // namespace projsurf
