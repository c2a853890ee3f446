#include "projsurf/planning/floor_occupancy.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/planning/plan_raster.hpp"

namespace projsurf {

FloorOccupancy::FloorOccupancy(const Cloud &cloud, const Eigen::Vector3d &gravity, double reach,
                               double obstacle_height)
    : g_(gravity.normalized()), frame_(levelledFrame(gravity)) {
    half_ = floorGridHalf(reach, kCell);
    side_ = 2 * half_ + 1;
    count_.assign(static_cast<std::size_t>(side_) * side_, 0);
    std::vector<float> down;
    for (std::size_t i = 0; i < cloud.points.size(); i += 7)
        if (isFinite(cloud.points[i])) down.push_back(static_cast<float>(cloud.points[i].cast<double>().dot(g_)));
    if (down.empty()) return;
    const std::size_t k = static_cast<std::size_t>(0.99 * (down.size() - 1));
    std::nth_element(down.begin(), down.begin() + k, down.end());
    floor_ = down[k];
    floor_seen_ = true;
    for (const Point &pf : cloud.points) {
        if (!isFinite(pf)) continue;
        const Eigen::Vector3d p = pf.cast<double>();
        const double above = aboveFloor(p);
        if (above < obstacle_height || above > 2.0) continue;
        const int i = index(p);
        if (i >= 0) ++count_[i];
    }
}

int FloorOccupancy::index(const Eigen::Vector3d &p) const {
    const int x = cellIndex(p.dot(frame_.forward), kCell) + half_, y = cellIndex(p.dot(frame_.left), kCell) + half_;
    if (x < 0 || y < 0 || x >= side_ || y >= side_) return -1;
    return y * side_ + x;
}

bool FloorOccupancy::occupied(const Eigen::Vector3d &p, double radius) const {
    const int r = static_cast<int>(std::ceil(radius / kCell));
    const int cx = cellIndex(p.dot(frame_.forward), kCell) + half_, cy = cellIndex(p.dot(frame_.left), kCell) + half_;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            if ((dx * dx + dy * dy) * kCell * kCell > radius * radius) continue;
            const int x = cx + dx, y = cy + dy;
            if (x < 0 || y < 0 || x >= side_ || y >= side_) continue;
            if (count_[static_cast<std::size_t>(y) * side_ + x] >= 2) return true;
        }
    return false;
}

bool FloorOccupancy::pathBlocked(const Eigen::Vector3d &p, double radius) const {
    const Eigen::Vector3d flat = p - p.dot(g_) * g_;
    const int samples = std::max(1, static_cast<int>(std::ceil(flat.norm() / kCell)));
    for (int s = 1; s <= samples; ++s)
        if (occupied(flat * (double(s) / samples), radius)) return true;
    return false;
}

}  // namespace projsurf
