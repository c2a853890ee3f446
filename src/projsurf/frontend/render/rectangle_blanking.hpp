#pragma once
// What stands in the beam before a detected rectangle, blanked (contract "Blanking"): what
// `projsurf correct --cloud/--depth` and Python's correct(cloud=) do with a current cloud.
#include <opencv2/core.hpp>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::frontend {

struct RectangleBlanking {
    cv::Mat mask;    ///< CV_8U of the framebuffer's size, 255 = blanked
    int pixels = 0;  ///< how many are
};

/// The framebuffer pixels whose rays meet something in `cloud` between the lens and the plane
/// through `rect` (the surface the picture was placed on).
RectangleBlanking blankingBefore(const Projector &projector, const Rectangle &rect, const Cloud &cloud);

}  // namespace projsurf::frontend
