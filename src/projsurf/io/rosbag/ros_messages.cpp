#include "projsurf/io/rosbag/ros_messages.hpp"

#include <cstring>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/bag_records.hpp"
#include "projsurf/io/rosbag/depth_image_bytes.hpp"

namespace projsurf {

const char *const kImageType = "sensor_msgs/Image";
const char *const kImageMd5 = "060021388200f6f0f447d0fcd9c64743";
const char *const kCameraInfoType = "sensor_msgs/CameraInfo";
const char *const kCameraInfoMd5 = "c9a58c1b0b154e0e6da7578cb991d214";

// The fields of each message and of the messages it contains, in the form ROS tools read
// (main message, then each nested one after a line of 80 '=' and "MSG: <type>").
namespace {
#define PROJSURF_RULE "================================================================================\n"
#define PROJSURF_HEADER_MSG "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n"
}  // namespace
const char *const kImageDefinition =
    "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 is_bigendian\nuint32 step\n"
    "uint8[] data\n" PROJSURF_RULE PROJSURF_HEADER_MSG;
const char *const kCameraInfoDefinition =
    "std_msgs/Header header\nuint32 height\nuint32 width\nstring distortion_model\nfloat64[] D\nfloat64[9] K\n"
    "float64[9] R\nfloat64[12] P\nuint32 binning_x\nuint32 binning_y\nsensor_msgs/RegionOfInterest roi\n" PROJSURF_RULE
        PROJSURF_HEADER_MSG PROJSURF_RULE
    "MSG: sensor_msgs/RegionOfInterest\nuint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool "
    "do_rectify\n";
#undef PROJSURF_RULE
#undef PROJSURF_HEADER_MSG

namespace {

void putU32(std::string &s, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void putF64(std::string &s, double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    putU32(s, static_cast<std::uint32_t>(bits));
    putU32(s, static_cast<std::uint32_t>(bits >> 32));
}
void putString(std::string &s, const std::string &v) {
    putU32(s, static_cast<std::uint32_t>(v.size()));
    s += v;
}
void putHeader(std::string &s, const RosHeader &h) {
    putU32(s, h.seq);
    putU32(s, h.sec);
    putU32(s, h.nsec);
    putString(s, h.frame_id);
}

double f64(RosReader &r) {
    const std::uint64_t lo = r.u32(), hi = r.u32();
    const std::uint64_t bits = lo | hi << 32;
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
}
RosHeader header(RosReader &r) {
    RosHeader h;
    h.seq = r.u32();
    h.sec = r.u32();
    h.nsec = r.u32();
    h.frame_id = r.text("header.frame_id");
    return h;
}

}  // namespace

std::string serializeDepthImage(const RosHeader &h, const cv::Mat &depth_mm) {
    CV_Assert(depth_mm.type() == CV_16UC1);
    std::string m;
    putHeader(m, h);
    putU32(m, static_cast<std::uint32_t>(depth_mm.rows));
    putU32(m, static_cast<std::uint32_t>(depth_mm.cols));
    putString(m, "16UC1");
    m.push_back(0);  // little-endian
    const std::uint32_t step = static_cast<std::uint32_t>(depth_mm.cols) * 2;
    putU32(m, step);
    putU32(m, step * static_cast<std::uint32_t>(depth_mm.rows));
    for (int v = 0; v < depth_mm.rows; ++v) {
        const auto *row = depth_mm.ptr<std::uint16_t>(v);
        for (int u = 0; u < depth_mm.cols; ++u) {
            m.push_back(static_cast<char>(row[u] & 0xff));
            m.push_back(static_cast<char>(row[u] >> 8));
        }
    }
    return m;
}

std::string serializeCameraInfo(const RosHeader &h, const CameraIntrinsics &c) {
    std::string m;
    putHeader(m, h);
    putU32(m, static_cast<std::uint32_t>(c.height));
    putU32(m, static_cast<std::uint32_t>(c.width));
    putString(m, "plumb_bob");
    putU32(m, 5);
    for (int i = 0; i < 5; ++i) putF64(m, 0.0);                                       // D: rectified, no distortion
    for (double v : {c.fx, 0.0, c.cx, 0.0, c.fy, c.cy, 0.0, 0.0, 1.0}) putF64(m, v);  // K
    for (double v : {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) putF64(m, v);      // R
    for (double v : {c.fx, 0.0, c.cx, 0.0, 0.0, c.fy, c.cy, 0.0, 0.0, 0.0, 1.0, 0.0}) putF64(m, v);  // P
    putU32(m, 0);                                                                                    // binning_x
    putU32(m, 0);                                                                                    // binning_y
    for (int i = 0; i < 4; ++i) putU32(m, 0);  // roi: the whole image
    m.push_back(0);                            // roi.do_rectify
    return m;
}

DepthImageMessage parseDepthImage(const std::string &bytes, const std::string &source) {
    RosReader r(bytes, source);
    DepthImageMessage out;
    out.header = header(r);
    const std::uint32_t height = r.u32(), width = r.u32();
    out.encoding = r.string();
    const std::string &encoding = out.encoding;
    const bool big = r.u8() != 0;
    const std::uint32_t step = r.u32();
    std::size_t length = 0;
    const std::size_t at = r.bytes(length);
    out.depth = depthImageFromBytes(source, encoding, width, height, step, big,
                                    reinterpret_cast<const std::uint8_t *>(bytes.data()) + at, length);
    return out;
}

CameraInfoMessage parseCameraInfo(const std::string &bytes, const std::string &source) {
    RosReader r(bytes, source);
    CameraInfoMessage out;
    out.header = header(r);
    out.height = r.u32();
    out.width = r.u32();
    r.string();  // distortion_model
    const std::uint32_t nd = r.u32();
    if (nd > r.remaining() / 8) throw InputError(source, "CameraInfo announces more distortion terms than it holds");
    for (std::uint32_t i = 0; i < nd; ++i) f64(r);
    for (double &k : out.K) k = f64(r);
    return out;  // R, P, binning and roi are not needed
}

}  // namespace projsurf
