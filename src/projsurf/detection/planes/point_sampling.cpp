#include "projsurf/detection/planes/point_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {

std::vector<int> samplePoints(const Cloud &cloud, int target) {
    std::vector<int> out;
    target = std::max(1, target);
    out.reserve(static_cast<std::size_t>(target) * 5 / 4);
    const int n = static_cast<int>(cloud.points.size());
    if (cloud.organized()) {
        const int s = std::max(1, static_cast<int>(std::round(std::sqrt(static_cast<double>(n) / target))));
        for (int v = s / 2; v < cloud.height; v += s)
            for (int u = s / 2; u < cloud.width; u += s) {
                const int i = v * cloud.width + u;
                if (isFinite(cloud.points[i])) out.push_back(i);
            }
    } else {
        const int finite = static_cast<int>(countFinite(cloud));
        const int k = std::max(1, finite / target);
        int seen = 0;
        for (int i = 0; i < n; ++i)
            if (isFinite(cloud.points[i]) && seen++ % k == 0) out.push_back(i);
    }
    return out;
}

double sampleSpacing(const Cloud &cloud, const std::vector<int> &inliers, const Plane &plane, int step,
                     const DepthTolerance &tolerance, double spread_area, int support_points) {
    std::vector<float> d;
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float pd = static_cast<float>(plane.d);
    auto onPlane = [&](const Point &p) { return isFinite(p) && std::abs(n.dot(p) + pd) <= tolerance.band(p.z()); };
    if (cloud.organized()) {
        // Every 4th inlier is plenty for a median (and each one reads cloud memory at random).
        for (std::size_t k = 0; k < inliers.size(); k += 4) {
            const int i = inliers[k];
            const int u = i % cloud.width, v = i / cloud.width;
            if (u + step < cloud.width && onPlane(cloud.points[i + step]))
                d.push_back((cloud.points[i + step] - cloud.points[i]).norm());
            if (v + step < cloud.height && onPlane(cloud.points[i + step * cloud.width]))
                d.push_back((cloud.points[i + step * cloud.width] - cloud.points[i]).norm());
        }
    }
    if (d.size() < 10) return std::sqrt(std::max(0.0, spread_area) / std::max(1, support_points));
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
}

}  // namespace projsurf
