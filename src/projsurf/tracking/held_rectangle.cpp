#include "projsurf/tracking/held_rectangle.hpp"

#include <algorithm>

#include "projsurf/tracking/steady_tracker.hpp"
#include "projsurf/detection/surface_check.hpp"

namespace projsurf {

namespace {
constexpr std::size_t kCheckedPoints = 40000;  ///< points the check reads at most (every step-th), for speed
}  // namespace

bool heldRectangleUsable(const Projector &projector, const Rectangle &rect, const Plane &plane, const Cloud &cloud,
                         const Eigen::Vector3d &gravity, double fit_margin_px, const DepthTolerance &tolerance,
                         double max_outlier_fraction) {
    if (!fitsProjector(projector, rect, fit_margin_px)) return false;
    // Nothing may stand in front of it now: the default method's surface check on this cloud.
    const PlaneFrame frame = makePlaneFrame(plane, gravity, rect.center());
    const int step = std::max<int>(1, static_cast<int>(cloud.size() / kCheckedPoints));
    return checkSurface(cloud, frame, rect, tolerance, max_outlier_fraction, step).accepted;
}

}  // namespace projsurf
