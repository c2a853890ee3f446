#include "cli/colour_input.hpp"

#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/io/files/files.hpp"

namespace projsurf::cli {

cv::Mat attachColourFile(Cloud &cloud, const std::string &path, const RegistrationOptions &options) {
    cv::Mat colour = readImage(path, cv::IMREAD_UNCHANGED);
    const frontend::ColourAttachment attached = frontend::attachRegisteredColour(cloud, colour, path, options);
    for (const std::string &w : attached.warnings) std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
    if (!attached.used) colour.release();
    return colour;
}

}  // namespace projsurf::cli
