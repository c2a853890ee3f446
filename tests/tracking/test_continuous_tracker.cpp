// Continuous mode as every front end runs it (tracking/continuous_tracker.hpp): detections in
// the camera frame, the camera's pose in a fixed frame, the picture kept put there.
#include <gtest/gtest.h>

#include <random>

#include "projsurf/tracking/continuous_tracker.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/rigid_transform.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;

namespace {

/// A noisy view of `wall` (camera frame), unorganized.
Cloud cloudOf(const Plane &wall, std::mt19937 &rng) {
    Cloud c;
    c.points = rig::noisyWallCloud(wall, CameraIntrinsics(), rng);
    c.width = static_cast<int>(c.points.size());
    return c;
}

/// What a detector would say: `rect` found on `wall` (camera frame), a level camera.
Detection detectionOf(const Plane &wall, const Rectangle &rect) {
    Detection d;
    d.found = true;
    d.plane = wall;
    d.rectangle = rect;
    d.gravity = Eigen::Vector3d(0, 1, 0);
    return d;
}

/// `rect` moved by (dx, dy) m in the camera frame, as a noisy detector reports it.
Rectangle shifted(const Rectangle &rect, double dx, double dy) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(dx, dy, 0.0);
    return transformRectangle(rect, t);
}

double maxCornerMove(const Rectangle &a, const Rectangle &b) {
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) worst = std::max(worst, (a.corners[i] - b.corners[i]).norm());
    return worst;
}

ContinuousSettings settings() {
    ContinuousSettings s;
    s.projector = rig::trueProjector();
    return s;
}

}  // namespace

TEST(ContinuousTracker, ARobotStandingStillKeepsThePictureWhileTheDetectionJitters) {
    std::mt19937 rng(3);
    const Plane wall = rig::wall(2.0, 0.0);
    const Rectangle rect = rig::rectangleInWorkspace(rig::trueProjector(), wall, 0.7);
    ContinuousTracker tracker(settings());
    const ContinuousFrame first =
        tracker.update(detectionOf(wall, rect), cloudOf(wall, rng), Eigen::Isometry3d::Identity());
    EXPECT_EQ(first.event, SteadyEvent::Acquired);
    ASSERT_TRUE(first.has_target);
    EXPECT_NEAR(first.shown.width, tracker.settings().steady.scale * rect.width, 1e-9);
    std::uniform_real_distribution<double> jitter(-0.03, 0.03);  // m: the detection's corners wander 3 cm
    double raw_moved = 0.0;
    for (int i = 0; i < 8; ++i) {
        const Rectangle seen = shifted(rect, jitter(rng), jitter(rng));
        raw_moved = std::max(raw_moved, maxCornerMove(seen, rect));
        const ContinuousFrame f =
            tracker.update(detectionOf(wall, seen), cloudOf(wall, rng), Eigen::Isometry3d::Identity());
        EXPECT_EQ(f.event, SteadyEvent::Kept) << "frame " << i;
        ASSERT_TRUE(f.has_target);
        EXPECT_LT(maxCornerMove(f.shown, first.shown), 1e-9) << "frame " << i;
    }
    EXPECT_GT(raw_moved, 0.01);  // the raw detection did move
}

TEST(ContinuousTracker, TheHeldPictureStaysPutInTheFixedFrameWhenTheCameraMoves) {
    std::mt19937 rng(5);
    const Plane wall = rig::wall(2.0, 0.0);  // in the first camera frame = the fixed frame
    const Rectangle rect = rig::rectangleInWorkspace(rig::trueProjector(), wall, 0.7);
    ContinuousTracker tracker(settings());
    const ContinuousFrame first =
        tracker.update(detectionOf(wall, rect), cloudOf(wall, rng), Eigen::Isometry3d::Identity());
    ASSERT_TRUE(first.has_target);
    // The robot drove 4 cm to the right along the wall: the fixed frame sees the camera at x = 0.04.
    Eigen::Isometry3d fixed_from_camera = Eigen::Isometry3d::Identity();
    fixed_from_camera.translation() = Eigen::Vector3d(0.04, 0.0, 0.0);
    const Eigen::Isometry3d camera_from_fixed = fixed_from_camera.inverse();
    const Plane wall_now = transformPlane(wall, camera_from_fixed);
    const ContinuousFrame f = tracker.update(detectionOf(wall_now, transformRectangle(rect, camera_from_fixed)),
                                             cloudOf(wall_now, rng), fixed_from_camera);
    EXPECT_EQ(f.event, SteadyEvent::Kept);
    ASSERT_TRUE(f.has_target);
    // In the new camera frame the picture sits 4 cm further left: the same place on the wall.
    EXPECT_LT(maxCornerMove(transformRectangle(f.shown, fixed_from_camera), first.shown), 1e-9);
    EXPECT_NEAR((f.shown.center() - first.shown.center()).x(), -0.04, 1e-9);
}

TEST(ContinuousTracker, NothingFoundNothingShownAndResetForgetsThePicture) {
    std::mt19937 rng(7);
    const Plane wall = rig::wall(2.0, 0.0);
    const Rectangle rect = rig::rectangleInWorkspace(rig::trueProjector(), wall, 0.7);
    ContinuousTracker tracker(settings());
    const ContinuousFrame none = tracker.update(Detection{}, cloudOf(wall, rng), Eigen::Isometry3d::Identity());
    EXPECT_EQ(none.event, SteadyEvent::None);
    EXPECT_FALSE(none.has_target);
    tracker.update(detectionOf(wall, rect), cloudOf(wall, rng), Eigen::Isometry3d::Identity());
    EXPECT_TRUE(tracker.tracker().hasTarget());
    tracker.reset();
    EXPECT_FALSE(tracker.tracker().hasTarget());
    const ContinuousFrame again =
        tracker.update(detectionOf(wall, shifted(rect, 0.05, 0.0)), cloudOf(wall, rng), Eigen::Isometry3d::Identity());
    EXPECT_EQ(again.event, SteadyEvent::Acquired);
}
