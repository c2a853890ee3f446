#include "projsurf/detection/detector.hpp"

#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/detection/paper/paper_method.hpp"

namespace projsurf {

SurfaceDetector::SurfaceDetector(const Projector &projector, const DetectorConfig &config)
    : projector_(projector), config_(config), scratch_(std::make_unique<DefaultScratch>()) {}
SurfaceDetector::~SurfaceDetector() = default;
SurfaceDetector::SurfaceDetector(SurfaceDetector &&) noexcept = default;
SurfaceDetector &SurfaceDetector::operator=(SurfaceDetector &&) noexcept = default;

double SurfaceDetector::aspect() const { return config_.aspect > 0.0 ? config_.aspect : projector_.aspect(); }

Detection SurfaceDetector::detect(const Cloud &cloud, const Eigen::Vector3d &gravity) {
    const Eigen::Vector3d down = gravity.normalized();
    Detection det = config_.method == Method::Paper
                        ? detectPaper(cloud, projector_, config_, down, aspect())
                        : detectDefault(cloud, projector_, config_, down, aspect(), *scratch_);
    det.gravity = down;
    return det;
}

Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                        const Eigen::Vector3d &gravity) {
    return SurfaceDetector(projector, config).detect(cloud, gravity);
}

}  // namespace projsurf
