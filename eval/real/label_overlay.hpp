#pragma once
// A picture of a real frame's label, for a reader to check it: the usable surfaces (green),
// the obstacles (red), the projector's footprint on the best surface (yellow), the label's
// best rectangle (blue) and, when given, the detector's rectangle (magenta), drawn over the
// registered colour image or, without one, the colour-mapped depth. What the colour makes
// unsuitable (the label's colour section) is orange.
#include <opencv2/core.hpp>

#include "eval/real/real_labels.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf::eval {

/// Depth as a turbo colour map, 0.5 m blue to 5 m red, black where there is no reading.
cv::Mat depthColour(const Cloud &cloud);

/// `background`: BGR image of the depth image's size. `detected`: the detector's rectangle,
/// or nullptr. `tint`: opacity of the polygons' fill (0 = outlines only).
cv::Mat renderLabelOverlay(const cv::Mat &background, const RealLabel &label, const CameraIntrinsics &camera,
                           const Rectangle *detected, double tint = 0.35);

/// The colour-aware picture of a label judged on colour: the same, with the colour-aware best
/// (colour.best) in blue, the detector with colour in magenta and the depth-only answer (when
/// given) in white, and a legend.
cv::Mat renderColourLabelOverlay(const cv::Mat &background, const RealLabel &label, const CameraIntrinsics &camera,
                                 const Rectangle *with_colour, const Rectangle *depth_only, double tint = 0.35);

}  // namespace projsurf::eval
