#include "projsurf/detection/gravity.hpp"

#include <cmath>
#include <random>
#include <vector>

#include "projsurf/types/plane.hpp"

namespace projsurf {

std::optional<GravityEstimate> estimateGravityFromFloor(const Cloud &cloud, const Eigen::Vector3d &prior,
                                                        double max_angle, double min_share, unsigned seed) {
    std::vector<Point> pts;
    const std::size_t step = std::max<std::size_t>(1, cloud.points.size() / 6000);
    for (std::size_t i = 0; i < cloud.points.size(); i += step)
        if (isFinite(cloud.points[i])) pts.push_back(cloud.points[i]);
    if (pts.size() < 50) return std::nullopt;
    const Eigen::Vector3f g = prior.normalized().cast<float>();
    const float cos_max = static_cast<float>(std::cos(max_angle));
    const float band = 0.03f;  // m: floors are flat; Kinect noise at 1-3 m is below this
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
    int best = 0;
    Eigen::Vector3f best_n = g;
    float best_d = 0.0f;
    for (int it = 0; it < 300; ++it) {
        const Point &a = pts[pick(rng)], &b = pts[pick(rng)], &c = pts[pick(rng)];
        Eigen::Vector3f n = (b - a).cross(c - a);
        if (n.norm() < 1e-6f) continue;
        n.normalize();
        if (n.dot(g) < 0) n = -n;  // along the prior: pointing down
        if (n.dot(g) < cos_max) continue;
        const float d = -n.dot(a);
        if (d >= 0.0f) continue;  // camera must be above it: n.0 + d < 0 means the plane is below
        int score = 0;
        for (const auto &p : pts) score += std::abs(n.dot(p) + d) <= band;
        if (score > best) {
            best = score;
            best_n = n;
            best_d = d;
        }
    }
    if (best < min_share * pts.size()) return std::nullopt;
    std::vector<int> inliers;
    for (int i = 0; i < static_cast<int>(pts.size()); ++i)
        if (std::abs(best_n.dot(pts[i]) + best_d) <= band) inliers.push_back(i);
    Eigen::Vector3d n = best_n.cast<double>();
    if (const auto refined = fitPlane(pts, inliers))
        n = refined->normal.dot(n) < 0 ? -refined->normal : refined->normal;
    GravityEstimate out;
    out.gravity = n.normalized();
    out.floor_points = static_cast<int>(inliers.size());
    out.angle_to_prior = std::acos(std::min(1.0, out.gravity.dot(prior.normalized())));
    return out;
}

}  // namespace projsurf
