#include "projsurf/frontend/inputs/registered_colour.hpp"

#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

ColourAttachment attachRegisteredColour(Cloud &cloud, const cv::Mat &bgr, const std::string &source,
                                        const RegistrationOptions &options) {
    return attachRegisteredColour(cloud, bgr, source, [&options](const Cloud &c, const cv::Mat &m) {
        return checkColourRegistration(c, m, options);
    });
}

ColourAttachment attachRegisteredColour(Cloud &cloud, const cv::Mat &bgr, const std::string &source,
                                        const RegistrationCheck &check) {
    if (bgr.depth() != CV_8U || bgr.channels() != 3) {
        const int bits = bgr.depth() == CV_8U ? 8 : bgr.depth() == CV_16U ? 16 : bgr.depth() == CV_32F ? 32 : 0;
        const std::string depth_png = bgr.depth() == CV_16U && bgr.channels() == 1 ? " (a depth PNG?)" : "";
        throw InputError(source, "expected 8-bit 3-channel colour (B, G, R), got " +
                                     (bits ? std::to_string(bits) : std::string("non-8")) + "-bit with " +
                                     std::to_string(bgr.channels()) + " channel" + (bgr.channels() == 1 ? "" : "s") +
                                     depth_png);
    }
    ColourAttachment out;
    if (!cloud.organized()) {
        out.warnings.push_back(source +
                               ": colour needs an organized cloud or a depth image to be registered to; not used");
        return out;
    }
    if (bgr.cols != cloud.width || bgr.rows != cloud.height)
        throw InputError(source, "colour image is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
                                     ", the cloud is " + std::to_string(cloud.width) + "x" +
                                     std::to_string(cloud.height));
    const RegistrationResult r = check(cloud, bgr);
    if (r.checked && !r.registered) {
        out.warnings.push_back(source + ": colour is not registered to the depth (" + r.summary() + "); not used");
        return out;
    }
    if (!r.checked)
        out.warnings.push_back(source + ": cannot check that the colour is registered to the depth (" + r.summary() +
                               "); used as given");
    out.used = attachColour(cloud, bgr);
    return out;
}

std::string suitabilityWithoutColourWarning(const std::string &what, const std::string &colour_option) {
    return what + " needs registered colour (" + colour_option + "); the surface is judged by depth only";
}

}  // namespace projsurf::frontend
