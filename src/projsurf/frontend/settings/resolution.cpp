#include "projsurf/frontend/settings/resolution.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace projsurf::frontend {

cv::Size parseResolution(const std::string &what, const std::string &text, int min_side) {
    constexpr int kMaxSide = limits::kMaxFramebufferSide;
    std::stringstream ss(text);
    double w = 0, h = 0;
    char comma = 0;
    if (!(ss >> w >> comma >> h) || comma != ',' || !(ss >> std::ws).eof())
        throw InputError(what, "expected W,H (two numbers separated by a comma), got '" + text + "'");
    if (!(w >= min_side && h >= min_side && w <= kMaxSide && h <= kMaxSide) || w != std::floor(w) || h != std::floor(h))
        throw InputError(what, "must be two whole numbers between " + std::to_string(min_side) + " and " +
                                   std::to_string(kMaxSide) + ", got '" + text + "'");
    const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    if (pixels > limits::kMaxFramebufferPixels)
        throw InputError(what, text + " is " + std::to_string(pixels) + " pixels, beyond the framebuffer limit of " +
                                   std::to_string(limits::kMaxFramebufferPixels) +
                                   " (a calibration of that resolution could not be read)");
    return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace projsurf::frontend
