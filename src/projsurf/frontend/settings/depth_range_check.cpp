#include "projsurf/frontend/settings/depth_range_check.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace projsurf::frontend {

std::optional<double> medianDepth(const Cloud &cloud) {
    std::vector<float> z;
    const std::size_t step = std::max<std::size_t>(1, cloud.points.size() / 20000);
    for (std::size_t i = 0; i < cloud.points.size(); i += step)
        if (isFinite(cloud.points[i])) z.push_back(cloud.points[i].z());
    if (z.size() < 100) return std::nullopt;
    std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
    return z[z.size() / 2];
}

std::optional<std::string> depthRangeWarning(const Cloud &cloud, const std::string &source, bool from_depth_image) {
    const auto median = medianDepth(cloud);
    if (!median || (*median >= kCloseUpDepth && *median <= kMaxSensorRange)) return std::nullopt;
    char buf[400];
    char close_up[120];
    std::snprintf(close_up, sizeof close_up,
                  "nearer than a projector robot works (under %.2f m: right only for a real close-up)", kCloseUpDepth);
    const char *side = *median < kMinSensorRange ? "nearer than an RGB-D camera's minimum range (about 0.4 m)"
                       : *median < kCloseUpDepth ? close_up
                                                 : "farther than an RGB-D camera reads (about 8 m)";
    if (from_depth_image) {
        std::snprintf(buf, sizeof buf, "%s: the median depth is %.2f m, %s; check its depth_scale (depth PNG units "
                      "per metre: 1000 for millimetres, 5000 for TUM, 10000 for 0.1 mm)",
                      source.c_str(), *median, side);
    } else if (*median > 100.0 && *median < 100000.0) {  // 0.1-100 m in millimetres
        std::snprintf(buf, sizeof buf, "%s: the median depth is %.0f m; the cloud looks like millimetres, and "
                      "projsurf reads metres (scale it by 0.001)",
                      source.c_str(), *median);
    } else {
        std::snprintf(buf, sizeof buf, "%s: the median depth is %.2f m, %s; projsurf reads clouds in metres",
                      source.c_str(), *median, side);
    }
    return std::string(buf);
}

}  // namespace projsurf::frontend
