#pragma once
// Continuous mode's question each frame (core/steady_tracker.hpp's held_usable): can the
// rectangle held from earlier frames still be shown from where the camera is now?
#include <Eigen/Core>

#include "projsurf/core/cloud.hpp"
#include "projsurf/core/depth_tolerance.hpp"
#include "projsurf/core/plane.hpp"
#include "projsurf/core/plane_frame.hpp"
#include "projsurf/core/projector.hpp"

namespace projsurf {

/// True when `rect` on `plane` (both in the camera frame of `cloud`, m) is still lit whole by
/// the projector (core/steady_tracker's fitsProjector) and nothing stands in front of it in
/// `cloud` now (core/surface_check on about 40000 of its points). `gravity`: down, camera frame.
/// `fit_margin_px`: every corner at least this far inside the framebuffer, px; `tolerance`
/// and `max_outlier_fraction`: the surface check's, as the detector's config has them.
bool heldRectangleUsable(const Projector &projector, const Rectangle &rect, const Plane &plane, const Cloud &cloud,
                         const Eigen::Vector3d &gravity, double fit_margin_px, const DepthTolerance &tolerance,
                         double max_outlier_fraction);

}  // namespace projsurf
