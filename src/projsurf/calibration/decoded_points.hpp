#pragma once
// Structured light lifted to 3-D: each decoded camera pixel with a depth reading becomes a
// camera-frame point paired with the framebuffer pixel that lit it.
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/types/camera.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/projector_fit.hpp"

namespace projsurf {

/// `depth`: CV_16UC1 in camera.depth_scale units, registered to the decoded colour image (same
/// size, else std::invalid_argument). Pixels at depth edges (3x3 neighbourhood spanning more
/// than `edge_m` m) are left out: their depth mixes two surfaces.
std::vector<ProjectorCorrespondence> liftDecoding(const GrayDecoding &decoding, const cv::Mat &depth,
                                                  const CameraIntrinsics &camera, double edge_m = 0.02);
/// The same, appended to `out` (several poses into one list without a copy of each).
void liftDecoding(const GrayDecoding &decoding, const cv::Mat &depth, const CameraIntrinsics &camera,
                  std::vector<ProjectorCorrespondence> &out, double edge_m = 0.02);

}  // namespace projsurf
