#pragma once
// ROS 1 wire format (little-endian) of the messages a depth camera publishes, for bags
// written and read without ROS: sensor_msgs/Image (a depth image) and sensor_msgs/CameraInfo.
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "projsurf/types/camera.hpp"

namespace projsurf {

/// std_msgs/Header.
struct RosHeader {
    std::uint32_t seq = 0;
    std::uint32_t sec = 0, nsec = 0;  ///< stamp
    std::string frame_id;
    double stamp() const { return sec + 1e-9 * nsec; }
};

/// What a depth camera_info says: the image size and the pinhole K (row-major 3x3, px).
struct CameraInfoMessage {
    RosHeader header;
    std::uint32_t width = 0, height = 0;
    std::array<double, 9> K{};
};

/// A depth image message: CV_16UC1 (mm) or CV_32FC1 (m), host byte order.
struct DepthImageMessage {
    RosHeader header;
    std::string encoding;  ///< as the message gives it: 16UC1 or mono16 (mm), 32FC1 (m)
    cv::Mat depth;
};

// Type names, md5sums and definitions, as a bag's connection header carries them.
extern const char *const kImageType;  ///< "sensor_msgs/Image"
extern const char *const kImageMd5;
extern const char *const kImageDefinition;
extern const char *const kCameraInfoType;  ///< "sensor_msgs/CameraInfo"
extern const char *const kCameraInfoMd5;
extern const char *const kCameraInfoDefinition;

/// A CV_16UC1 depth image (mm, 0 = no reading) as a 16UC1 sensor_msgs/Image.
std::string serializeDepthImage(const RosHeader &header, const cv::Mat &depth_mm);
/// The pinhole of `camera` (no distortion, "plumb_bob" with zero D, R = I, P = [K | 0]).
std::string serializeCameraInfo(const RosHeader &header, const CameraIntrinsics &camera);

/// Throws InputError(source, problem) for a message shorter than its fields or another encoding.
DepthImageMessage parseDepthImage(const std::string &bytes, const std::string &source);
CameraInfoMessage parseCameraInfo(const std::string &bytes, const std::string &source);

}  // namespace projsurf
