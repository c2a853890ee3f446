#include "continuous.hpp"

#include <algorithm>

#include "projsurf/core/surface_check.hpp"

namespace projsurf::ros_node {

Plane transformPlane(const Plane &plane, const Eigen::Isometry3d &T) {
    // n.x + d = 0 with x = T^-1 y  ->  (R n).y + d - (R n).t = 0
    const Eigen::Vector3d n = T.linear() * plane.normal;
    Plane out;
    out.normal = n;
    out.d = plane.d - n.dot(T.translation());
    return out;
}

Rectangle transformRectangle(const Rectangle &rect, const Eigen::Isometry3d &T) {
    Rectangle out = rect;
    for (auto &c : out.corners) c = T * c;
    return out;
}

bool ContinuousMode::stillUsable(const Rectangle &rect, const Plane &plane, const Cloud &cloud,
                                 const DetectorConfig &config, const Eigen::Vector3d &gravity) const {
    if (!fitsProjector(params_.projector, rect, params_.fit_margin_px)) return false;
    // Nothing may stand in front of it now: the default mode's surface check on this cloud.
    const PlaneFrame frame = makePlaneFrame(plane, gravity, rect.center());
    const int step = std::max<int>(1, static_cast<int>(cloud.size() / 40000));
    const SurfaceCheckResult check =
        checkSurface(cloud, frame, rect, config.tolerance, config.check.max_outlier_fraction, step);
    return check.accepted;
}

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
        m.held_usable = stillUsable(transformRectangle(tracker_.target(), camera_from_fixed),
                                    transformPlane(tracker_.plane(), camera_from_fixed), cloud, config, det.gravity);
    }
    Output out;
    out.event = tracker_.update(m);
    out.has_target = tracker_.hasTarget();
    if (out.has_target) out.shown = transformRectangle(tracker_.target(), camera_from_fixed);
    return out;
}

}  // namespace projsurf::ros_node
