#include "projsurf/detection/paper/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "projsurf/types/clamp_to_int.hpp"

namespace projsurf {

std::vector<Point> voxelDownsample(const std::vector<Point> &points, double leaf) {
    std::vector<std::pair<std::uint64_t, int>> keyed;
    keyed.reserve(points.size());
    const float inv = static_cast<float>(1.0 / leaf);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        const Point &p = points[i];
        if (!isFinite(p)) continue;
        // 21 bits per axis around an offset: +-1 M voxels, i.e. +-50 km at 5 cm. The voxel
        // number is clamped to +-2^40 before converting (a far point must not overflow).
        auto k = [&](float v) {
            const std::int64_t cell =
                clampToInt64(std::floor(v * inv), -(std::int64_t{1} << 40), std::int64_t{1} << 40);
            return static_cast<std::uint64_t>(cell + (1 << 20)) & 0x1FFFFF;
        };
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
