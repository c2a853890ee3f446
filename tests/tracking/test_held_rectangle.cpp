// Continuous mode's geometry in the core: planes and rectangles carried between frames
// (types/rigid_transform.hpp), and whether the held rectangle can still be shown
// (tracking/held_rectangle.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "projsurf/types/camera.hpp"
#include "projsurf/tracking/held_rectangle.hpp"
#include "projsurf/types/rigid_transform.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;

namespace {

Eigen::Isometry3d somePose() {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, 0.3).normalized()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(1.0, -0.5, 2.0);
    return T;
}

/// A 640x480 camera's organized view of `wall` (no noise); `box` pixels [u0,u1)x[v0,v1) at 1 m instead.
Cloud viewOf(const Plane &wall, cv::Rect box = cv::Rect()) {
    CameraIntrinsics cam;
    cv::Mat depth(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const auto hit = intersectRay(wall, Eigen::Vector3d::Zero(), cam.backProject(u, v, 1.0));
            if (hit && hit->z() > 0)
                depth.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(hit->z() * 1000.0 + 0.5);
            if (box.contains({u, v})) depth.at<std::uint16_t>(v, u) = 1000;
        }
    return depthToCloud(depth, cam);
}

}  // namespace

TEST(RigidTransform, CarriesPointsOfThePlaneOntoTheCarriedPlane) {
    const Plane p = rig::wall(2.5, 20.0);
    const Eigen::Isometry3d T = somePose();
    const Plane q = transformPlane(p, T);
    EXPECT_NEAR(q.normal.norm(), 1.0, 1e-12);
    for (const Eigen::Vector3d &x : {p.project({0.3, 0.1, 2.0}), p.project({-1.0, 0.5, 3.0})})
        EXPECT_NEAR(q.normal.dot(T * x) + q.d, 0.0, 1e-12);
    // There and back is the identity.
    const Plane back = transformPlane(q, T.inverse());
    EXPECT_NEAR((back.normal - p.normal).norm(), 0.0, 1e-12);
    EXPECT_NEAR(back.d, p.d, 1e-12);
}

TEST(RigidTransform, CarriesCornersAndKeepsTheSize) {
    const Projector proj = rig::trueProjector();
    const Rectangle r = rig::rectangleInWorkspace(proj, rig::wall(2.0, 0.0));
    const Eigen::Isometry3d T = somePose();
    const Rectangle s = transformRectangle(r, T);
    EXPECT_EQ(s.width, r.width);
    EXPECT_EQ(s.height, r.height);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR((s.corners[i] - T * r.corners[i]).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s.corners[0] - s.corners[1]).norm(), r.width, 1e-9);
}

TEST(HeldRectangle, UsableOnAClearWallNotWhenBlockedOrOutOfTheProjector) {
    const Projector proj = rig::trueProjector();
    const Plane wall = rig::wall(2.0, 0.0);
    const Rectangle rect = rig::rectangleInWorkspace(proj, wall, 0.7);
    const Eigen::Vector3d down(0, 1, 0);
    const DepthTolerance tol;
    EXPECT_TRUE(heldRectangleUsable(proj, rect, wall, viewOf(wall), down, 2.0, tol, 0.03));
    // A box 1 m from the camera in front of the middle of the rectangle.
    EXPECT_FALSE(heldRectangleUsable(proj, rect, wall, viewOf(wall, cv::Rect(280, 200, 80, 80)), down, 2.0, tol, 0.03));
    // The robot turned: the rectangle is no longer in the framebuffer.
    Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
    turned.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix();
    EXPECT_FALSE(heldRectangleUsable(proj, transformRectangle(rect, turned), transformPlane(wall, turned), viewOf(wall),
                                     down, 2.0, tol, 0.03));
}
