#include "projsurf/sim/noise/wall_residual_stats.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace projsurf::sim {
namespace {

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    const std::size_t k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * (v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}

}  // namespace

std::optional<WallResidualStats> wallResidualStats(const Cloud &cloud, cv::Rect region, const WallStatsOptions &o) {
    if (!cloud.organized()) return std::nullopt;
    region &= cv::Rect(0, 0, cloud.width, cloud.height);
    std::vector<int> all;
    for (int v = region.y; v < region.y + region.height; ++v)
        for (int u = region.x; u < region.x + region.width; ++u) {
            const int i = v * cloud.width + u;
            if (isFinite(cloud.points[i])) all.push_back(i);
        }
    if (static_cast<int>(all.size()) < o.min_points) return std::nullopt;
    auto fit = fitPlane(cloud.points, all);
    if (!fit) return std::nullopt;
    Plane plane = *fit;
    std::vector<int> in;
    double band = o.max_band;
    for (int it = 0; it < 6; ++it) {
        in.clear();
        for (int i : all)
            if (std::abs(plane.signedDistance(cloud.points[i].cast<double>())) <= band) in.push_back(i);
        if (static_cast<int>(in.size()) < o.min_points) return std::nullopt;
        const auto refit = fitPlane(cloud.points, in);
        if (!refit) return std::nullopt;
        plane = *refit;
        std::vector<double> dev;
        dev.reserve(in.size());
        for (int i : in) dev.push_back(std::abs(plane.signedDistance(cloud.points[i].cast<double>())));
        band = std::min(o.max_band, std::max(o.min_band, 3.0 * 1.4826 * percentile(dev, 0.5)));
    }
    // Final inliers and residual image.
    cv::Mat r(cloud.height, cloud.width, CV_64F, cv::Scalar(0)), m(cloud.height, cloud.width, CV_64F, cv::Scalar(0));
    in.clear();
    for (int i : all) {
        const double d = plane.signedDistance(cloud.points[i].cast<double>());
        if (std::abs(d) > band) continue;
        in.push_back(i);
        r.at<double>(i / cloud.width, i % cloud.width) = d;
        m.at<double>(i / cloud.width, i % cloud.width) = 1.0;
    }
    if (static_cast<int>(in.size()) < o.min_points) return std::nullopt;
    cv::Mat rs, ms;
    const cv::Size k(o.smooth_px, o.smooth_px);
    cv::boxFilter(r, rs, CV_64F, k, cv::Point(-1, -1), false, cv::BORDER_CONSTANT);
    cv::boxFilter(m, ms, CV_64F, k, cv::Point(-1, -1), false, cv::BORDER_CONSTANT);
    WallResidualStats s;
    s.points = static_cast<int>(in.size());
    s.plane = plane;
    s.distance = std::abs(plane.d);
    s.angle_deg = std::acos(std::min(1.0, std::abs(plane.normal.z()))) * 180.0 / 3.14159265358979323846;
    double sum2 = 0.0, local2 = 0.0;
    std::vector<double> smooth;
    smooth.reserve(in.size());
    for (int i : in) {
        const int v = i / cloud.width, u = i % cloud.width;
        const double d = r.at<double>(v, u);
        const double sm = rs.at<double>(v, u) / ms.at<double>(v, u);
        sum2 += d * d;
        local2 += (d - sm) * (d - sm);
        smooth.push_back(sm);
    }
    s.rms = std::sqrt(sum2 / s.points);
    s.local_rms = std::sqrt(local2 / s.points);
    s.low_p1 = percentile(smooth, 0.01);
    s.low_p99 = percentile(smooth, 0.99);
    return s;
}

}  // namespace projsurf::sim
