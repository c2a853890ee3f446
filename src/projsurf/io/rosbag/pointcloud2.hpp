#pragma once
// sensor_msgs/PointCloud2 -> Cloud without depending on ROS: the message's layout is
// described by plain values, so the ROS node and the bag reader share one tested parser.
#include <cstdint>
#include <string>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// One entry of PointCloud2.fields (datatype codes as in sensor_msgs/PointField).
struct PointField2 {
    std::string name;
    std::uint32_t offset = 0;
    std::uint8_t datatype = 0;  ///< 1 INT8 .. 7 FLOAT32, 8 FLOAT64
    std::uint32_t count = 1;
};

/// A view of a PointCloud2 message's layout and bytes (the bytes are not copied).
struct PointCloud2View {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<PointField2> fields;
    bool is_bigendian = false;
    std::uint32_t point_step = 0;
    std::uint32_t row_step = 0;
    const std::uint8_t *data = nullptr;
    std::size_t data_size = 0;
};

/// A view of any message with sensor_msgs/PointCloud2's members (the ROS message itself,
/// from the node or a bag), without depending on ROS here.
template <class Message>
PointCloud2View viewOfMessage(const Message &msg) {
    PointCloud2View v;
    v.width = msg.width;
    v.height = msg.height;
    v.is_bigendian = msg.is_bigendian != 0;
    v.point_step = msg.point_step;
    v.row_step = msg.row_step;
    v.data = msg.data.data();
    v.data_size = msg.data.size();
    v.fields.reserve(msg.fields.size());
    for (const auto &f : msg.fields) v.fields.push_back({f.name, f.offset, f.datatype, f.count});
    return v;
}

/// Reads x, y, z (FLOAT32 or FLOAT64) into a cloud; keeps the grid when height > 1, NaN
/// points included. Throws InputError(source, problem) when x/y/z are missing, of another
/// type, big-endian on this host, or the sizes do not add up.
Cloud cloudFromPointCloud2(const PointCloud2View &msg, const std::string &source);

/// The datatype codes of sensor_msgs/PointField.
constexpr std::uint8_t kPointFieldFloat32 = 7;
constexpr std::uint8_t kPointFieldFloat64 = 8;

}  // namespace projsurf
