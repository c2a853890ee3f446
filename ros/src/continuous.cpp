#include "continuous.hpp"

#include "projsurf/tracking/held_rectangle.hpp"
#include "projsurf/types/rigid_transform.hpp"

namespace projsurf::ros_node {

ContinuousMode::Output ContinuousMode::update(const Detection &det, const Cloud &cloud,
                                              const Eigen::Isometry3d &fixed_from_camera,
                                              const DetectorConfig &config) {
    const Eigen::Isometry3d camera_from_fixed = fixed_from_camera.inverse();
    SteadyMeasurement m;
    m.found = det.found;
    if (det.found) {
        m.plane = transformPlane(det.plane, fixed_from_camera);
        m.rectangle = transformRectangle(det.rectangle, fixed_from_camera);
    }
    if (tracker_.hasTarget()) {
        m.held_usable = heldRectangleUsable(params_.projector, transformRectangle(tracker_.target(), camera_from_fixed),
                                            transformPlane(tracker_.plane(), camera_from_fixed), cloud, det.gravity,
                                            params_.fit_margin_px, config.tolerance, config.check.max_outlier_fraction);
    }
    Output out;
    out.event = tracker_.update(m);
    out.has_target = tracker_.hasTarget();
    if (out.has_target) out.shown = transformRectangle(tracker_.target(), camera_from_fixed);
    return out;
}

}  // namespace projsurf::ros_node
