#include "projsurf/tracking/continuous_tracker.hpp"

#include "projsurf/tracking/held_rectangle.hpp"
#include "projsurf/types/rigid_transform.hpp"

namespace projsurf {

namespace {

/// This frame's detection as the steady tracker takes it: in the fixed frame.
SteadyMeasurement measurementInFixedFrame(const Detection &det, const Eigen::Isometry3d &fixed_from_camera) {
    SteadyMeasurement m;
    m.found = det.found;
    if (det.found) {
        m.plane = transformPlane(det.plane, fixed_from_camera);
        m.rectangle = transformRectangle(det.rectangle, fixed_from_camera);
    }
    return m;
}

}  // namespace

ContinuousSettings continuousSettings(const Projector &projector, const DetectorConfig &detector) {
    ContinuousSettings settings;
    settings.projector = projector;
    settings.detector = detector;
    return settings;
}

ContinuousFrame ContinuousTracker::update(const Detection &det, const Cloud &cloud,
                                          const Eigen::Isometry3d &fixed_from_camera) {
    const Eigen::Isometry3d camera_from_fixed = fixed_from_camera.inverse();
    SteadyMeasurement m = measurementInFixedFrame(det, fixed_from_camera);
    if (tracker_.hasTarget()) {
        const DetectorConfig &config = settings_.detector;
        m.held_usable =
            heldRectangleUsable(settings_.projector, transformRectangle(tracker_.target(), camera_from_fixed),
                                transformPlane(tracker_.plane(), camera_from_fixed), cloud, det.gravity,
                                settings_.fit_margin_px, config.tolerance, config.check.max_outlier_fraction);
    }
    ContinuousFrame out;
    out.event = tracker_.update(m);
    out.has_target = tracker_.hasTarget();
    if (out.has_target) out.shown = transformRectangle(tracker_.target(), camera_from_fixed);
    return out;
}

}  // namespace projsurf
