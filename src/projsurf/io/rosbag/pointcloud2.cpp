#include "projsurf/io/rosbag/pointcloud2.hpp"

#include <cstring>
#include <limits>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace projsurf {
namespace {

struct Accessor {
    std::uint32_t offset = 0;
    bool is_double = false;
};

Accessor findField(const PointCloud2View &msg, const std::string &name, const std::string &source) {
    for (const auto &f : msg.fields) {
        if (f.name != name) continue;
        if (f.datatype != kPointFieldFloat32 && f.datatype != kPointFieldFloat64)
            throw InputError(source, "PointCloud2 field '" + name + "' is not FLOAT32 or FLOAT64");
        const std::uint32_t bytes = f.datatype == kPointFieldFloat64 ? 8 : 4;
        if (static_cast<std::uint64_t>(f.offset) + bytes > msg.point_step)
            throw InputError(source, "PointCloud2 field '" + name + "' lies outside point_step");
        return {f.offset, f.datatype == kPointFieldFloat64};
    }
    throw InputError(source, "PointCloud2 has no field '" + name + "'");
}

float readValue(const std::uint8_t *p, const Accessor &a) {
    if (a.is_double) {
        double v;
        std::memcpy(&v, p + a.offset, sizeof v);
        return static_cast<float>(v);
    }
    float v;
    std::memcpy(&v, p + a.offset, sizeof v);
    return v;
}

bool hostIsBigEndian() {
    const std::uint16_t one = 1;
    std::uint8_t first;
    std::memcpy(&first, &one, 1);
    return first == 0;
}

}  // namespace

Cloud cloudFromPointCloud2(const PointCloud2View &msg, const std::string &source) {
    if (msg.is_bigendian != hostIsBigEndian())
        throw InputError(source, "PointCloud2 byte order differs from this machine's");
    if (msg.width == 0 || msg.height == 0) throw InputError(source, "PointCloud2 is empty");
    if (static_cast<std::uint64_t>(msg.width) * msg.height > limits::kMaxCloudPoints)
        throw InputError(source, "PointCloud2 of " + std::to_string(msg.width) + " x " + std::to_string(msg.height) +
                                     " points exceeds the limit of " + std::to_string(limits::kMaxCloudPoints) +
                                     " points");
    const Accessor ax = findField(msg, "x", source);
    const Accessor ay = findField(msg, "y", source);
    const Accessor az = findField(msg, "z", source);
    const std::uint64_t row_bytes = static_cast<std::uint64_t>(msg.width) * msg.point_step;
    if (msg.row_step < row_bytes) throw InputError(source, "PointCloud2 row_step is smaller than width * point_step");
    const std::uint64_t need = static_cast<std::uint64_t>(msg.row_step) * (msg.height - 1) + row_bytes;
    if (msg.data == nullptr || msg.data_size < need)
        throw InputError(source, "PointCloud2 data is shorter than its width, height and steps say");

    Cloud cloud;
    cloud.width = static_cast<int>(msg.width);
    cloud.height = static_cast<int>(msg.height);
    cloud.points.resize(static_cast<std::size_t>(msg.width) * msg.height);
    std::size_t k = 0;
    for (std::uint32_t r = 0; r < msg.height; ++r) {
        const std::uint8_t *row = msg.data + static_cast<std::size_t>(r) * msg.row_step;
        for (std::uint32_t c = 0; c < msg.width; ++c, ++k) {
            const std::uint8_t *p = row + static_cast<std::size_t>(c) * msg.point_step;
            cloud.points[k] = Point(readValue(p, ax), readValue(p, ay), readValue(p, az));
        }
    }
    if (msg.height == 1) cloud.width = static_cast<int>(cloud.points.size());
    return cloud;
}

}  // namespace projsurf
