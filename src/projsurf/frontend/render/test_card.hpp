#pragma once
// The picture shown when the user gave none (the CLI's demo, the ROS node): drawn here, so
// nothing has to be downloaded, and made so that what goes wrong on the wall is easy to see.
#include <opencv2/core.hpp>

namespace projsurf::frontend {

/// BGR (CV_8UC3) card of `size` (e.g. the projector's 1280 x 800): a grid of squares and
/// circles (round and square only when the keystone is right), colour bars, the word projsurf
/// centred near the bottom (a picture upside down or mirrored is obvious) and a green border
/// (a picture cut off is obvious). Drawn for an 800 px tall card and scaled with the smaller side.
cv::Mat testCard(cv::Size size);

}  // namespace projsurf::frontend
