#include "projsurf/detector/detector.hpp"

#include <algorithm>

#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/detection/paper/paper_method.hpp"
#include "projsurf/detection/planes/virtual_depth_image.hpp"

namespace projsurf {
namespace {

/// Indices into the virtual image's pixels as indices into the cloud it was made from.
void toSourceIndices(std::vector<int> &indices, const std::vector<int> &source) {
    for (int &i : indices)
        i = i >= 0 && static_cast<std::size_t>(i) < source.size() ? source[static_cast<std::size_t>(i)] : -1;
    indices.erase(std::remove(indices.begin(), indices.end(), -1), indices.end());
}

}  // namespace

SurfaceDetector::SurfaceDetector(const Projector &projector, const DetectorConfig &config)
    : projector_(projector), config_(config), scratch_(std::make_unique<DefaultScratch>()) {}
SurfaceDetector::~SurfaceDetector() = default;
SurfaceDetector::SurfaceDetector(SurfaceDetector &&) noexcept = default;
SurfaceDetector &SurfaceDetector::operator=(SurfaceDetector &&) noexcept = default;

double SurfaceDetector::aspect() const { return config_.aspect > 0.0 ? config_.aspect : projector_.aspect(); }

Detection SurfaceDetector::detect(const Cloud &cloud, const Eigen::Vector3d &gravity) {
    const Eigen::Vector3d down = gravity.normalized();
    if (config_.method == Method::Paper) {
        Detection det = detectPaper(cloud, projector_, config_, down, aspect());
        det.gravity = down;
        return det;
    }
    // The default method reads depth images; an unorganized cloud becomes the one it was.
    const std::optional<VirtualDepthImage> image = virtualDepthImage(cloud, config_.unorganized);
    Detection det = detectDefault(image ? image->cloud : cloud, projector_, config_, down, aspect(), *scratch_);
    if (image) {
        toSourceIndices(det.debug.inliers, image->source);
        toSourceIndices(det.debug.outliers, image->source);
        toSourceIndices(det.surface_check.outlier_indices, image->source);
    }
    det.gravity = down;
    return det;
}

Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                        const Eigen::Vector3d &gravity) {
    return SurfaceDetector(projector, config).detect(cloud, gravity);
}

}  // namespace projsurf
