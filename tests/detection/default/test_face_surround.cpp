// Faces that stand free in the room (a box, a person) against walls (to the view's border, at a
// corner), on noise-free simulated depth images: what is seen beyond each edge, and the rule.
#include <gtest/gtest.h>

#include <string>

#include "projsurf/detection/default/face_surround.hpp"
#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf;

namespace {

struct Face {
    Cloud cloud;
    std::vector<int> points;  ///< the face's pixels
    PlaneFrame frame;
};

/// The scenario's exact depth image as an organized cloud, and the pixels of the quads labelled
/// `label` that lie on `plane` (within 5 mm).
Face renderFace(const sim::Scenario &sc, const CameraIntrinsics &camera, const std::string &label, const Plane &plane) {
    const sim::ExactDepth exact = sim::castExactDepth(sc.scene, camera);
    Face f;
    f.cloud.width = camera.width;
    f.cloud.height = camera.height;
    f.cloud.points.resize(static_cast<std::size_t>(camera.width) * camera.height, Point::Constant(NAN));
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int v = 0; v < camera.height; ++v)
        for (int u = 0; u < camera.width; ++u) {
            double z = 0.0;
            int quad = -1;
            sim::opaqueAt(exact, u, v, z, quad);
            if (quad < 0 || z <= 0.0) continue;
            const Eigen::Vector3d p = camera.backProject(u, v, z);
            const int i = v * camera.width + u;
            f.cloud.points[i] = p.cast<float>();
            if (sc.scene.quads[quad].label == label && std::abs(plane.signedDistance(p)) < 0.005) {
                f.points.push_back(i);
                sum += p;
            }
        }
    if (!f.points.empty()) f.frame = makePlaneFrame(plane, sc.gravity, sum / static_cast<double>(f.points.size()));
    return f;
}

FaceSurround surroundOf(const Face &f, const CameraIntrinsics &camera) {
    return faceSurround(f.cloud, camera, f.frame, f.points, DepthTolerance{});
}

}  // namespace

TEST(FaceSurround, BoxAgainstTheWallStandsFree) {
    // Its front 0.45 m before the wall: the wall is seen above it and beside it.
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("big_obstacle", 2.0, 0.0);
    const Plane front = makePlane(sc.wall.normal, sc.wall.d - 0.45);
    const Face f = renderFace(sc, camera, "box", front);
    ASSERT_GT(f.points.size(), 1000u);
    const FaceSurround s = surroundOf(f, camera);
    EXPECT_GE(s.top.pastShare(), 0.9);
    EXPECT_GT(s.top.seen(), 0);
    EXPECT_GE(std::max(s.left.pastShare(), s.right.pastShare()), 0.9);
    EXPECT_TRUE(standsFree(s));
}

TEST(FaceSurround, PersonBeforeTheWallStandsFree) {
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("person", 2.5, 0.0);
    // The body's front: the nearest person face, found from the depth.
    const sim::ExactDepth exact = sim::castExactDepth(sc.scene, camera);
    double nearest = 1e9;
    for (int v = 0; v < camera.height; ++v)
        for (int u = 0; u < camera.width; ++u) {
            const int q = exact.quad.at<int>(v, u);
            if (q >= 0 && sc.scene.quads[q].label == "person") nearest = std::min(nearest, exact.z.at<double>(v, u));
        }
    ASSERT_LT(nearest, 2.5);
    const Plane front = makePlane(sc.wall.normal, nearest);
    const Face f = renderFace(sc, camera, "person", front);
    ASSERT_GT(f.points.size(), 500u);
    EXPECT_TRUE(standsFree(surroundOf(f, camera)));
}

TEST(FaceSurround, ANarrowFaceOpenOnBothSidesStandsFreeWithItsTopOutOfView) {
    // A person 1.2 m from the camera fills the view's height: nothing is seen above them, the
    // wall is seen past them on both sides.
    FaceSurround s;
    s.width = 0.44;
    s.height = 0.9;
    s.top.unseen = 20;
    s.left.past = s.right.past = 20;
    EXPECT_TRUE(standsFree(s));
    FaceSurround one_side = s;  // a wall's end beside a doorway: open on one side only
    one_side.right = EdgeView{};
    one_side.right.front = 20;
    EXPECT_FALSE(standsFree(one_side));
    FaceSurround wide = s;  // as wide as a wall
    wide.width = 1.2;
    EXPECT_FALSE(standsFree(wide));
    FaceSurround ceiling = s;  // a narrow wall between two doorways, the ceiling seen above it
    ceiling.top = EdgeView{};
    ceiling.top.front = 20;
    EXPECT_FALSE(standsFree(ceiling));
}

