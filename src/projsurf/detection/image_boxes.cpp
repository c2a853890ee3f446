#include "projsurf/detection/image_boxes.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {

cv::Rect pixelBox(const CameraIntrinsics &camera, const std::vector<Eigen::Vector3d> &points, int margin) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e6), hi = Eigen::Vector2d::Constant(-1e6);
    for (const Eigen::Vector3d &p : points) {
        if (!p.allFinite() || p.z() < 1e-3) return {};
        const Eigen::Vector2d px = camera.project(p);
        lo = lo.cwiseMin(px);
        hi = hi.cwiseMax(px);
    }
    lo = lo.cwiseMax(-1e6);
    hi = hi.cwiseMin(1e6);
    const cv::Rect pixels(
        cv::Point(static_cast<int>(std::floor(lo.x())) - margin, static_cast<int>(std::floor(lo.y())) - margin),
        cv::Point(static_cast<int>(std::ceil(hi.x())) + margin + 1, static_cast<int>(std::ceil(hi.y())) + margin + 1));
    return pixels & cv::Rect(0, 0, camera.width, camera.height);
}

cv::Rect beamImageBox(const CameraIntrinsics &camera, const PlaneFrame &frame, const RasterFrame &raster,
                      const Eigen::Vector3d &lens, double near, int margin) {
    const RasterFrame &r = raster;
    std::vector<Eigen::Vector3d> volume;
    for (const Eigen::Vector2d &corner :
         {r.toPlane({0, 0}), r.toPlane({r.cols, 0}), r.toPlane({r.cols, r.rows}), r.toPlane({0, r.rows})}) {
        const Eigen::Vector3d x = frame.toCamera(corner);
        // Where the beam towards this corner is at depth `near` (or the lens, if nearer).
        const double s = x.z() - lens.z() > 1e-9 ? std::clamp((near - lens.z()) / (x.z() - lens.z()), 0.0, 1.0) : 0.0;
        volume.push_back(x);
        volume.push_back(lens + s * (x - lens));
    }
    return pixelBox(camera, volume, margin);
}

cv::Rect indexImageBox(const Cloud &cloud, const std::vector<int> &indices, int margin) {
    if (!cloud.organized() || indices.empty()) return {};
    int u0 = cloud.width, v0 = cloud.height, u1 = -1, v1 = -1;
    for (int i : indices) {
        const int u = i % cloud.width, v = i / cloud.width;
        u0 = std::min(u0, u);
        v0 = std::min(v0, v);
        u1 = std::max(u1, u);
        v1 = std::max(v1, v);
    }
    return cv::Rect(u0 - margin, v0 - margin, u1 - u0 + 1 + 2 * margin, v1 - v0 + 1 + 2 * margin) &
           cv::Rect(0, 0, cloud.width, cloud.height);
}

}  // namespace projsurf
