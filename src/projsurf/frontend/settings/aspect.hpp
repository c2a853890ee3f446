#pragma once
// The picture's aspect ratio as a user writes it: "W:H" (16:9) or one number (1.777).
#include <string>

namespace projsurf::frontend {

/// The ratios a picture may have (width / height): from a tall strip to a wide one.
constexpr double kMinAspect = 0.01;
constexpr double kMaxAspect = 100.0;

/// "W:H" or one number -> W / H, within [kMinAspect, kMaxAspect]. Throws InputError(what, problem); a
/// ratio written with another separator ("16x9", "16/9") is told to be written W:H.
double parseAspect(const std::string &what, const std::string &text);

}  // namespace projsurf::frontend
