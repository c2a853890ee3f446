// Geometry against independent formulas: ray-plane, Euler-Rodrigues vs Eigen, corner rays.
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "projsurf/calibration/euler_rodrigues.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

using namespace projsurf;

TEST(EulerRodrigues, MatchesEigenAngleAxis) {
    std::srand(3);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Vector3d v = Eigen::Vector3d::Random();
        const Eigen::Vector3d axis = Eigen::Vector3d::Random().normalized();
        const double angle = 3.0 * Eigen::Vector2d::Random().x();
        const Eigen::Vector3d expected = Eigen::AngleAxisd(angle, axis) * v;
        EXPECT_LT((eulerRodriguesRotate(v, axis, angle) - expected).norm(), 1e-12);
    }
}

TEST(PaperCornerRays, SymmetricAboutTheAxisAndAtHalfFov) {
    // The Appendix's R2 (the x axis carried by the first rotation) is perpendicular to the
    // rotated ray only when the axis has no x component, as in the paper's set-up (A.3).
    const double h = 39.3 * M_PI / 180.0, v = 24.0 * M_PI / 180.0;
    const Eigen::Vector3d axis = Eigen::Vector3d(0.0, -0.08, 1.0).normalized();
    const auto rays = paperCornerRays(axis, h, v);
    // All four corners make the same angle with the axis.
    const double a0 = std::acos(rays[0].dot(axis));
    for (const auto &r : rays) EXPECT_NEAR(std::acos(r.dot(axis)), a0, 1e-9);
    // Their mean lies on the axis.
    const Eigen::Vector3d mean = (rays[0] + rays[1] + rays[2] + rays[3]).normalized();
    EXPECT_LT((mean - axis).norm(), 1e-9);
    // Top corners are above (smaller y than) the bottom ones; left corners left of right ones.
    EXPECT_LT(rays[0].y(), rays[3].y());
    EXPECT_LT(rays[0].x(), rays[1].x());
    // The first rotation is exactly half the horizontal FOV.
    const double gamma = std::atan2(axis.y(), axis.z());
    const Eigen::Vector3d r1(0, std::cos(gamma), -std::sin(gamma));
    EXPECT_NEAR(r1.dot(axis), 0.0, 1e-12);
    EXPECT_NEAR(std::acos(eulerRodriguesRotate(axis, r1, h / 2).dot(axis)), h / 2, 1e-12);
}

TEST(Projector, CornerRaysSpanTheFieldOfView) {
    Projector p;
    p.direction = Eigen::Vector3d(0.1, -0.05, 1.0).normalized();
    const auto rays = p.cornerRays();
    const Eigen::Vector3d d = p.direction;
    for (const auto &r : rays) {
        const Eigen::Vector3d q = r / r.dot(d);  // on the plane at unit distance
        EXPECT_NEAR(std::abs(q.dot(p.right())), std::tan(p.fov_h / 2), 1e-12);
        EXPECT_NEAR(std::abs(q.dot(p.down())), std::tan(p.fov_v / 2), 1e-12);
    }
    // Round trip pixel -> ray -> pixel.
    const Eigen::Vector3d point = p.origin + 2.5 * p.ray({100.25, 700.5});
    const auto px = p.toPixel(point);
    ASSERT_TRUE(px.has_value());
    EXPECT_NEAR(px->x(), 100.25, 1e-9);
    EXPECT_NEAR(px->y(), 700.5, 1e-9);
    EXPECT_NEAR(p.right().dot(d), 0.0, 1e-12);
    EXPECT_NEAR(p.right().y(), 0.0, 1e-12);  // zero roll: right stays horizontal in the camera
}

TEST(Plane, RayIntersectionMatchesParametricForm) {
    const Plane wall = makePlane(Eigen::Vector3d(0.3, 0.0, -1.0), 2.0);
    EXPECT_GT(wall.d, 0.0);
    const Eigen::Vector3d o(0.0, 0.12, 0.0), dir = Eigen::Vector3d(0.2, -0.1, 1.0).normalized();
    const auto hit = intersectRay(wall, o, dir);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(wall.signedDistance(*hit), 0.0, 1e-12);
    EXPECT_LT(((*hit - o).normalized() - dir).norm(), 1e-12);
    EXPECT_FALSE(intersectRay(wall, o, -dir).has_value());  // behind the origin
}

TEST(PlaneFrame, UprightRightHandedFacingTheCamera) {
    const Plane wall = makePlane(Eigen::Vector3d(-0.4, 0.0, -1.0), 2.0);
    const PlaneFrame f = makePlaneFrame(wall, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 2));
    EXPECT_NEAR(f.up.dot(Eigen::Vector3d(0, -1, 0)), 1.0, 1e-12);
    EXPECT_NEAR(f.right.dot(f.normal), 0.0, 1e-12);
    EXPECT_GT(f.right.x(), 0.9);  // the viewer's right is the camera's right
    const Rectangle r = makeRectangle(f, {-0.5, -0.2}, {0.5, 0.4});
    EXPECT_NEAR(r.area(), 0.6, 1e-12);
    EXPECT_LT(r.corners[0].y(), r.corners[3].y());  // top-left is above bottom-left
    EXPECT_LT(r.corners[0].x(), r.corners[1].x());
}
