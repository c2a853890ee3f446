#include "projsurf/detection/planes/virtual_depth_image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "projsurf/detection/planes/pixel_lattice.hpp"

namespace projsurf {
namespace {

constexpr double kNearZ = 0.05;  // m: nearer than any depth camera reads

/// The value at fraction q of `v` (reorders it).
float quantile(std::vector<float> &v, double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
}

/// Where the normalised coordinates (x/z, y/z) fall: pixel (round((u - u0) fu), round((v - v0) fv)).
struct ImageLayout {
    double u0 = 0, v0 = 0;  ///< x/z and y/z at pixel (0, 0)
    double fu = 1, fv = 1;  ///< px per unit of x/z, y/z
    int width = 0, height = 0;
    double lo = 0, hi_u = 0, hi_v = 0;  ///< px, the extent kept: (u - u0) fu in [lo, hi_u], the same for v
    double off_pixel = 0.5;             ///< px, points further off a pixel centre are left out (strays off a lattice)
};

/// The pixel grid the cloud was taken on, when its points lie on one (a depth image's points,
/// shuffled, filtered or cropped): the image it came from, pixel for pixel. Nullopt when they lie
/// on none (another viewpoint, a voxel grid, merged scans).
std::optional<ImageLayout> latticeLayout(const std::vector<float> &us, const std::vector<float> &vs,
                                         const VirtualImageConfig &config) {
    const auto lu = pixelLattice(us, config.lattice), lv = pixelLattice(vs, config.lattice);
    if (!lu || !lv || static_cast<double>(lu->count) * lv->count > std::max(config.max_pixels, 64)) return std::nullopt;
    ImageLayout l;
    l.fu = 1.0 / lu->step;
    l.fv = 1.0 / lv->step;
    l.u0 = lu->origin;
    l.v0 = lv->origin;
    l.width = lu->count;
    l.height = lv->count;
    l.lo = -0.5;  // every lattice point is kept, none that lies off the lattice
    l.off_pixel = 0.25;
    l.hi_u = l.width - 0.5;
    l.hi_v = l.height - 0.5;
    return l;
}

/// A square-pixel grid over the points' extent (the outermost 0.1 % on each side left out: one
/// far outlier must not spread the image thin) at the cloud's own angular density.
ImageLayout densityLayout(const std::vector<float> &us, const std::vector<float> &vs,
                          const VirtualImageConfig &config) {
    std::vector<float> su = us, sv = vs;
    ImageLayout l;
    l.u0 = quantile(su, 0.001);
    l.v0 = quantile(sv, 0.001);
    const double u1 = quantile(su, 0.999), v1 = quantile(sv, 0.999);
    const double span_u = std::max(u1 - l.u0, 1e-3), span_v = std::max(v1 - l.v0, 1e-3);

    // The covered share of that extent, on a coarse grid (about 16 points per cell).
    const double n = static_cast<double>(us.size());
    const double coarse = std::sqrt(n / 16.0 / (span_u * span_v));  // cells per unit of x/z
    const int cw = std::clamp(static_cast<int>(std::ceil(span_u * coarse)), 1, 4096);
    const int ch = std::clamp(static_cast<int>(std::ceil(span_v * coarse)), 1, 4096);
    std::vector<char> occupied(static_cast<std::size_t>(cw) * ch, 0);
    for (std::size_t k = 0; k < us.size(); ++k) {
        const int cu = std::clamp(static_cast<int>((us[k] - l.u0) / span_u * cw), 0, cw - 1);
        const int cv = std::clamp(static_cast<int>((vs[k] - l.v0) / span_v * ch), 0, ch - 1);
        occupied[static_cast<std::size_t>(cv) * cw + cu] = 1;
    }
    const double covered =
        std::max(1.0, static_cast<double>(std::count(occupied.begin(), occupied.end(), 1))) / (cw * ch);

    // Focal length (px per unit of x/z) giving `fill` pixels per point over the covered part.
    double f = std::sqrt(n * config.fill / (covered * span_u * span_v));
    const double cap = static_cast<double>(std::max(config.max_pixels, 64));
    f = std::min(f, std::sqrt(cap / (span_u * span_v)));
    l.fu = l.fv = f;
    l.hi_u = (u1 - l.u0) * f;
    l.hi_v = (v1 - l.v0) * f;
    l.width = std::max(2, static_cast<int>(std::ceil(span_u * f)) + 1);
    l.height = std::max(2, static_cast<int>(std::ceil(span_v * f)) + 1);
    return l;
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
    const std::optional<ImageLayout> lattice = latticeLayout(us, vs, config);
    const ImageLayout l = lattice ? *lattice : densityLayout(us, vs, config);

    VirtualDepthImage out;
    Cloud &image = out.cloud;
    image.width = l.width;
    image.height = l.height;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    image.points.assign(static_cast<std::size_t>(l.width) * l.height, Point(nan, nan, nan));
    out.source.assign(image.points.size(), -1);
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const double x = (us[k] - l.u0) * l.fu, y = (vs[k] - l.v0) * l.fv;
        if (!(x >= l.lo && x <= l.hi_u && y >= l.lo && y <= l.hi_v)) continue;
        if (std::abs(x - std::round(x)) > l.off_pixel || std::abs(y - std::round(y)) > l.off_pixel) continue;
        const int c = std::clamp(static_cast<int>(std::lround(x)), 0, l.width - 1);
        const int r = std::clamp(static_cast<int>(std::lround(y)), 0, l.height - 1);
        const std::size_t at = static_cast<std::size_t>(r) * l.width + c;
        const Point &p = cloud.points[static_cast<std::size_t>(kept[k])];
        if (!(image.points[at].z() <= p.z())) {  // nearest wins (NaN compares false)
            image.points[at] = p;
            out.source[at] = kept[k];
        }
    }
    return out;
}

}  // namespace projsurf
