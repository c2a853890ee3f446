#include "projsurf/detection/planes/vertical_planes.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {

Eigen::Vector3d centroid(const std::vector<Point> &points, const std::vector<int> &indices) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int i : indices) s += points[i].cast<double>();
    return s / static_cast<double>(std::max<std::size_t>(1, indices.size()));
}

namespace {

/// Least-squares refits of `plane` on its inliers among `pool`, while it stays vertical.
Plane refine(const std::vector<Point> &points, const std::vector<float> &band, const std::vector<int> &pool,
             const Eigen::Vector3d &gravity, const VerticalPlaneOptions &options, Plane plane,
             std::vector<int> &inliers) {
    for (int round = 0; round < options.refine_rounds; ++round) {
        const auto refitted = fitPlane(points, inliers);
        if (!refitted || tiltFromVertical(*refitted, gravity) > options.ransac.max_tilt) break;
        plane = *refitted;
        inliers = planeInliers(points, pool, band, plane);
    }
    return plane;
}

}  // namespace

std::vector<PlaneInliers> findVerticalPlanes(const std::vector<Point> &points, const std::vector<float> &band,
                                             const Eigen::Vector3d &gravity, const DepthTolerance &tolerance,
                                             const VerticalPlaneOptions &options, std::mt19937 &rng) {
    std::vector<int> active(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) active[i] = static_cast<int>(i);
    std::vector<PlaneInliers> planes;
    std::vector<char> taken(points.size(), 0);
    for (int attempt = 0; attempt < 2 * options.max_planes && static_cast<int>(planes.size()) < options.max_planes &&
                          static_cast<int>(active.size()) >= options.min_points;
         ++attempt) {
        const auto found = findVerticalPlane(points, active, band, gravity, options.ransac, rng);
        if (!found || static_cast<int>(found->inliers.size()) < options.min_points) break;
        std::vector<int> inliers = found->inliers;
        const Plane plane = refine(points, band, active, gravity, options, found->plane, inliers);
        for (int i : inliers) taken[i] = 1;
        active.erase(std::remove_if(active.begin(), active.end(), [&](int i) { return taken[i]; }), active.end());
        const float z = static_cast<float>(centroid(points, inliers).z());
        // The last found plane it is a slice of, if any.
        auto slice_of = std::find_if(planes.rbegin(), planes.rend(), [&](const PlaneInliers &p) {
            return std::abs(p.plane.normal.dot(plane.normal)) > std::cos(options.merge_angle) &&
                   std::abs(p.plane.d - plane.d) < tolerance.margin(z);
        });
        if (slice_of == planes.rend()) {
            planes.push_back({plane, std::move(inliers)});
            continue;
        }
        slice_of->inliers.insert(slice_of->inliers.end(), inliers.begin(), inliers.end());
        const auto merged = fitPlane(points, slice_of->inliers);
        if (merged && tiltFromVertical(*merged, gravity) <= options.ransac.max_tilt) slice_of->plane = *merged;
    }
    return planes;
}

}  // namespace projsurf
