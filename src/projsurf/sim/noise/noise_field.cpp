#include "projsurf/sim/noise/noise_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "projsurf/sim/noise/gaussian_table.hpp"

namespace projsurf::sim {

void normalizeField(cv::Mat &field) {
    cv::Scalar mean, sd;
    cv::meanStdDev(field, mean, sd);
    if (!(sd[0] > 1e-12)) return;
    field.convertTo(field, CV_32F, 1.0 / sd[0], -mean[0] / sd[0]);
}

cv::Mat smoothField(int width, int height, double cell_px, std::uint32_t seed) {
    std::seed_seq seq{seed};  // spreads nearby seeds over the whole generator state
    std::mt19937 rng(seq);
    NormalSource gauss(rng);
    // Grid nodes cover the image with one spare node each side so the cubic has support.
    const int gw = static_cast<int>(std::ceil(width / cell_px)) + 3,
              gh = static_cast<int>(std::ceil(height / cell_px)) + 3;
    cv::Mat grid(gh, gw, CV_32F);
    for (int r = 0; r < gh; ++r)
        for (int c = 0; c < gw; ++c) grid.at<float>(r, c) = gauss.next();
    cv::Mat field(height, width, CV_32F);
    // Catmull-Rom interpolation; pixel (u, v) sits at grid coordinate 1 + u / cell_px.
    auto weights = [](double t, double w[4]) {
        const double t2 = t * t, t3 = t2 * t;
        w[0] = 0.5 * (-t3 + 2 * t2 - t);
        w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
        w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
        w[3] = 0.5 * (t3 - t2);
    };
    std::vector<int> cx(width);
    std::vector<std::array<double, 4>> wx(width);
    for (int u = 0; u < width; ++u) {
        const double g = 1.0 + u / cell_px;
        cx[u] = static_cast<int>(std::floor(g));
        weights(g - cx[u], wx[u].data());
    }
    for (int v = 0; v < height; ++v) {
        const double g = 1.0 + v / cell_px;
        const int r0 = static_cast<int>(std::floor(g));
        double wy[4];
        weights(g - r0, wy);
        float *row = field.ptr<float>(v);
        for (int u = 0; u < width; ++u) {
            double sum = 0.0;
            for (int j = 0; j < 4; ++j) {
                const float *gr = grid.ptr<float>(std::clamp(r0 - 1 + j, 0, gh - 1));
                double s = 0.0;
                for (int i = 0; i < 4; ++i) s += wx[u][i] * gr[std::clamp(cx[u] - 1 + i, 0, gw - 1)];
                sum += wy[j] * s;
            }
            row[u] = static_cast<float>(sum);
        }
    }
    normalizeField(field);
    return field;
}

cv::Mat correlatedNoise(int width, int height, double sigma_px, std::mt19937 &rng) {
    NormalSource gauss(rng);
    cv::Mat field(height, width, CV_32F);
    for (int v = 0; v < height; ++v) {
        float *row = field.ptr<float>(v);
        for (int u = 0; u < width; ++u) row[u] = gauss.next();
    }
    if (sigma_px > 0.0) cv::GaussianBlur(field, field, cv::Size(0, 0), sigma_px, sigma_px, cv::BORDER_REFLECT);
    normalizeField(field);
    return field;
}

std::vector<float> columnBands(int width, double period_px, std::uint32_t seed) {
    const cv::Mat f = smoothField(width, 1, period_px, seed);
    return std::vector<float>(f.ptr<float>(0), f.ptr<float>(0) + width);
}

std::uint32_t unitSeed(const std::string &sensor, int unit, const std::string &purpose) {
    // FNV-1a over the three parts: stable across platforms and runs.
    std::uint32_t h = 2166136261u;
    auto mix = [&](const std::string &s) {
        for (unsigned char c : s) {
            h ^= c;
            h *= 16777619u;
        }
        h ^= 0xffu;
        h *= 16777619u;
    };
    mix(sensor);
    mix(std::to_string(unit));
    mix(purpose);
    return h;
}

}  // namespace projsurf::sim
