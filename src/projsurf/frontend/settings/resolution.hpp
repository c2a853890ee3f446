#pragma once
// A framebuffer resolution as a user writes it: "W,H", two whole numbers of pixels.
#include <opencv2/core.hpp>
#include <string>

namespace projsurf::frontend {

/// "1280,800" -> 1280 x 800. Throws InputError(what, problem) unless both are whole numbers
/// between `min_side` and 16384 (px) and the framebuffer has at most
/// limits::kMaxFramebufferPixels pixels (what a calibration may say).
cv::Size parseResolution(const std::string &what, const std::string &text, int min_side = 2);

}  // namespace projsurf::frontend
