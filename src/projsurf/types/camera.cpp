#include "projsurf/types/camera.hpp"

#include <cmath>
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

std::optional<CameraIntrinsics> fitIntrinsics(const Cloud &cloud, const std::vector<int> &indices,
                                              double max_error_px) {
    if (!cloud.organized()) return std::nullopt;
    // pixel = f * ratio + c on each axis (ratio = x / z or y / z): two straight-line fits.
    struct Line {
        double n = 0, sr = 0, sp = 0, srr = 0, srp = 0, f = 0, c = 0;
        void add(double r, double p) {
            n += 1;
            sr += r;
            sp += p;
            srr += r * r;
            srp += r * p;
        }
        bool solve() {
            const double det = n * srr - sr * sr;
            if (!(std::abs(det) > 1e-12 * n * n)) return false;
            f = (n * srp - sr * sp) / det;
            c = (sp - f * sr) / n;
            return f > 0.0;
        }
    } u, v;
    auto usable = [&](int i) { return isFinite(cloud.points[i]) && cloud.points[i].z() > 0.0f; };
    for (int i : indices) {
        if (!usable(i)) continue;
        const Point &p = cloud.points[i];
        u.add(p.x() / p.z(), i % cloud.width);
        v.add(p.y() / p.z(), i / cloud.width);
    }
    if (u.n < 10 || !u.solve() || !v.solve()) return std::nullopt;
    for (int i : indices) {
        if (!usable(i)) continue;
        const Point &p = cloud.points[i];
        if (std::abs(u.f * p.x() / p.z() + u.c - i % cloud.width) > max_error_px ||
            std::abs(v.f * p.y() / p.z() + v.c - i / cloud.width) > max_error_px)
            return std::nullopt;
    }
    CameraIntrinsics k;
    k.width = cloud.width;
    k.height = cloud.height;
    k.fx = u.f;
    k.cx = u.c;
    k.fy = v.f;
    k.cy = v.c;
    return k;
}

}  // namespace projsurf
