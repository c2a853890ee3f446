#include "projsurf/detection/default/face_surround.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {
namespace {

enum class Beyond { Past, Front, On, Unseen };

/// The reading at the pixel of a point on the plane (or the nearest one within search_px).
const Point *readingAt(const Cloud &cloud, const CameraIntrinsics &camera, const Eigen::Vector3d &p, int search_px) {
    if (!(p.z() > 0.0)) return nullptr;
    const Eigen::Vector2d px = camera.project(p);
    if (!px.allFinite()) return nullptr;
    const long cx = std::lround(px.x()), cy = std::lround(px.y());
    if (cx < 0 || cy < 0 || cx >= cloud.width || cy >= cloud.height) return nullptr;
    for (int r = 0; r <= search_px; ++r)
        for (long y = cy - r; y <= cy + r; ++y)
            for (long x = cx - r; x <= cx + r; ++x) {
                if (std::max(std::abs(y - cy), std::abs(x - cx)) != r) continue;  // the ring at distance r
                if (x < 0 || y < 0 || x >= cloud.width || y >= cloud.height) continue;
                const Point &q = cloud.points[static_cast<std::size_t>(y) * cloud.width + x];
                if (isFinite(q)) return &q;
            }
    return nullptr;
}

/// Where the ray through the plane's point p ends, against the plane.
Beyond beyondAt(const Cloud &cloud, const CameraIntrinsics &camera, const Eigen::Vector3d &p,
                const DepthTolerance &tolerance, const FaceSurroundOptions &opt) {
    const Point *q = readingAt(cloud, camera, p, opt.search_px);
    if (!q) return Beyond::Unseen;
    // Along the same ray depth and range grow together: compare depths.
    const double step = q->z() - p.z();
    const double margin = std::max(opt.min_step, static_cast<double>(tolerance.margin(static_cast<float>(p.z()))));
    if (step > margin) return Beyond::Past;
    if (step < -margin) return Beyond::Front;
    return Beyond::On;
}

/// One position along an edge: the nearest decisive reading among the offsets outward.
void lookBeyond(const Cloud &cloud, const CameraIntrinsics &camera, const PlaneFrame &frame,
                const Eigen::Vector2d &edge, const Eigen::Vector2d &outward, const DepthTolerance &tolerance,
                const FaceSurroundOptions &opt, EdgeView &view) {
    bool on = false;
    for (double d : opt.offsets) {
        const Beyond b = beyondAt(cloud, camera, frame.toCamera(edge + d * outward), tolerance, opt);
        if (b == Beyond::Past) {
            ++view.past;
            return;
        }
        if (b == Beyond::Front) {
            ++view.front;
            return;
        }
        on = on || b == Beyond::On;
    }
    if (on)
        ++view.on;
    else
        ++view.unseen;
}

/// The longest stretch of sorted values with no gap over max_gap (the face, not stray points in line with it).
double longestRun(std::vector<double> v, double max_gap) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    double best = 0.0, start = v[0];
    for (std::size_t i = 1; i <= v.size(); ++i)
        if (i == v.size() || v[i] - v[i - 1] > max_gap) {
            best = std::max(best, v[i - 1] - start);
            if (i < v.size()) start = v[i];
        }
    return best;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

double quantile(std::vector<double> &v, double q) {
    const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}

}  // namespace