TEST(FaceSurround, WallToTheViewsBorderDoesNot) {
    // Nothing beyond its top (the view ends, or no reading), the image's border beside it.
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 20.0);
    const Face f = renderFace(sc, camera, "wall", sc.wall);
    ASSERT_GT(f.points.size(), 10000u);
    const FaceSurround s = surroundOf(f, camera);
    EXPECT_EQ(s.top.past, 0);
    EXPECT_FALSE(standsFree(s));
}

TEST(FaceSurround, WallAtACornerDoesNot) {
    // The side wall comes towards the camera: in front of the main wall's plane.
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("corner", 2.0, 0.0);
    const Face f = renderFace(sc, camera, "wall", sc.wall);
    ASSERT_GT(f.points.size(), 10000u);
    const FaceSurround s = surroundOf(f, camera);
    EXPECT_GT(s.right.front, s.right.past);
    EXPECT_FALSE(standsFree(s));
}

TEST(FaceSurround, NothingToSayWithoutAnImage) {
    Cloud cloud;
    cloud.points = {Point(0, 0, 2), Point(1, 0, 2), Point(0, 1, 2)};
    cloud.width = 3;
    const FaceSurround s = faceSurround(cloud, CameraIntrinsics{}, PlaneFrame{}, {0, 1, 2}, DepthTolerance{});
    EXPECT_EQ(s.top.positions() + s.left.positions() + s.right.positions(), 0);
    EXPECT_FALSE(standsFree(s));
}

TEST(FaceSurround, AFarStrayPointIsBinnedWithoutOverflow) {
    // A wall image with one reading 10^12 m to the side among the face's points (a fuzzer's
    // input): the face is binned without converting that distance to an int (UBSan checks it).
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 0.0);
    Face f = renderFace(sc, camera, "wall", sc.wall);
    ASSERT_GT(f.points.size(), 1000u);
    f.cloud.points[f.points[0]] = Point(1e12f, 0.0f, 2.0f);
    const FaceSurround s = surroundOf(f, camera);
    EXPECT_GT(s.top.positions(), 0);
    EXPECT_FALSE(standsFree(s));
}

TEST(FaceSurround, OpenAboveABoxButNotAboveAWall) {
    // The box's top edge looks past its plane onto the wall behind; a wall's top looks at nothing
    // (the view ends) and a wall at a corner is bounded in front.
    const CameraIntrinsics camera;
    const sim::Scenario box = sim::makeScenario("big_obstacle", 2.0, 0.0);
    const Face front = renderFace(box, camera, "box", makePlane(box.wall.normal, box.wall.d - 0.45));
    ASSERT_GT(front.points.size(), 1000u);
    EXPECT_TRUE(openAbove(surroundOf(front, camera)));
    for (const char *name : {"wall", "corner"}) {
        const sim::Scenario sc = sim::makeScenario(name, 2.0, 0.0);
        const Face wall = renderFace(sc, camera, "wall", sc.wall);
        ASSERT_GT(wall.points.size(), 10000u);
        EXPECT_FALSE(openAbove(surroundOf(wall, camera))) << name;
    }
}

TEST(FaceSurround, AStripOfAWallIsLowerThanAPicture) {
    // The wall's points in a band of 8 image rows (about 3 cm at 2 m): a face no picture fits
    // on (FreeStandingRule::min_height); the whole wall is far taller.
    const CameraIntrinsics camera;
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 0.0);
    Face f = renderFace(sc, camera, "wall", sc.wall);
    ASSERT_GT(f.points.size(), 10000u);
    EXPECT_GT(surroundOf(f, camera).height, 1.0);
    std::vector<int> strip;
    for (int i : f.points)
        if (i / camera.width >= 240 && i / camera.width < 248) strip.push_back(i);
    ASSERT_GT(strip.size(), 1000u);
    f.points = strip;
    EXPECT_LT(surroundOf(f, camera).height, FreeStandingRule{}.min_height);
}
