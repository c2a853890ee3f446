#include "projsurf/detection/planes/vertical_ransac.hpp"
#include "projsurf/types/target_clones.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {
namespace {

/// Points whose distance to the plane n.x + d = 0 is within their band (x, y, z, band as
/// separate arrays so that the loop vectorises; AVX2 where the CPU has it).
PROJSURF_CLONES
int countWithin(const float *x, const float *y, const float *z, const float *band, int n, float nx, float ny, float nz,
                float d) {
    int count = 0;
    for (int i = 0; i < n; ++i) count += std::abs(nx * x[i] + ny * y[i] + nz * z[i] + d) <= band[i];
    return count;
}

}  // namespace

std::vector<int> planeInliers(const std::vector<Point> &points, const std::vector<int> &active,
                              const std::vector<float> &band, const Plane &plane) {
    std::vector<int> out(active.size());
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float d = static_cast<float>(plane.d);
    std::size_t kept = 0;
    for (int i : active) {  // without a branch: inliers and outliers interleave unpredictably
        out[kept] = i;
        kept += std::abs(n.dot(points[i]) + d) <= band[i];
    }
    out.resize(kept);
    return out;
}

std::optional<PlaneInliers> findVerticalPlane(const std::vector<Point> &points, const std::vector<int> &active,
                                              const std::vector<float> &band, const Eigen::Vector3d &gravity,
                                              const RansacOptions &options, std::mt19937 &rng) {
    if (active.size() < 3) return std::nullopt;
    const Eigen::Vector3f g = gravity.normalized().cast<float>();
    const float max_sin_tilt = static_cast<float>(std::sin(options.max_tilt));

    // Hypotheses are scored on a fixed random subset (all points when small): the first
    // score_subset places of a Fisher-Yates shuffle, which need no more draws than that.
    std::vector<int> subset = active;
    if (options.score_subset > 0 && static_cast<int>(subset.size()) > options.score_subset) {
        for (std::size_t k = 0; k < static_cast<std::size_t>(options.score_subset); ++k)
            std::swap(subset[k], subset[std::uniform_int_distribution<std::size_t>(k, subset.size() - 1)(rng)]);
        subset.resize(options.score_subset);
    }
    const int m = static_cast<int>(subset.size());
    std::vector<float> sx(m), sy(m), sz(m), sb(m);
    for (int k = 0; k < m; ++k) {
        const Point &p = points[subset[k]];
        sx[k] = p.x();
        sy[k] = p.y();
        sz[k] = p.z();
        sb[k] = band[subset[k]];
    }
    std::uniform_int_distribution<std::size_t> pick(0, active.size() - 1);
    const float span2 = static_cast<float>(options.max_sample_span * options.max_sample_span);

    int best_score = 0;
    Eigen::Vector3f best_n = Eigen::Vector3f::Zero();
    float best_d = 0.0f;
    double needed = options.max_iterations;
    for (int it = 0; it < options.max_iterations && it < needed; ++it) {
        const Point &p1 = points[active[pick(rng)]];
        Point p2 = points[active[pick(rng)]], p3 = points[active[pick(rng)]];
        if (span2 > 0.0f) {
            for (int retry = 0; retry < 8 && (p2 - p1).squaredNorm() > span2; ++retry) p2 = points[active[pick(rng)]];
            for (int retry = 0; retry < 8 && (p3 - p1).squaredNorm() > span2; ++retry) p3 = points[active[pick(rng)]];
        }
        Eigen::Vector3f n = (p2 - p1).cross(p3 - p1);
        const float len = n.norm();
        if (!(len > 1e-6f)) continue;
        n /= len;
        if (std::abs(n.dot(g)) > max_sin_tilt) continue;  // not vertical
        const float d = -n.dot(p1);
        const int score = countWithin(sx.data(), sy.data(), sz.data(), sb.data(), m, n.x(), n.y(), n.z(), d);
        if (score > best_score) {
            best_score = score;
            best_n = n;
            best_d = d;
            const double w = static_cast<double>(score) / subset.size();
            const double p_good = w * w * w;
            if (p_good >= 1.0)
                needed = 0;
            else if (p_good > 0.0)
                needed = std::log(1.0 - options.probability) / std::log(1.0 - p_good);
        }
    }
    if (best_score < 3) return std::nullopt;
    PlaneInliers result;
    result.plane = makePlane(best_n.cast<double>(), best_d);
    result.inliers = planeInliers(points, active, band, result.plane);
    return result;
}

}  // namespace projsurf
