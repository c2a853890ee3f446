#include "projsurf/detection/surface_check.hpp"

#include <cmath>
#include <limits>

namespace projsurf {
namespace {

struct Box {
    Eigen::Vector2d lo, hi;
    bool contains(const Eigen::Vector2d &p) const {
        return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
    }
};

Box planeBox(const PlaneFrame &frame, const Rectangle &rect) {
    Box b{Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()),
          Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity())};
    for (const auto &c : rect.corners) {
        const Eigen::Vector2d uv = frame.toPlane(c);
        b.lo = b.lo.cwiseMin(uv);
        b.hi = b.hi.cwiseMax(uv);
    }
    return b;
}

}  // namespace

SurfaceCheckResult checkSurfaceAgainstMeanDepth(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                                double threshold, int max_outliers) {
    // Rotate so the rectangle is perpendicular to z (plane frame), keep the points inside
    // its limits, compare each z with the mean z (paper Fig. 10).
    const Box box = planeBox(frame, rect);
    std::vector<int> inside;
    std::vector<double> heights;
    double sum = 0.0;
    for (int i = 0; i < static_cast<int>(cloud.points.size()); ++i) {
        const Point &p = cloud.points[i];
        if (!isFinite(p)) continue;
        const Eigen::Vector3d q = p.cast<double>();
        if (!box.contains(frame.toPlane(q))) continue;
        inside.push_back(i);
        heights.push_back(frame.height(q));
        sum += heights.back();
    }
    SurfaceCheckResult r;
    r.points = static_cast<int>(inside.size());
    if (inside.empty()) return r;
    const double mean = sum / inside.size();
    for (std::size_t k = 0; k < inside.size(); ++k) {
        const double e = heights[k] - mean;
        if (e * e > threshold * threshold) r.outlier_indices.push_back(inside[k]);
    }
    r.outliers = static_cast<int>(r.outlier_indices.size());
    r.accepted = r.outliers <= max_outliers;
    return r;
}

SurfaceCheckResult checkSurface(const Cloud &cloud, const PlaneFrame &frame, const Rectangle &rect,
                                const DepthTolerance &tolerance, double max_fraction, int step, const cv::Rect &roi) {
    const Box box = planeBox(frame, rect);
    const Eigen::Vector3f n = frame.normal.cast<float>();
    const float d = static_cast<float>(-frame.normal.dot(frame.origin));
    const Eigen::Vector3f o = frame.origin.cast<float>(), right = frame.right.cast<float>(),
                          up = frame.up.cast<float>();
    SurfaceCheckResult r;
    auto visit = [&](int i) {
        const Point &p = cloud.points[i];
        if (!isFinite(p)) return;
        const float np = n.dot(p);
        if (std::abs(np) < 1e-6f) return;
        const float t = -d / np;  // camera ray through p meets the plane at t * p
        if (t <= 0.0f) return;
        const Eigen::Vector3f q = t * p - o;
        const Eigen::Vector2d uv(q.dot(right), q.dot(up));
        if (!box.contains(uv)) return;
        ++r.points;
        if (std::abs(np + d) > tolerance.margin(p.z())) r.outlier_indices.push_back(i);
    };
    const bool use_roi = cloud.organized() && roi.area() > 0;
    const cv::Rect area = use_roi ? (roi & cv::Rect(0, 0, cloud.width, cloud.height)) : cv::Rect();
    if (use_roi) {
        for (int v = area.y; v < area.y + area.height; v += step)
            for (int u = area.x; u < area.x + area.width; u += step) visit(v * cloud.width + u);
    } else if (cloud.organized()) {
        for (int v = 0; v < cloud.height; v += step)
            for (int u = 0; u < cloud.width; u += step) visit(v * cloud.width + u);
    } else {
        for (int i = 0; i < static_cast<int>(cloud.points.size()); i += step) visit(i);
    }
    r.outliers = static_cast<int>(r.outlier_indices.size());
    r.accepted = r.points > 0 && r.outliers <= max_fraction * r.points;
    return r;
}

}  // namespace projsurf
