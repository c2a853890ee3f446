#include "projsurf/pipeline/detector.hpp"

namespace projsurf {

SurfaceDetector::SurfaceDetector(const Projector &projector, const DetectorConfig &config)
    : projector_(projector), config_(config) {}

Detection SurfaceDetector::detect(const Cloud &) {
    Detection d;
    d.reason = "not implemented";
    return d;
}

Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config) {
    return SurfaceDetector(projector, config).detect(cloud);
}

}  // namespace projsurf
