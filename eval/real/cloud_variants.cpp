#include "eval/real/cloud_variants.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace projsurf::eval {
namespace {

VariantRun compare(const Detection &variant, const Detection &organized) {
    VariantRun r;
    r.found = variant.found;
    r.area = variant.found ? variant.rectangle.width * variant.rectangle.height : 0.0;
    if (!variant.found || !organized.found) {
        r.agrees = !variant.found && !organized.found;
        return r;
    }
    const double cosine = std::abs(variant.plane.normal.normalized().dot(organized.plane.normal.normalized()));
    r.angle_deg = std::acos(std::min(1.0, cosine)) * 180.0 / M_PI;
    r.offset = std::abs(variant.plane.signedDistance(organized.rectangle.center()));
    const double area = organized.rectangle.width * organized.rectangle.height;
    r.agrees = r.angle_deg <= 1.0 && r.offset <= 0.02 && std::abs(r.area - area) <= 0.10 * area;
    return r;
}

}  // namespace

VariantRun unorganizedVariant(const Cloud &cloud, const Detection &organized, const Projector &projector,
                              const DetectorConfig &config, const Eigen::Vector3d &gravity) {
    Cloud loose;
    for (const auto &p : cloud.points)
        if (isFinite(p)) loose.points.push_back(p);
    std::mt19937 rng(11);
    std::shuffle(loose.points.begin(), loose.points.end(), rng);
    loose.width = static_cast<int>(loose.points.size());
    loose.height = 1;
    return compare(detectSurface(loose, projector, config, gravity), organized);
}

std::vector<VariantRun> shiftedVariants(const Cloud &cloud, const Detection &organized, const Projector &projector,
                                        const DetectorConfig &config, const Eigen::Vector3d &gravity) {
    std::vector<VariantRun> runs;
    if (!cloud.organized()) return runs;
    for (const auto &[du, dv] : {std::pair{1, 1}, std::pair{2, 0}, std::pair{0, 3}}) {
        Cloud crop;
        crop.width = cloud.width - du;
        crop.height = cloud.height - dv;
        for (int v = dv; v < cloud.height; ++v)
            for (int u = du; u < cloud.width; ++u)
                crop.points.push_back(cloud.points[static_cast<std::size_t>(v) * cloud.width + u]);
        runs.push_back(compare(detectSurface(crop, projector, config, gravity), organized));
    }
    return runs;
}

}  // namespace projsurf::eval
