#pragma once
// Continuous mode's question each frame (tracking/steady_tracker.hpp's held_usable): can the
// rectangle held from earlier frames still be shown from where the camera is now?
#include <Eigen/Core>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

/// True when `rect` on `plane` (both in the camera frame of `cloud`, m) is still lit whole by
/// the projector (tracking/steady_tracker's fitsProjector) and nothing stands in front of it in
/// `cloud` now (detection/surface_check on about 40000 of its points). `gravity`: down, camera frame.
/// `fit_margin_px`: every corner at least this far inside the framebuffer, px; `tolerance`
/// and `max_outlier_fraction`: the surface check's, as the detector's config has them.
bool heldRectangleUsable(const Projector &projector, const Rectangle &rect, const Plane &plane, const Cloud &cloud,
                         const Eigen::Vector3d &gravity, double fit_margin_px, const DepthTolerance &tolerance,
                         double max_outlier_fraction);

}  // namespace projsurf
