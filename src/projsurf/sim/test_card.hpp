#pragma once
// A picture to project in the demo, drawn procedurally so that nothing has to be downloaded:
// a test card whose distortions are easy to see (grid, circles, colour bars, text, corner marks).
#include <opencv2/core.hpp>

namespace projsurf::sim {

/// BGR test card of the given size (e.g. the projector's 1280 x 800).
cv::Mat testCard(cv::Size size);

}  // namespace projsurf::sim
