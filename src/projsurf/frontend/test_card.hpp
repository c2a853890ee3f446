#pragma once
// The picture shown when the user gave none: it shows its own orientation and edges.
#include <opencv2/core.hpp>

namespace projsurf::frontend {

/// BGR (CV_8UC3) card of `size`: border, grid, an "up" arrow, the word projsurf bottom left,
/// so a picture upside down, mirrored or cut off is obvious on the wall.
cv::Mat testCard(cv::Size size);

}  // namespace projsurf::frontend
