#pragma once
// Reflectances (BGR, 0-1) of the simulator's materials, shared by its scenes.
#include <opencv2/core.hpp>

namespace projsurf::sim::palette {

const cv::Vec3f kWallPaint{0.82f, 0.85f, 0.86f};
const cv::Vec3f kFloor{0.42f, 0.48f, 0.55f};
const cv::Vec3f kWood{0.25f, 0.42f, 0.58f};
const cv::Vec3f kCardboard{0.35f, 0.55f, 0.70f};
const cv::Vec3f kPoster{0.25f, 0.22f, 0.75f};

}  // namespace projsurf::sim::palette
