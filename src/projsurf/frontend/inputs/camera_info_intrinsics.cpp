#include "projsurf/frontend/inputs/camera_info_intrinsics.hpp"

#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

double rosDepthScale(const std::string &what, const std::string &encoding) {
    if (encoding == "16UC1" || encoding == "mono16") return kRosDepthMillimetres;
    if (encoding == "32FC1") return kRosDepthMetres;
    throw InputError(what, "encoding '" + encoding + "' (expected 16UC1 in mm or 32FC1 in m)");
}

CameraIntrinsics cameraInfoIntrinsics(const std::string &what, std::uint32_t width, std::uint32_t height,
                                      const std::array<double, 9> &K, const std::string &encoding) {
    return pinholeCamera(what, static_cast<int>(width), static_cast<int>(height), K[0], K[4], K[2], K[5],
                         rosDepthScale(what, encoding));
}

}  // namespace projsurf::frontend
