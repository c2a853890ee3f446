#include "projsurf/types/cloud.hpp"

#include <algorithm>

namespace projsurf {

std::size_t countFinite(const Cloud &cloud) {
    return static_cast<std::size_t>(
        std::count_if(cloud.points.begin(), cloud.points.end(), [](const Point &p) { return isFinite(p); }));
}

}  // namespace projsurf
