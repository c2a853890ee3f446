#pragma once
// Projection surface detection (paper section 3.2): from a cloud to the biggest upright
// rectangle of a given aspect ratio that the projector can light on a vertical surface.
#include <Eigen/Core>
#include <memory>

#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct DefaultScratch;

/// Detection with a fixed projector and configuration over a stream of frames, keeping the
/// largest working buffers (the point grid, the per-plane counts) from one frame to the next.
/// Gravity may change from frame to frame (a robot that tilts, --gravity auto).
class SurfaceDetector {
public:
    SurfaceDetector(const Projector &projector, const DetectorConfig &config);
    ~SurfaceDetector();
    SurfaceDetector(SurfaceDetector &&) noexcept;
    SurfaceDetector &operator=(SurfaceDetector &&) noexcept;

    /// `gravity`: down in the camera frame (the contract's default is a level camera, [0, 1, 0]).
    Detection detect(const Cloud &cloud, const Eigen::Vector3d &gravity = levelGravity());

    const DetectorConfig &config() const { return config_; }
    const Projector &projector() const { return projector_; }
    /// Picture width / height: the configured one, else the framebuffer's.
    double aspect() const;

    static Eigen::Vector3d levelGravity() { return Eigen::Vector3d::UnitY(); }

private:
    Projector projector_;
    DetectorConfig config_;
    std::unique_ptr<DefaultScratch> scratch_;
};

/// One-shot convenience.
Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                        const Eigen::Vector3d &gravity = SurfaceDetector::levelGravity());

}  // namespace projsurf
