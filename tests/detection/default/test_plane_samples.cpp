// The written-out per-point passes of the wall's shape (detection/default/plane_samples) against
// the library forms they stand for: PlaneFrame::toPlane, Plane::signedDistance,
// WallShape::quadratic and DepthTolerance::band.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "projsurf/detection/default/plane_samples.hpp"

using namespace projsurf;

namespace {

struct WallPoints {
    std::vector<Point> points;
    std::vector<float> band;
    Plane plane;
    PlaneFrame frame;
    WallShape shape;
    DepthTolerance tolerance;
};

/// A wall 2.6 m away turned 20 deg, points scattered up to 12 cm off it, a bent quadratic.
WallPoints wallSetup() {
    WallPoints s;
    s.plane = makePlane(Eigen::Vector3d(0.34, -0.02, -0.94).normalized(), 2.6);
    s.frame = makePlaneFrame(s.plane, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0.1, 0.2, 2.7));
    s.shape.centre = Eigen::Vector2d(0.3, -0.2);
    s.shape.c << 0.004, -0.01, 0.02, 0.03, -0.015, 0.008;
    s.tolerance.noise_k = 2.1e-3;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> along(-1.5, 1.5), off(-0.12, 0.12);
    for (int i = 0; i < 1000; ++i) {
        const Eigen::Vector3d p =
            s.frame.origin + along(rng) * s.frame.right + along(rng) * s.frame.up + off(rng) * s.plane.normal;
        s.points.push_back(p.cast<float>());
        s.band.push_back(s.tolerance.band(s.points.back().z()));
    }
    return s;
}

}  // namespace

TEST(PlaneSamples, MatchTheLibrarysPlaneCoordinatesAndHeights) {
    const WallPoints s = wallSetup();
    std::vector<PlaneSample> out(s.points.size());
    planeSamples(s.points, s.band, s.plane, s.frame, out.data());
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const Eigen::Vector3d p = s.points[i].cast<double>();
        const Eigen::Vector2d uv = s.frame.toPlane(p);
        EXPECT_NEAR(out[i].uv.x(), uv.x(), 1e-12) << i;
        EXPECT_NEAR(out[i].uv.y(), uv.y(), 1e-12) << i;
        EXPECT_NEAR(out[i].h, s.plane.signedDistance(p), 1e-12) << i;
        EXPECT_EQ(out[i].band, s.band[i]) << i;
        EXPECT_EQ(out[i].z, p.z()) << i;
    }
}

TEST(PlaneSamples, OffQuadraticMatchesTheShapeAndTheBand) {
    const WallPoints s = wallSetup();
    std::vector<double> off(s.points.size());
    std::vector<float> band(s.points.size());
    offQuadratic(s.points, s.plane, s.frame, s.shape, s.tolerance, off.data(), band.data());
    int clamped = 0;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const Eigen::Vector3d p = s.points[i].cast<double>();
        const double reference = std::abs(s.plane.signedDistance(p) - s.shape.quadratic(s.frame.toPlane(p)));
        EXPECT_NEAR(off[i], reference, 1e-12) << i;
        EXPECT_EQ(band[i], s.tolerance.band(s.points[i].z())) << i;
        clamped += band[i] == static_cast<float>(s.tolerance.max_band);
    }
    EXPECT_GT(clamped, 0) << "the far points should reach the band's ceiling";
}
