#pragma once
// The corrected framebuffer the projector shows: keystone correction (core/keystone) of the
// picture into the rectangle, and a test card when the user gave no picture.
#include <opencv2/core.hpp>
#include <string>

#include "projsurf/core/plane_frame.hpp"
#include "projsurf/core/projector.hpp"

namespace projsurf::ros_node {

/// A picture that shows its own orientation and edges (border, grid, an "up" arrow), of the
/// given size, BGR.
cv::Mat testCard(cv::Size size);

struct Framebuffer {
    cv::Mat image;        ///< CV_8UC3 of the projector's resolution; empty when `problem` is set
    std::string problem;  ///< why the picture cannot be shown in the rectangle
};

/// `picture` (BGR) warped so that it appears whole, upright and undistorted (letterboxed) in
/// `rect` (camera frame) when the framebuffer is projected. A rectangle that leaves the
/// framebuffer by more than `tolerance_px` is refused; up to that, its edge is clipped.
Framebuffer renderFramebuffer(const Projector &projector, const Rectangle &rect, const cv::Mat &picture,
                              double tolerance_px);

}  // namespace projsurf::ros_node
