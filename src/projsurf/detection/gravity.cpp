#include "projsurf/detection/gravity.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "projsurf/types/plane.hpp"

namespace projsurf {

namespace {

struct Candidate {
    Eigen::Vector3f n;  // unit, along the prior (down)
    float d = 0.0f;     // n.p + d = 0; -d is the camera's height above the plane
    int score = 0;
};

std::vector<int> inliersOf(const std::vector<Point> &pts, const Eigen::Vector3f &n, float d, float band) {
    std::vector<int> in;
    for (int i = 0; i < static_cast<int>(pts.size()); ++i)
        if (std::abs(n.dot(pts[i]) + d) <= band) in.push_back(i);
    return in;
}

/// px: the half-baseline of a reading's normal, from its neighbours this far left/right and
/// up/down: 8 px span 9 cm at 3 m, several times a Kinect v1's depth noise there (1.3 cm).
constexpr int kNormalReach = 8;
/// rad (30 deg): how far a floor reading's normal may stray from the floor's own (noise, carpet).
constexpr double kNormalSlack = 0.52;

/// Whether a reading's normal (zero when unknown) lies within kNormalSlack of the plane normal n.
bool facesAlong(const Eigen::Vector3f &normal, const Eigen::Vector3f &n) {
    return std::abs(normal.dot(n)) >= static_cast<float>(std::cos(kNormalSlack));
}

/// The surface normal at reading i of an organized cloud, or zero when a neighbour is missing.
Eigen::Vector3f normalAt(const Cloud &cloud, std::size_t i) {
    const int w = cloud.width, r = static_cast<int>(i / w), c = static_cast<int>(i % w), k = kNormalReach;
    if (r < k || c < k || r + k >= cloud.height || c + k >= w) return Eigen::Vector3f::Zero();
    const std::size_t down = static_cast<std::size_t>(k) * w;
    const Point &left = cloud.points[i - k], &right = cloud.points[i + k], &above = cloud.points[i - down],
                &below = cloud.points[i + down];
    if (!isFinite(left) || !isFinite(right) || !isFinite(above) || !isFinite(below)) return Eigen::Vector3f::Zero();
    const Eigen::Vector3f n = (right - left).cross(below - above);
    const float norm = n.norm();
    return norm > 0.0f ? Eigen::Vector3f(n / norm) : Eigen::Vector3f::Zero();
}

/// About 6000 finite readings of the cloud, with the surface's normal at each where the cloud
/// is organized and the neighbours give one (else zero), and the readings to draw a floor's
/// three points from: of an organized cloud, those whose normal lies within `max_angle` +
/// kNormalSlack of `down` (a floor seen at 3 m holds a tenth of a frame, so three readings drawn
/// from all of them are all on it once in 700 draws), else all.
struct FloorSample {
    std::vector<Point> points;
    std::vector<Eigen::Vector3f> normals;
    std::vector<int> seeds;
};

FloorSample floorSample(const Cloud &cloud, const Eigen::Vector3f &down, double max_angle) {
    FloorSample out;
    const std::size_t step = std::max<std::size_t>(1, cloud.points.size() / 6000);
    const bool organized = cloud.organized();
    const float cos_max = static_cast<float>(std::cos(std::min(M_PI / 2, max_angle + kNormalSlack)));
    for (std::size_t i = 0; i < cloud.points.size(); i += step) {
        if (!isFinite(cloud.points[i])) continue;
        const Eigen::Vector3f n = organized ? normalAt(cloud, i) : Eigen::Vector3f::Zero();
        if (!organized || std::abs(n.dot(down)) >= cos_max) out.seeds.push_back(static_cast<int>(out.points.size()));
        out.points.push_back(cloud.points[i]);
        out.normals.push_back(n);
    }
    if (out.seeds.size() < 3) {
        out.seeds.resize(out.points.size());
        for (std::size_t i = 0; i < out.points.size(); ++i) out.seeds[i] = static_cast<int>(i);
    }
    return out;
}

/// Whether the readings within `band` of (n, d) face along n, as a floor's do: at least half of
/// those with a normal within kNormalSlack of it. A slanted plane that cuts through walls, a
/// person or a box holds stripes of their readings, which face sideways. True when no normal is
/// known (an unorganized cloud).
bool facesLikeAFloor(const FloorSample &sample, const Eigen::Vector3f &n, float d, float band) {
    int known = 0, along = 0;
    for (std::size_t i = 0; i < sample.points.size(); ++i) {
        if (sample.normals[i].isZero() || std::abs(n.dot(sample.points[i]) + d) > band) continue;
        ++known;
        along += facesAlong(sample.normals[i], n);
    }
    return known == 0 || 2 * along >= known;
}

/// The floor plane (n, d) refitted by least squares reweighted `rounds` times over the points
/// within `band` of it and nearer than `max_depth`: Tukey weights on the residual (scale: the
/// median absolute residual), each point also weighted by 1/z^2: far readings are noisier and
/// bent most by a structured-light sensor (their variance's 1/z^4 leaned on the few nearest
/// floor readings and did worse on the labelled frames).
void reweightedFloorFit(const std::vector<Point> &pts, float band, float max_depth, int rounds, Eigen::Vector3f &n,
                        float &d) {
    std::vector<float> residual;
    std::vector<int> near;
    for (int round = 0; round < rounds; ++round) {
        near.clear();
        residual.clear();
        for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
            const float r = n.dot(pts[i]) + d;
            if (std::abs(r) <= band && pts[i].z() < max_depth) {
                near.push_back(i);
                residual.push_back(std::abs(r));
            }
        }
        if (near.size() < 50) return;
        std::vector<float> sorted = residual;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double width = 4.685 * std::max(1.4826 * sorted[sorted.size() / 2], 0.003);
        double sw = 0.0;
        Eigen::Vector3d s = Eigen::Vector3d::Zero();
        Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
        for (std::size_t k = 0; k < near.size(); ++k) {
            const double t = residual[k] / width;
            if (t >= 1.0) continue;
            const Eigen::Vector3d p = pts[near[k]].cast<double>();
            const double z2 = std::max(0.25, p.z() * p.z());
            const double w = (1.0 - t * t) * (1.0 - t * t) / z2;
            sw += w;
            s += w * p;
            ss += w * p * p.transpose();
        }
        if (!(sw > 0.0)) return;
        const Eigen::Vector3d mean = s / sw;
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(ss / sw - mean * mean.transpose());
        Eigen::Vector3f next = solver.eigenvectors().col(0).cast<float>();
        if (next.dot(n) < 0) next = -next;
        n = next.normalized();
        d = -n.dot(mean.cast<float>());
    }
}

/// m: how far below a level plane a parallel one must lie to be another surface (a table top
/// is 0.4-1.1 m above the floor).
constexpr float kBelowTop = 0.3f;

/// A table or a counter top is level too, and may hold more readings than the floor below it:
/// the lowest plane parallel to `top` holding `min_score` readings within `band`, at least
/// kBelowTop below it, is the floor; `top` when there is none.
Candidate lowestParallelPlane(const FloorSample &sample, const Candidate &top, float band, int min_score) {
    // How far below the camera along top.n the readings that face along it lie (-d of a parallel
    // plane through them); a slice of a wall would hold many of any (an unorganized cloud's
    // readings have no normal: its top stands).
    std::vector<float> below;
    for (std::size_t i = 0; i < sample.points.size(); ++i)
        if (facesAlong(sample.normals[i], top.n)) below.push_back(top.n.dot(sample.points[i]));
    std::sort(below.begin(), below.end());
    Candidate out = top;
    // Windows of 2 band slid over the sorted heights, deepest first.
    std::size_t lo = below.size();
    for (std::size_t hi = below.size(); hi-- > 0;) {
        while (lo > 0 && below[lo - 1] >= below[hi] - 2.0f * band) --lo;
        const float centre = below[hi] - band;
        if (centre < -top.d + kBelowTop) break;
        if (static_cast<int>(hi - lo + 1) >= min_score) {
            out.d = -centre;
            break;
        }
    }
    return out;
}

}  // namespace

