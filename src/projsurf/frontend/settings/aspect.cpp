#include "projsurf/frontend/settings/aspect.hpp"

#include <cmath>
#include <optional>

#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {
namespace {

/// The whole of `text` as a finite number.
std::optional<double> number(const std::string &text) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v)) return std::nullopt;
        return v;
    } catch (const std::exception &) {
        return std::nullopt;
    }
}

}  // namespace

double parseAspect(const std::string &what, const std::string &text) {
    double a = 0.0;
    const auto colon = text.find(':');
    if (colon == std::string::npos) {
        if (const auto v = number(text)) a = *v;
    } else {
        const auto w = number(text.substr(0, colon)), h = number(text.substr(colon + 1));
        if (w && h && *h != 0.0) a = *w / *h;
    }
    if (a >= kMinAspect && a <= kMaxAspect) return a;
    std::string hint;
    for (const char sep : {'x', 'X', '/', '*', ','})
        if (const auto at = text.find(sep); at != std::string::npos && colon == std::string::npos &&
                                            number(text.substr(0, at)) && number(text.substr(at + 1))) {
            hint = " (write " + text.substr(0, at) + ":" + text.substr(at + 1) + ")";
            break;
        }
    throw InputError(what, "expected a positive aspect ratio W:H, got '" + text + "'" + hint);
}

}  // namespace projsurf::frontend
