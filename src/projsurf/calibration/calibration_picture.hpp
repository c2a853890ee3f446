#pragma once
// The calibration picture of paper section 3.1.1, what the projector shows while the camera
// captures it for calibrateProjector (calibration.hpp): black, one white disc on the centre.
#include <opencv2/core.hpp>

namespace projsurf {

/// BGR (CV_8UC3), width x height px: black, one white disc of `radius_px` centred on the
/// framebuffer centre ((W-1)/2, (H-1)/2, the principal point). A radius <= 0 means H / 8.
cv::Mat calibrationPicture(int width, int height, double radius_px = 0.0);

}  // namespace projsurf