std::optional<GravityEstimate> estimateGravityFromFloor(const Cloud &cloud, const Eigen::Vector3d &prior,
                                                        double max_angle, double min_share, unsigned seed) {
    const Eigen::Vector3f g = prior.normalized().cast<float>();
    const FloorSample sample = floorSample(cloud, g, max_angle);
    const std::vector<Point> &pts = sample.points;
    if (pts.size() < 50) return std::nullopt;
    const float cos_max = static_cast<float>(std::cos(max_angle));
    const float band = 0.03f;  // m: floors are flat; Kinect noise at 1-3 m is below this
    const int min_score = static_cast<int>(std::ceil(min_share * pts.size()));
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pick(0, sample.seeds.size() - 1);
    // Every large plane in the cone below the camera.
    std::vector<Candidate> large;
    for (int it = 0; it < 300; ++it) {
        const Point &a = pts[sample.seeds[pick(rng)]], &b = pts[sample.seeds[pick(rng)]],
                    &c = pts[sample.seeds[pick(rng)]];
        Eigen::Vector3f n = (b - a).cross(c - a);
        if (n.norm() < 1e-6f) continue;
        n.normalize();
        if (n.dot(g) < 0) n = -n;  // along the prior: pointing down
        if (n.dot(g) < cos_max) continue;
        const float d = -n.dot(a);
        if (d >= 0.0f) continue;  // camera must be above it: n.0 + d < 0 means the plane is below
        int score = 0;
        for (const auto &p : pts) score += std::abs(n.dot(p) + d) <= band;
        if (score >= min_score && facesLikeAFloor(sample, n, d, band)) large.push_back({n, d, score});
    }
    if (large.empty()) return std::nullopt;
    // The biggest of them (the lowest of them would pick planes tilted through the far floor),
    // then the lowest plane parallel to it (a counter top is bigger than the floor at times).
    const Candidate &biggest =
        *std::max_element(large.begin(), large.end(), [](auto &x, auto &y) { return x.score < y.score; });
    const Candidate floor = lowestParallelPlane(sample, biggest, band, min_score);
    // Least squares on the floor's inliers, twice: the RANSAC normal from three points is only
    // a seed (a few degrees off on noisy depth); each refit re-selects the inliers within the band.
    Eigen::Vector3f n = floor.n;
    float d = floor.d;
    std::vector<int> inliers = inliersOf(pts, n, d, band);
    for (int round = 0; round < 3; ++round) {
        const auto refined = fitPlane(pts, inliers);
        if (!refined) break;
        Eigen::Vector3f rn = refined->normal.cast<float>();
        float rd = static_cast<float>(refined->d);
        if (rn.dot(n) < 0) {
            rn = -rn;
            rd = -rd;
        }
        // After the first fit (from the three-point seed), a refinement moves the normal by a
        // fraction of a degree; more is a jump onto the
        // surface beside the floor, so the last fit stands.
        if (round > 0 && rn.dot(n) < std::cos(2.0f * static_cast<float>(M_PI) / 180.0f)) break;
        std::vector<int> next = inliersOf(pts, rn, rd, band);
        if (static_cast<int>(next.size()) < min_score) break;
        n = rn;
        d = rd;
        inliers = std::move(next);
    }
    // The least-squares fit gives every reading the same say, the far ones too (noisier, bent).
    reweightedFloorFit(pts, band, 5.0f, 5, n, d);
    if (!facesLikeAFloor(sample, n, d, band)) return std::nullopt;  // the refits slid onto stripes
    inliers = inliersOf(pts, n, d, band);
    GravityEstimate out;
    out.gravity = n.cast<double>().normalized();
    out.floor_points = static_cast<int>(inliers.size());
    out.angle_to_prior = std::acos(std::min(1.0, out.gravity.dot(prior.normalized())));
    return out;
}

}  // namespace projsurf
