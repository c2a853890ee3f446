#include "projsurf/detection/colour/colour_registration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace projsurf {

std::string RegistrationResult::summary() const {
    char buf[200];
    if (!checked) {
        std::snprintf(buf, sizeof buf, "%d depth-edge pixels, edge score %.2f at best shift vs median %.2f",
                      edge_pixels, score_best, score_median);
    } else {
        std::snprintf(buf, sizeof buf,
                      "edge score %.2f at offset 0, %.2f times the median shift; best %.2f at %+d,%+d px", score_zero,
                      score_median > 0 ? score_zero / score_median : 0.0, score_best, best_dx, best_dy);
    }
    return buf;
}

RegistrationResult checkColourRegistration(const Cloud &cloud, const cv::Mat &bgr, const RegistrationOptions &opt) {
    RegistrationResult r;
    const int w = cloud.width, h = cloud.height;
    if (!cloud.organized() || bgr.empty() || bgr.cols != w || bgr.rows != h || bgr.type() != CV_8UC3) return r;
    // Depth edges: a jump of the depth across two pixels, horizontally or vertically, between
    // two readings (a missing reading is no edge: shadows of the IR projector lie beside
    // the true edges).
    const int m = opt.max_shift_px + 2;
    std::vector<int> edges;
    auto z = [&](int u, int v) { return cloud.points[static_cast<std::size_t>(v) * w + u].z(); };
    // A jump between a and b (two pixels apart) that is much steeper than the surface on
    // either side (aa..a, b..bb): a discontinuity, not a floor or wall seen at a grazing angle.
    const float steep = static_cast<float>(opt.jump_over_slope);
    auto jump = [&](float aa, float a, float b, float bb, float limit) {
        const float j = std::abs(b - a);
        return std::isfinite(a) && std::isfinite(b) && j > limit &&
               (!std::isfinite(aa) || j > steep * std::abs(a - aa)) &&
               (!std::isfinite(bb) || j > steep * std::abs(bb - b));
    };
    for (int v = m; v < h - m; ++v)
        for (int u = m; u < w - m; ++u) {
            const float c = z(u, v);
            if (!std::isfinite(c)) continue;
            const float limit =
                std::max(static_cast<float>(opt.depth_jump), static_cast<float>(opt.depth_jump_share) * c);
            if (jump(z(u - 3, v), z(u - 1, v), z(u + 1, v), z(u + 3, v), limit) ||
                jump(z(u, v - 3), z(u, v - 1), z(u, v + 1), z(u, v + 3), limit))
                edges.push_back(v * w + u);
        }
    r.edge_pixels = static_cast<int>(edges.size());
    if (r.edge_pixels < opt.min_edge_pixels) return r;
    if (static_cast<int>(edges.size()) > opt.max_samples) {
        std::vector<int> kept;
        const double step = static_cast<double>(edges.size()) / opt.max_samples;
        for (int i = 0; i < opt.max_samples; ++i) kept.push_back(edges[static_cast<std::size_t>(i * step)]);
        edges.swap(kept);
    }
    // Colour edges: gradient magnitude of the grey image, smoothed over 3 px so that a shift
    // of a pixel or two still scores.
    cv::Mat grey, gx, gy, mag;
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    cv::Sobel(grey, gx, CV_32F, 1, 0, 3);
    cv::Sobel(grey, gy, CV_32F, 0, 1, 3);
    cv::magnitude(gx, gy, mag);
    cv::blur(mag, mag, {3, 3});
    // Each edge against its neighbourhood (a textured floor or a poster must not win every
    // shift): the magnitude over its local mean.
    cv::Mat local;
    cv::blur(mag, local, {opt.local_window_px, opt.local_window_px});
    const double mean = cv::mean(mag)[0];
    if (!(mean > 1e-6)) return r;
    cv::Mat relative;
    cv::divide(mag, local + 0.25 * mean, relative);
    mag = relative;
    const float *g = mag.ptr<float>(0);
    const int n = 2 * opt.max_shift_px + 1;
    std::vector<double> scores(static_cast<std::size_t>(n) * n);
    for (int dy = -opt.max_shift_px; dy <= opt.max_shift_px; ++dy)
        for (int dx = -opt.max_shift_px; dx <= opt.max_shift_px; ++dx) {
            const int off = dy * w + dx;
            double sum = 0.0;
            for (int k : edges) sum += g[k + off];
            const double s = sum / static_cast<double>(edges.size());
            scores[static_cast<std::size_t>(dy + opt.max_shift_px) * n + dx + opt.max_shift_px] = s;
            if (s > r.score_best) {
                r.score_best = s;
                r.best_dx = dx;
                r.best_dy = dy;
            }
            if (dx == 0 && dy == 0) r.score_zero = s;
        }
    std::vector<double> sorted = scores;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    r.score_median = sorted[sorted.size() / 2];
    r.checked = r.score_best >= opt.min_prominence * r.score_median;
    r.registered = r.checked && r.score_zero >= opt.min_zero_over_median * r.score_median &&
                   r.score_zero >= opt.min_zero_over_best * r.score_best;
    return r;
}

bool attachColour(Cloud &cloud, const cv::Mat &bgr) {
    if (!cloud.organized() || bgr.empty() || bgr.cols != cloud.width || bgr.rows != cloud.height ||
        bgr.type() != CV_8UC3)
        return false;
    cloud.colours.resize(cloud.points.size());
    for (int v = 0; v < bgr.rows; ++v) {
        const auto *row = bgr.ptr<cv::Vec3b>(v);
        for (int u = 0; u < bgr.cols; ++u) {
            const cv::Vec3b &c = row[u];
            cloud.colours[static_cast<std::size_t>(v) * bgr.cols + u] = {c[0], c[1], c[2]};
        }
    }
    return true;
}

}  // namespace projsurf
