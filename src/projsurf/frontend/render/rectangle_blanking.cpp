#include "projsurf/frontend/render/rectangle_blanking.hpp"

#include "projsurf/people/beam_blanking.hpp"

namespace projsurf::frontend {

RectangleBlanking blankingBefore(const Projector &projector, const Rectangle &rect, const Cloud &cloud) {
    const auto &c = rect.corners;
    const Eigen::Vector3d normal = (c[1] - c[0]).cross(c[3] - c[0]).normalized();
    const Plane plane = makePlane(normal, -normal.dot(rect.center()));
    BeamBlanker blanker(projector);
    RectangleBlanking b;
    b.mask = blanker.compute(cloud, plane).clone();
    b.pixels = blanker.blankedPixels();
    return b;
}

}  // namespace projsurf::frontend
