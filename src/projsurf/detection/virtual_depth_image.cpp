#include "projsurf/detection/virtual_depth_image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace projsurf {
namespace {

constexpr double kNearZ = 0.05;  // m: nearer than any depth camera reads

/// The value at fraction q of `v` (reorders it).
float quantile(std::vector<float> &v, double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
}

}  // namespace

std::optional<VirtualDepthImage> virtualDepthImage(const Cloud &cloud, const VirtualImageConfig &config) {
    if (!config.enabled || cloud.organized()) return std::nullopt;
    // Normalised image coordinates (x/z, y/z) of the points in front of the camera.
    const float limit = static_cast<float>(std::tan(config.max_half_angle_deg * M_PI / 180.0));
    std::vector<float> us, vs;
    std::vector<int> kept;
    for (int i = 0; i < static_cast<int>(cloud.points.size()); ++i) {
        const Point &p = cloud.points[static_cast<std::size_t>(i)];
        if (!isFinite(p) || p.z() < kNearZ) continue;
        const float u = p.x() / p.z(), v = p.y() / p.z();
        if (std::abs(u) > limit || std::abs(v) > limit) continue;
        us.push_back(u);
        vs.push_back(v);
        kept.push_back(i);
    }
    if (static_cast<int>(kept.size()) < std::max(config.min_points, 1)) return std::nullopt;
    // The extent without the odd stray point (one far outlier must not spread the image thin).
    std::vector<float> su = us, sv = vs;
    const double u_lo = quantile(su, 0.001), u_hi = quantile(su, 0.999);
    const double v_lo = quantile(sv, 0.001), v_hi = quantile(sv, 0.999);
    const double span_u = std::max(u_hi - u_lo, 1e-3), span_v = std::max(v_hi - v_lo, 1e-3);
    const auto insideExtent = [&](std::size_t k) {
        return us[k] >= u_lo && us[k] <= u_hi && vs[k] >= v_lo && vs[k] <= v_hi;
    };

    // The covered share of that extent, on a coarse grid (about 16 points per cell).
    const double n = static_cast<double>(kept.size());
    const double coarse = std::sqrt(n / 16.0 / (span_u * span_v));  // cells per unit of x/z
    const int cw = std::clamp(static_cast<int>(std::ceil(span_u * coarse)), 1, 4096);
    const int ch = std::clamp(static_cast<int>(std::ceil(span_v * coarse)), 1, 4096);
    std::vector<char> occupied(static_cast<std::size_t>(cw) * ch, 0);
    for (std::size_t k = 0; k < kept.size(); ++k) {
        if (!insideExtent(k)) continue;  // a stray point beyond the extent would index before the grid
        const int cu = std::min(cw - 1, static_cast<int>((us[k] - u_lo) / span_u * cw));
        const int cv = std::min(ch - 1, static_cast<int>((vs[k] - v_lo) / span_v * ch));
        occupied[static_cast<std::size_t>(cv) * cw + cu] = 1;
    }
    const double covered =
        std::max(1.0, static_cast<double>(std::count(occupied.begin(), occupied.end(), 1))) / (cw * ch);

    // Focal length (px per unit of x/z) giving `fill` pixels per point over the covered part.
    double f = std::sqrt(n * config.fill / (covered * span_u * span_v));
    const double cap = static_cast<double>(std::max(config.max_pixels, 64));
    f = std::min(f, std::sqrt(cap / (span_u * span_v)));
    const int width = std::max(2, static_cast<int>(std::ceil(span_u * f)) + 1);
    const int height = std::max(2, static_cast<int>(std::ceil(span_v * f)) + 1);

    VirtualDepthImage out;
    Cloud &image = out.cloud;
    image.width = width;
    image.height = height;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    image.points.assign(static_cast<std::size_t>(width) * height, Point(nan, nan, nan));
    out.source.assign(image.points.size(), -1);
    for (std::size_t k = 0; k < kept.size(); ++k) {
        if (!insideExtent(k)) continue;
        const int c = std::clamp(static_cast<int>(std::lround((us[k] - u_lo) * f)), 0, width - 1);
        const int r = std::clamp(static_cast<int>(std::lround((vs[k] - v_lo) * f)), 0, height - 1);
        const std::size_t at = static_cast<std::size_t>(r) * width + c;
        const Point &p = cloud.points[static_cast<std::size_t>(kept[k])];
        if (!(image.points[at].z() <= p.z())) {  // nearest wins (NaN compares false)
            image.points[at] = p;
            out.source[at] = kept[k];
        }
    }
    return out;
}

}  // namespace projsurf
