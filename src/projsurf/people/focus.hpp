#pragma once
// Where the projector must focus to show a rectangle sharp: distances along its optical axis.
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

/// Depths along the projector's optical axis (m), measured from the lens centre: a thin-lens
/// projector is sharp on the plane perpendicular to its axis at `distance_m`.
struct Focus {
    double distance_m = 0.0;  ///< to the rectangle's centre
    double nearest_m = 0.0;   ///< the nearest of the four corners
    double farthest_m = 0.0;  ///< the farthest of the four corners
};

/// Focus of a rectangle given in the camera frame (contract "Focus").
Focus focusFor(const Projector &projector, const Rectangle &rectangle);

}  // namespace projsurf
