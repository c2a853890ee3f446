// The picture on a wall larger than the projector's footprint: only the footprint bounds it,
// so it reaches the footprint's edge (the raster's edge there is not the wall's).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "projsurf/detector/detector.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf;

namespace {

/// How far p can move along d (unit) before it leaves the convex polygon `poly` (m).
double room(const std::array<Eigen::Vector2d, 4> &poly, const Eigen::Vector2d &p, const Eigen::Vector2d &d) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d a = poly[i], e = poly[(i + 1) % poly.size()] - a;
        const double det = e.x() * d.y() - e.y() * d.x();  // p + t d = a + s e
        if (std::abs(det) < 1e-12) continue;
        const Eigen::Vector2d q = a - p;
        const double t = (e.x() * q.y() - e.y() * q.x()) / det, s = (d.x() * q.y() - d.y() * q.x()) / det;
        if (t >= -1e-9 && s >= -1e-9 && s <= 1.0 + 1e-9) best = std::min(best, std::max(0.0, t));
    }
    return best;
}

}  // namespace

TEST(FootprintEdge, ThePictureReachesTheFootprintWhereTheWallGoesOn) {
    // A plain wall at 4 m, seen exactly: 5.4 m wide against a 2.9 m footprint. Before the
    // raster reached past the footprint, its border cells were trimmed as the wall's edge and
    // the picture stopped 5-10 mm short of the footprint (4.57 m^2 against 4.62).
    for (const double angle : {0.0, 10.0}) {
        const sim::Scenario sc = sim::makeScenario("wall", 4.0, angle);
        sim::SensorModel sensor;
        sensor.noise = false;
        const sim::RgbdFrame frame = sim::renderFrame(sc.scene, sensor, 1);
        const Detection det = detectSurface(frame.cloud, sim::exampleProjector(), DetectorConfig{}, sc.gravity);
        ASSERT_TRUE(det.found) << det.reason;
        ASSERT_TRUE(det.debug.has_workspace);
        std::array<Eigen::Vector2d, 4> footprint;
        for (std::size_t i = 0; i < 4; ++i) footprint[i] = det.debug.frame.toPlane(det.debug.workspace[i]);
        // Corners: top left, top right, bottom right, bottom left (makeRectangle's order). It
        // can grow no more when it is held on two opposite sides, top and bottom or left and right.
        std::array<Eigen::Vector2d, 4> c;
        for (std::size_t i = 0; i < 4; ++i) c[i] = det.debug.frame.toPlane(det.rectangle.corners[i]);
        const Eigen::Vector2d up(0, 1), right(1, 0);
        const double height_room = std::min(room(footprint, c[0], up), room(footprint, c[1], up)) +
                                   std::min(room(footprint, c[2], -up), room(footprint, c[3], -up));
        const double width_room = std::min(room(footprint, c[0], -right), room(footprint, c[3], -right)) +
                                  std::min(room(footprint, c[1], right), room(footprint, c[2], right));
        const double held = std::min(height_room, width_room);
        EXPECT_LT(held, 0.002) << "angle " << angle << ": " << det.rectangle.width << " x " << det.rectangle.height;
    }
}
