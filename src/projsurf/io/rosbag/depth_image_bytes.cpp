#include "projsurf/io/rosbag/depth_image_bytes.hpp"

#include <algorithm>
#include <cstring>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace projsurf {

cv::Mat depthImageFromBytes(const std::string &source, const std::string &encoding, std::uint32_t width,
                            std::uint32_t height, std::uint32_t step, bool is_bigendian, const std::uint8_t *data,
                            std::size_t size) {
    const bool mm = encoding == "16UC1" || encoding == "mono16";
    const bool metres = encoding == "32FC1";
    if (!mm && !metres) throw InputError(source, "encoding '" + encoding + "' (expected 16UC1 in mm or 32FC1 in m)");
    if (width == 0 || height == 0) throw InputError(source, "the depth image is empty");
    if (static_cast<std::uint64_t>(width) * height > limits::kMaxImagePixels)
        throw InputError(source,
                         "the depth image exceeds the limit of " + std::to_string(limits::kMaxImagePixels) + " pixels");
    const std::size_t bpp = mm ? 2 : 4;
    if (step < static_cast<std::size_t>(width) * bpp || size < static_cast<std::size_t>(step) * height)
        throw InputError(source, "data is shorter than its size says");
    cv::Mat image(static_cast<int>(height), static_cast<int>(width), mm ? CV_16UC1 : CV_32FC1);
    for (std::uint32_t v = 0; v < height; ++v) {
        auto *row = image.ptr<std::uint8_t>(static_cast<int>(v));
        std::memcpy(row, data + static_cast<std::size_t>(v) * step, width * bpp);
        if (is_bigendian)
            for (std::uint32_t u = 0; u < width; ++u) std::reverse(row + u * bpp, row + (u + 1) * bpp);
    }
    return image;
}

}  // namespace projsurf
