#include "projsurf/frontend/minimum_size.hpp"

#include <cstdio>

namespace projsurf::frontend {

MinimumSize defaultMinimumSize(Method method) {
    if (method == Method::Paper) return MinimumSize{0.0, 0.0};
    return MinimumSize{};
}

bool enforceMinimumSize(Detection &det, const MinimumSize &minimum, const std::string &width_option,
                        const std::string &area_option) {
    if (!det.found) return false;
    const Rectangle &r = det.rectangle;
    char buf[320];
    if (r.width < minimum.width)
        std::snprintf(buf, sizeof buf, "the largest area, %.3f x %.3f m, is narrower than %s %.3f m", r.width, r.height,
                      width_option.c_str(), minimum.width);
    else if (r.area() < minimum.area)
        std::snprintf(buf, sizeof buf, "the largest area, %.3f x %.3f m (%.4f m^2), is smaller than %s %.4f m^2",
                      r.width, r.height, r.area(), area_option.c_str(), minimum.area);
    else
        return false;
    det.found = false;
    det.reason = buf;
    return true;
}

}  // namespace projsurf::frontend
