#include "projsurf/core/camera.hpp"

#include <limits>

namespace projsurf {

Cloud depthToCloud(const cv::Mat &depth, const CameraIntrinsics &camera) {
    Cloud cloud;
    cloud.width = depth.cols;
    cloud.height = depth.rows;
    cloud.points.resize(static_cast<std::size_t>(depth.cols) * depth.rows);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inv_fx = static_cast<float>(1.0 / camera.fx);
    const float inv_fy = static_cast<float>(1.0 / camera.fy);
    const float inv_scale = static_cast<float>(1.0 / camera.depth_scale);
    for (int v = 0; v < depth.rows; ++v) {
        const auto *row = depth.ptr<std::uint16_t>(v);
        Point *out = cloud.points.data() + static_cast<std::size_t>(v) * depth.cols;
        const float y_factor = (static_cast<float>(v) - static_cast<float>(camera.cy)) * inv_fy;
        for (int u = 0; u < depth.cols; ++u) {
            if (row[u] == 0) {
                out[u] = Point(nan, nan, nan);
                continue;
            }
            const float z = static_cast<float>(row[u]) * inv_scale;
            out[u] = Point((static_cast<float>(u) - static_cast<float>(camera.cx)) * inv_fx * z, y_factor * z, z);
        }
    }
    return cloud;
}

}  // namespace projsurf
