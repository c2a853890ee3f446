#pragma once
// The pixels of a sensor_msgs/Image depth message (from the node or a bag) as an OpenCV image,
// without depending on ROS: 16UC1 / mono16 in millimetres (REP 118), 32FC1 in metres.
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace projsurf {

/// The image of the message's fields: CV_16UC1 (mm) or CV_32FC1 (m), in this machine's byte
/// order, copied. Throws InputError(source, problem) for another encoding, an empty image or
/// data shorter than height x step.
cv::Mat depthImageFromBytes(const std::string &source, const std::string &encoding, std::uint32_t width,
                            std::uint32_t height, std::uint32_t step, bool is_bigendian, const std::uint8_t *data,
                            std::size_t size);

}  // namespace projsurf
