#include "projsurf/io/rosbag/rosbag_clouds.hpp"

#include <set>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/bag_records.hpp"
#include "projsurf/io/rosbag/pointcloud2.hpp"

namespace projsurf {

bool haveRosbagSupport() { return true; }

namespace {

constexpr const char *kCloudType = "sensor_msgs/PointCloud2";
constexpr const char *kCloudMd5 = "1158d486dd51d683ce2f1be655c3c181";

/// A serialized sensor_msgs/PointCloud2 (ROS 1, little-endian) read field by field; `data`
/// of the view points into `bytes`.
PointCloud2View parsePointCloud2(const std::string &bytes, const std::string &source, BagCloudInfo &info) {
    RosReader r(bytes, source);
    r.u32();  // header.seq
    const std::uint32_t sec = r.u32(), nsec = r.u32();
    info.frame_id = r.text("header.frame_id");
    if (sec != 0 || nsec != 0) info.stamp = sec + 1e-9 * nsec;
    PointCloud2View v;
    v.height = r.u32();
    v.width = r.u32();
    const std::uint32_t nfields = r.u32();
    if (nfields > r.remaining() / 13)
        throw InputError(source, "PointCloud2 announces more fields than the message holds");
    for (std::uint32_t i = 0; i < nfields; ++i) {
        PointField2 f;
        f.name = r.string();
        f.offset = r.u32();
        f.datatype = r.u8();
        f.count = r.u32();
        v.fields.push_back(f);
    }
    v.is_bigendian = r.u8() != 0;
    v.point_step = r.u32();
    v.row_step = r.u32();
    std::size_t length = 0;
    const std::size_t at = r.bytes(length);
    v.data = reinterpret_cast<const std::uint8_t *>(bytes.data()) + at;
    v.data_size = length;
    return v;
}

}  // namespace

std::size_t forEachBagCloud(const std::string &path, const std::string &topic,
                            const std::function<void(const Cloud &, const BagCloudInfo &)> &visit) {
    // Our own bounded reader: the rosbag library's parser trusts the lengths in the file.
    BagFile bag(path, topic);

    // Check the topic against what the bag holds before reading any message.
    std::set<std::string> cloud_topics;
    std::string topic_type, topic_md5;
    for (const BagConnection &c : bag.connections()) {
        if (c.type == kCloudType) cloud_topics.insert(c.topic);
        if (c.topic == topic) {
            topic_type = c.type;
            topic_md5 = c.md5sum;
        }
    }
    if (topic_type.empty()) {
        std::string have;
        for (const auto &t : cloud_topics) have += (have.empty() ? "" : ", ") + t;
        throw InputError(
            path, "no topic '" + topic + "' in the bag (PointCloud2 topics: " + (have.empty() ? "none" : have) + ")");
    }
    if (topic_type != kCloudType)
        throw InputError(path, "topic '" + topic + "' holds " + topic_type + ", not " + kCloudType);
    if (!topic_md5.empty() && topic_md5 != "*" && topic_md5 != kCloudMd5)
        throw InputError(path, "topic '" + topic + "' holds a sensor_msgs/PointCloud2 of another definition (md5sum " +
                                   topic_md5.substr(0, 32) + ")");

    std::size_t index = 0;
    for (const BagMessageRef &m : bag.messages()) {
        const std::string bytes = bag.read(m);
        const std::string source = path + ":" + topic + "#" + std::to_string(index);
        BagCloudInfo info;
        info.stamp = m.sec + 1e-9 * m.nsec;  // the receive time, unless the header has a stamp
        info.index = index;
        const PointCloud2View view = parsePointCloud2(bytes, source, info);
        const Cloud cloud = cloudFromPointCloud2(view, source);
        visit(cloud, info);
        ++index;
    }
    return index;
}

}  // namespace projsurf
