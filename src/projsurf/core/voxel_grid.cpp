#include "projsurf/core/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace projsurf {

std::vector<Point> voxelDownsample(const std::vector<Point> &points, double leaf) {
    std::vector<std::pair<std::uint64_t, int>> keyed;
    keyed.reserve(points.size());
    const float inv = static_cast<float>(1.0 / leaf);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        const Point &p = points[i];
        if (!isFinite(p)) continue;
        // 21 bits per axis around an offset: +-1 M voxels, i.e. +-50 km at 5 cm.
        auto k = [&](float v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inv)) + (1 << 20)) & 0x1FFFFF; };
        keyed.emplace_back((k(p.x()) << 42) | (k(p.y()) << 21) | k(p.z()), i);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<Point> out;
    for (std::size_t a = 0; a < keyed.size();) {
        std::size_t b = a;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        while (b < keyed.size() && keyed[b].first == keyed[a].first) sum += points[keyed[b++].second].cast<double>();
        out.push_back((sum / static_cast<double>(b - a)).cast<float>());
        a = b;
    }
    return out;
}

}  // namespace projsurf
