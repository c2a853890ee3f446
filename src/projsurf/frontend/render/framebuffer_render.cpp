#include "projsurf/frontend/render/framebuffer_render.hpp"

#include <cmath>

namespace projsurf::frontend {

namespace {
/// Picture and rectangle aspect ratios differ by more than this share: some of the rectangle
/// stays dark. 0.5 %, about one pixel in 200.
constexpr double kLetterboxShare = 0.005;
}  // namespace

FramebufferRender keystoneFor(const Projector &projector, const Rectangle &rect, cv::Size picture,
                              double tolerance_px) {
    FramebufferRender out;
    if (!(tolerance_px >= 0.0 && tolerance_px <= 1e6)) {  // NaN too: the CLI and Python share this
        out.problem = "the keystone tolerance must be a finite number of pixels, 0 or more";
        out.tolerance_refused = true;
        return out;
    }
    KeystoneResult k = computeKeystone(projector, rect, picture, tolerance_px);
    if (!k.keystone) {
        out.problem = k.problem;
        return out;
    }
    out.keystone = std::move(k.keystone);
    const double rect_area = rect.width * rect.height,
                 shown_area = out.keystone->shown.width * out.keystone->shown.height;
    out.letterboxed = rect_area > 0.0 && shown_area < rect_area * (1.0 - kLetterboxShare);
    return out;
}

FramebufferRender renderFramebuffer(const Projector &projector, const Rectangle &rect, const cv::Mat &picture,
                                    double tolerance_px) {
    FramebufferRender out = keystoneFor(projector, rect, picture.size(), tolerance_px);
    if (out.keystone) out.image = warpToFramebuffer(picture, *out.keystone);
    return out;
}

}  // namespace projsurf::frontend
