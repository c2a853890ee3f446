#include "projsurf/detection/default/wall_relief.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

}  // namespace

WallRelief fitWallRelief(const std::vector<ReliefSample> &samples, double focal_px, const WallReliefOptions &opt) {
    WallRelief g;
    if (!opt.enabled || samples.size() < 200 || !(focal_px > 0.0) || opt.node_px <= 0.0 || opt.rounds < 1) return g;
    std::vector<double> depths;
    depths.reserve(samples.size());
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e30), hi = Eigen::Vector2d::Constant(-1e30);
    for (const ReliefSample &s : samples) {
        depths.push_back(s.z);
        lo = lo.cwiseMin(s.uv);
        hi = hi.cwiseMax(s.uv);
    }
    const double extent = (hi - lo).maxCoeff();
    const double spacing = std::max(opt.node_px * median(depths) / focal_px, extent / std::max(1, opt.max_nodes - 1));
    if (!(spacing > 1e-4) || !std::isfinite(extent)) return g;
    g.origin = lo;
    g.spacing = spacing;
    g.nu = std::max(2, static_cast<int>(std::ceil((hi.x() - lo.x()) / spacing)) + 1);
    g.nv = std::max(2, static_cast<int>(std::ceil((hi.y() - lo.y()) / spacing)) + 1);
    const double sigma = std::max(0.5, opt.sigma_px / opt.node_px);  // in nodes

    cv::Mat sums(g.nv, g.nu, CV_64FC2);  // per node: the weighted residuals, the weights
    std::vector<float> heights;
    for (int round = 0; round < opt.rounds; ++round) {
        sums.setTo(cv::Scalar::all(0.0));
        for (const ReliefSample &s : samples) {
            const WallRelief::Axis u = g.uAxis(s.uv.x()), v = g.vAxis(s.uv.y());
            const double t = (s.r - (g.empty() ? 0.0 : g.at(u, v))) / (opt.tukey_bands * s.band);
            if (!(std::abs(t) < 1.0)) continue;
            const double w = (1.0 - t * t) * (1.0 - t * t);
            const double wn[4] = {(1 - u.a) * (1 - v.a), u.a * (1 - v.a), (1 - u.a) * v.a, u.a * v.a};
            const int di[4] = {0, 1, 0, 1}, dj[4] = {0, 0, 1, 1};
            for (int k = 0; k < 4; ++k) {
                cv::Vec2d &node = sums.at<cv::Vec2d>(v.i + dj[k], u.i + di[k]);
                node[0] += wn[k] * w * s.r;
                node[1] += wn[k] * w;
            }
        }
        // Normalised convolution: zeros beyond the grid carry no weight. Both sums in one pass
        // (each channel filtered on its own, as two single-channel blurs would).
        cv::GaussianBlur(sums, sums, cv::Size(), sigma, sigma, cv::BORDER_CONSTANT);
        std::vector<double> weights;
        for (int j = 0; j < g.nv; ++j)
            for (int i = 0; i < g.nu; ++i)
                if (sums.at<cv::Vec2d>(j, i)[1] > 0.0) weights.push_back(sums.at<cv::Vec2d>(j, i)[1]);
        const double floor = opt.min_weight_share * median(weights);
        if (!(floor > 0.0)) return WallRelief{};
        heights.assign(static_cast<std::size_t>(g.nu) * g.nv, 0.0f);
        for (int j = 0; j < g.nv; ++j)
            for (int i = 0; i < g.nu; ++i)
                heights[static_cast<std::size_t>(j) * g.nu + i] =
                    static_cast<float>(sums.at<cv::Vec2d>(j, i)[0] / std::max(sums.at<cv::Vec2d>(j, i)[1], floor));
        g.h = heights;
    }
    return g;
}

}  // namespace projsurf
