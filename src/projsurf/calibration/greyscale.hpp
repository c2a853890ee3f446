#pragma once
// One channel of brightness from a camera or framebuffer image, whatever its layout.
#include <opencv2/core.hpp>

namespace projsurf {

/// A single-channel image of the same size and depth: BGR and BGRA through OpenCV's luma
/// weights, a single channel as it is (shared, not copied).
cv::Mat greyscale(const cv::Mat &image);

}  // namespace projsurf
