#pragma once
// The framebuffer a projector shows: a picture keystone-corrected (keystone/keystone) into a
// detected rectangle, letterboxed. What `projsurf correct`, the node and Python's correct() do.
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::frontend {

struct FramebufferRender {
    std::optional<Keystone> keystone;  ///< nullopt when the picture cannot be shown in the rectangle
    cv::Mat image;                   ///< of the projector's resolution and the picture's type; empty without a keystone
    std::string problem;             ///< why the picture cannot be shown (empty when it can)
    bool tolerance_refused = false;  ///< the problem is the tolerance given, not the rectangle
    /// The picture's aspect ratio differs from the rectangle's, so bars of the rectangle stay
    /// dark (letterbox or pillarbox).
    bool letterboxed = false;
};

/// `picture` warped so that it appears whole, upright and undistorted in `rect` (camera
/// frame, m) when the framebuffer is projected. A rectangle that leaves the framebuffer by
/// more than `tolerance_px` is refused; up to that, its edge is clipped.
FramebufferRender renderFramebuffer(const Projector &projector, const Rectangle &rect, const cv::Mat &picture,
                                    double tolerance_px);

/// The keystone only (for a stream of frames, warped by keystone/keystone_warper), same contract.
FramebufferRender keystoneFor(const Projector &projector, const Rectangle &rect, cv::Size picture, double tolerance_px);

}  // namespace projsurf::frontend
