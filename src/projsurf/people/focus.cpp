#include "projsurf/people/focus.hpp"

#include <algorithm>

namespace projsurf {

Focus focusFor(const Projector &projector, const Rectangle &rectangle) {
    const Eigen::Vector3d axis = projector.direction.normalized();
    const auto depth = [&](const Eigen::Vector3d &p) { return (p - projector.origin).dot(axis); };
    Focus f;
    f.distance_m = depth(rectangle.center());
    f.nearest_m = f.farthest_m = depth(rectangle.corners[0]);
    for (int i = 1; i < 4; ++i) {
        const double d = depth(rectangle.corners[i]);
        f.nearest_m = std::min(f.nearest_m, d);
        f.farthest_m = std::max(f.farthest_m, d);
    }
    return f;
}

}  // namespace projsurf
