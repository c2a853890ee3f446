#pragma once
// A minimal ROS 1 bag (format 2.0) writer for tests and fuzzing seeds: one chunk (stored
// uncompressed) holding the connection and the PointCloud2 messages, then the index section
// (the connection again). Enough for projsurf's bag reader; written without ROS.
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf::bagtest {

inline void putU32(std::string &s, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
inline void putU64(std::string &s, std::uint64_t v) {
    putU32(s, static_cast<std::uint32_t>(v));
    putU32(s, static_cast<std::uint32_t>(v >> 32));
}
inline void putString(std::string &s, const std::string &v) {
    putU32(s, static_cast<std::uint32_t>(v.size()));
    s += v;
}

using BagFields = std::vector<std::pair<std::string, std::string>>;

inline std::string bagFields(const BagFields &fields) {
    std::string h;
    for (const auto &[k, v] : fields) putString(h, k + "=" + v);
    return h;
}

inline std::string bagRecord(const BagFields &fields, const std::string &data) {
    std::string r;
    putString(r, bagFields(fields));
    putString(r, data);
    return r;
}

inline std::string u32Bytes(std::uint32_t v) {
    std::string s;
    putU32(s, v);
    return s;
}

/// A serialized sensor_msgs/PointCloud2 (x, y, z FLOAT32) of `cloud`.
inline std::string serializeCloud(const Cloud &cloud, std::uint32_t sec, const std::string &frame_id) {
    std::string m;
    putU32(m, 0);    // seq
    putU32(m, sec);  // stamp
    putU32(m, 0);
    putString(m, frame_id);
    const bool organized = cloud.organized();
    putU32(m, organized ? cloud.height : 1);
    putU32(m, organized ? cloud.width : static_cast<std::uint32_t>(cloud.size()));
    putU32(m, 3);
    const char *names[3] = {"x", "y", "z"};
    for (std::uint32_t i = 0; i < 3; ++i) {
        putString(m, names[i]);
        putU32(m, 4 * i);
        m.push_back(7);  // FLOAT32
        putU32(m, 1);
    }
    m.push_back(0);  // little-endian
    putU32(m, 12);
    putU32(m, 12 * (organized ? cloud.width : static_cast<std::uint32_t>(cloud.size())));
    putU32(m, static_cast<std::uint32_t>(12 * cloud.size()));
    for (const Point &p : cloud.points)
        for (int a = 0; a < 3; ++a) {
            std::uint32_t bits;
            std::memcpy(&bits, &p[a], 4);
            putU32(m, bits);
        }
    m.push_back(0);  // is_dense
    return m;
}

/// The bytes of a bag with `clouds` on `topic`, message k recorded at second 100 + k.
inline std::string bagWithClouds(const std::vector<Cloud> &clouds, const std::string &topic) {
    const std::string conn_header = bagFields({{"topic", topic},
                                               {"type", "sensor_msgs/PointCloud2"},
                                               {"md5sum", "1158d486dd51d683ce2f1be655c3c181"},
                                               {"message_definition", "(not needed)"}});
    const BagFields conn_fields = {{"op", "\x07"}, {"conn", u32Bytes(0)}, {"topic", topic}};
    std::string chunk = bagRecord(conn_fields, conn_header);
    for (std::size_t k = 0; k < clouds.size(); ++k) {
        std::string time;
        putU32(time, static_cast<std::uint32_t>(100 + k));
        putU32(time, 0);
        chunk += bagRecord({{"op", "\x02"}, {"conn", u32Bytes(0)}, {"time", time}},
                           serializeCloud(clouds[k], static_cast<std::uint32_t>(100 + k), "camera_optical"));
    }
    const std::string magic = "#ROSBAG V2.0\n";
    const std::string chunk_record = bagRecord(
        {{"op", "\x05"}, {"compression", "none"}, {"size", u32Bytes(static_cast<std::uint32_t>(chunk.size()))}}, chunk);
    // The bag header record is padded to 4096 bytes (as rosbag does); its index_pos is known
    // once its own size is.
    auto header = [&](std::uint64_t index_pos) {
        std::string ip;
        putU64(ip, index_pos);
        const BagFields f = {
            {"op", "\x03"}, {"index_pos", ip}, {"conn_count", u32Bytes(1)}, {"chunk_count", u32Bytes(1)}};
        const std::string fields = bagFields(f);
        return bagRecord(f, std::string(4096 - 8 - fields.size(), ' '));
    };
    const std::uint64_t index_pos = magic.size() + header(0).size() + chunk_record.size();
    return magic + header(index_pos) + chunk_record + bagRecord(conn_fields, conn_header);
}

}  // namespace projsurf::bagtest
