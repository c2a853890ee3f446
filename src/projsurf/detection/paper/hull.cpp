#include "projsurf/detection/paper/hull.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

double cross(const Eigen::Vector2d &o, const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

std::uint64_t key(const cv::Point2f &p) {
    std::uint32_t x, y;
    std::memcpy(&x, &p.x, 4);
    std::memcpy(&y, &p.y, 4);
    return (static_cast<std::uint64_t>(x) << 32) | y;
}

/// Largest bounding-box side the concave hull works on, in the points' unit (metres): far
/// beyond any wall a projector can reach, well inside float and int range.
constexpr double kMaxConcaveExtent = 1e6;

}  // namespace

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> pts) {
    std::sort(pts.begin(), pts.end(),
              [](const auto &a, const auto &b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    std::vector<Eigen::Vector2d> hull(2 * pts.size());
    std::size_t k = 0;
    for (const auto &p : pts) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
        hull[k++] = p;
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

std::vector<Segment2> polygonEdges(const std::vector<Eigen::Vector2d> &polygon) {
    std::vector<Segment2> edges;
    for (std::size_t i = 0; i < polygon.size(); ++i) edges.push_back({polygon[i], polygon[(i + 1) % polygon.size()]});
    return edges;
}

std::vector<Segment2> concaveHullEdges(const std::vector<Eigen::Vector2d> &points, double alpha) {
    if (points.size() < 3) return {};
    Eigen::Vector2d lo = points[0], hi = points[0];
    for (const auto &p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    // Subdiv2D works in float, and in an int rectangle: beyond this extent (far or
    // non-finite points) there is no usable concave hull (and the casts would overflow).
    if (!((hi - lo).allFinite() && (hi - lo).maxCoeff() < kMaxConcaveExtent)) return {};
    // Subdiv2D works in float; shift to the bounding box so precision is kept.
    const cv::Rect2f box(0.0f, 0.0f, static_cast<float>(hi.x() - lo.x()) + 1.0f,
                         static_cast<float>(hi.y() - lo.y()) + 1.0f);
    cv::Subdiv2D subdiv(
        cv::Rect(0, 0, static_cast<int>(std::ceil(box.width)) + 1, static_cast<int>(std::ceil(box.height)) + 1));
    for (const auto &p : points)
        subdiv.insert(cv::Point2f(static_cast<float>(p.x() - lo.x()), static_cast<float>(p.y() - lo.y())));
    std::vector<cv::Vec6f> triangles;
    subdiv.getTriangleList(triangles);

    struct EdgeCount {
        cv::Point2f a, b;
        int count;
    };
    std::map<std::pair<std::uint64_t, std::uint64_t>, EdgeCount> edges;
    auto addEdge = [&](const cv::Point2f &a, const cv::Point2f &b) {
        std::uint64_t ka = key(a), kb = key(b);
        if (ka > kb) std::swap(ka, kb);
        const auto k = std::make_pair(ka, kb);
        auto it = edges.find(k);
        if (it == edges.end())
            edges.emplace(k, EdgeCount{a, b, 1});
        else
            ++it->second.count;
    };
    const double r_max = alpha;
    for (const auto &t : triangles) {
        const cv::Point2f p[3] = {{t[0], t[1]}, {t[2], t[3]}, {t[4], t[5]}};
        bool inside = true;
        for (const auto &q : p) inside &= q.x >= 0 && q.y >= 0 && q.x <= box.width && q.y <= box.height;
        if (!inside) continue;  // a triangle on Subdiv2D's virtual outer vertices
        const double a = cv::norm(p[1] - p[2]), b = cv::norm(p[0] - p[2]), c = cv::norm(p[0] - p[1]);
        const double area2 = std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
        if (area2 <= 1e-12) continue;
        const double circumradius = a * b * c / (2.0 * area2);
        if (circumradius > r_max) continue;
        addEdge(p[0], p[1]);
        addEdge(p[1], p[2]);
        addEdge(p[2], p[0]);
    }
    std::vector<Segment2> out;
    for (const auto &[k, e] : edges) {
        if (e.count != 1) continue;
        out.push_back(
            {Eigen::Vector2d(e.a.x + lo.x(), e.a.y + lo.y()), Eigen::Vector2d(e.b.x + lo.x(), e.b.y + lo.y())});
    }
    return out;
}

}  // namespace projsurf