FaceSurround faceSurround(const Cloud &cloud, const CameraIntrinsics &camera, const PlaneFrame &frame,
                          const std::vector<int> &points, const DepthTolerance &tolerance,
                          const FaceSurroundOptions &opt) {
    FaceSurround out;
    if (!cloud.organized() || points.empty() || opt.bins < 1) return out;
    std::vector<Eigen::Vector2d> uv;
    uv.reserve(points.size());
    std::vector<double> us, vs;
    for (int i : points) {
        uv.push_back(frame.toPlane(cloud.points[i].cast<double>()));
        us.push_back(uv.back().x());
        vs.push_back(uv.back().y());
    }
    const double tail = 1.0 - opt.edge_quantile;
    const double u0 = quantile(us, tail), u1 = quantile(us, opt.edge_quantile);
    const double v0 = quantile(vs, tail), v1 = quantile(vs, opt.edge_quantile);
    if (!(u1 > u0 && v1 > v0)) return out;
    // The face's points binned by column (for its top) and by row (for its sides).
    const int n = opt.bins;
    std::vector<std::vector<double>> column(n), row(n);
    for (const Eigen::Vector2d &w : uv) {
        // Compared as doubles first: a far stray point must not overflow the conversion.
        const double c = std::floor((w.x() - u0) / (u1 - u0) * n), r = std::floor((w.y() - v0) / (v1 - v0) * n);
        if (c >= 0 && c < n) column[static_cast<int>(c)].push_back(w.y());
        if (r >= 0 && r < n) row[static_cast<int>(r)].push_back(w.x());
    }
    // The face's size: the median over columns (rows) of its longest unbroken stretch.
    std::vector<double> heights, widths;
    for (int k = 0; k < n; ++k) {
        if (static_cast<int>(column[k].size()) >= opt.min_bin_points)
            heights.push_back(longestRun(column[k], opt.max_gap));
        if (static_cast<int>(row[k].size()) >= opt.min_bin_points) widths.push_back(longestRun(row[k], opt.max_gap));
    }
    out.height = median(heights);
    out.width = median(widths);
    for (int k = 0; k < n; ++k) {
        const double u = u0 + (k + 0.5) / n * (u1 - u0);
        const double v = v0 + (k + 0.5) / n * (v1 - v0);
        if (static_cast<int>(column[k].size()) >= opt.min_bin_points) {
            const double top = quantile(column[k], opt.edge_quantile);
            lookBeyond(cloud, camera, frame, {u, top}, {0.0, 1.0}, tolerance, opt, out.top);
        }
        if (static_cast<int>(row[k].size()) >= opt.min_bin_points) {
            std::vector<double> &r = row[k];
            const double left = quantile(r, 1.0 - opt.edge_quantile), right = quantile(r, opt.edge_quantile);
            lookBeyond(cloud, camera, frame, {left, v}, {-1.0, 0.0}, tolerance, opt, out.left);
            lookBeyond(cloud, camera, frame, {right, v}, {1.0, 0.0}, tolerance, opt, out.right);
        }
    }
    return out;
}

namespace {

bool open(const EdgeView &e, const FreeStandingRule &rule) {
    return e.positions() > 0 && e.past + e.front >= rule.min_seen * e.positions() && e.pastShare() >= rule.min_past;
}

bool wallSized(const FaceSurround &s, const FreeStandingRule &rule) {
    return s.height >= rule.wall_height && s.width >= rule.wall_width;
}

/// The camera sees a surface in front of the face's plane beyond the edge (above it: a ceiling,
/// a soffit; beside it: a wall at a corner, a recess's side).
bool boundedInFront(const EdgeView &e, const FreeStandingRule &rule) {
    return e.positions() > 0 && e.past + e.front >= rule.min_seen * e.positions() &&
           e.pastShare() <= 1.0 - rule.min_past;
}

}  // namespace

bool standsFree(const FaceSurround &s, const FreeStandingRule &rule) {
    if (wallSized(s, rule)) return false;
    if (open(s.top, rule) && (open(s.left, rule) || open(s.right, rule))) return true;
    // Narrower than a wall, open on both sides, its top out of view (a person close by, a
    // door leaf, a pillar): it stands in the room, whatever is above it.
    return s.width < rule.wall_width && open(s.left, rule) && open(s.right, rule) && !boundedInFront(s.top, rule);
}

bool openAbove(const FaceSurround &s, const FreeStandingRule &rule) { return !wallSized(s, rule) && open(s.top, rule); }

bool enclosedInFront(const FaceSurround &s, const FreeStandingRule &rule) {
    return boundedInFront(s.top, rule) && boundedInFront(s.left, rule) && boundedInFront(s.right, rule);
}

}  // namespace projsurf
