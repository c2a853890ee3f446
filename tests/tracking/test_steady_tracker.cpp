// Continuous-mode steadiness: the picture stays put, ignores noise, and does not jump
// between walls unless the held place cannot be shown and another wins several frames.
#include <gtest/gtest.h>

#include <random>

#include "projsurf/tracking/steady_tracker.hpp"

using namespace projsurf;

namespace {

// A wall facing the camera: the plane z = depth (normal towards the camera, -z).
Plane wallAt(double depth) { return makePlane({0.0, 0.0, -1.0}, depth); }

// Upright rectangle of width w, height h centred at (cx, cy) on the wall z = depth.
Rectangle rectOn(double depth, double cx, double cy, double w, double h) {
    const PlaneFrame f = makePlaneFrame(wallAt(depth), {0.0, 1.0, 0.0}, {cx, cy, depth});
    return makeRectangle(f, {-w / 2, -h / 2}, {w / 2, h / 2});
}

// A side wall x = 1.5 (normal towards the camera, -x).
Plane sideWall() { return makePlane({-1.0, 0.0, 0.0}, 1.5); }
Rectangle rectOnSide(double w, double h) {
    const PlaneFrame f = makePlaneFrame(sideWall(), {0.0, 1.0, 0.0}, {1.5, 0.0, 2.5});
    return makeRectangle(f, {-w / 2, -h / 2}, {w / 2, h / 2});
}

SteadyMeasurement seen(const Plane &p, const Rectangle &r, bool held_usable) {
    SteadyMeasurement m;
    m.found = true;
    m.plane = p;
    m.rectangle = r;
    m.held_usable = held_usable;
    return m;
}

double maxCornerMove(const Rectangle &a, const Rectangle &b) {
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) worst = std::max(worst, (a.corners[i] - b.corners[i]).norm());
    return worst;
}

}  // namespace

TEST(SteadyTracker, AcquiresTheFirstRectangleScaledAboutItsCentre) {
    SteadyConfig cfg;
    cfg.scale = 0.8;
    SteadyTracker t(cfg);
    EXPECT_EQ(t.update(SteadyMeasurement{}), SteadyEvent::None);
    EXPECT_FALSE(t.hasTarget());
    const Rectangle r = rectOn(2.0, 0.1, -0.2, 1.0, 0.625);
    EXPECT_EQ(t.update(seen(wallAt(2.0), r, false)), SteadyEvent::Acquired);
    ASSERT_TRUE(t.hasTarget());
    EXPECT_NEAR(t.target().width, 0.8, 1e-12);
    EXPECT_NEAR(t.target().height, 0.5, 1e-12);
    EXPECT_NEAR((t.target().center() - r.center()).norm(), 0.0, 1e-12);
    // Still upright: the left edge runs along gravity.
    const Eigen::Vector3d left = t.target().corners[3] - t.target().corners[0];
    EXPECT_NEAR(left.normalized().dot(Eigen::Vector3d(0, 1, 0)), 1.0, 1e-9);
}

TEST(SteadyTracker, NoisyDetectionsOfTheSameWallDoNotMoveThePicture) {
    SteadyTracker t;
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.01);  // 1 cm on every corner and the depth
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.2, 0.75), false));
    const Rectangle first = t.target();
    for (int i = 0; i < 200; ++i) {
        const double depth = 2.0 + noise(rng);
        const Rectangle r = rectOn(depth, noise(rng), noise(rng), 1.2 + noise(rng), 0.75 + noise(rng));
        EXPECT_EQ(t.update(seen(wallAt(depth), r, true)), SteadyEvent::Kept);
    }
    // Only the smoothed depth may change: within a few millimetres, not the 1 cm noise.
    EXPECT_LT(maxCornerMove(first, t.target()), 0.006);
}

TEST(SteadyTracker, AlternatingBestWallsDoNotMakeThePictureJump) {
    SteadyTracker t;
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.0, 0.625), false));
    const Rectangle first = t.target();
    for (int i = 0; i < 50; ++i) {
        // Every other frame a much bigger side wall wins the detector; the held one still fits.
        const SteadyMeasurement m = i % 2 == 0 ? seen(sideWall(), rectOnSide(2.0, 1.25), true)
                                               : seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.0, 0.625), true);
        EXPECT_EQ(t.update(m), SteadyEvent::Kept) << "frame " << i;
    }
    EXPECT_LT(maxCornerMove(first, t.target()), 1e-9);
}

TEST(SteadyTracker, AnotherWallWinsOnlyAfterSwitchFramesWhenTheHeldOneIsGone) {
    SteadyConfig cfg;
    cfg.switch_frames = 4;
    cfg.hold_frames = 100;
    SteadyTracker t(cfg);
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.0, 0.625), false));
    for (int i = 1; i < cfg.switch_frames; ++i)
        EXPECT_EQ(t.update(seen(sideWall(), rectOnSide(1.0, 0.625), false)), SteadyEvent::Held) << i;
    EXPECT_EQ(t.update(seen(sideWall(), rectOnSide(1.0, 0.625), false)), SteadyEvent::Switched);
    EXPECT_NEAR(std::abs(t.plane().normal.x()), 1.0, 1e-9);
}

TEST(SteadyTracker, AMuchBiggerPlaceWinsOnlyWhenItPersists) {
    SteadyConfig cfg;
    cfg.switch_frames = 3;
    SteadyTracker t(cfg);
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 0.5, 0.3125), false));
    const SteadyMeasurement big = seen(wallAt(2.0), rectOn(2.0, 0.3, 0.0, 1.5, 0.9375), true);
    EXPECT_EQ(t.update(big), SteadyEvent::Kept);
    EXPECT_EQ(t.update(big), SteadyEvent::Kept);
    EXPECT_EQ(t.update(big), SteadyEvent::Moved);
    EXPECT_NEAR(t.target().width, 1.5 * cfg.scale, 1e-9);
}

TEST(SteadyTracker, ThePictureMovesAlongTheSameWallWhenItNoLongerFits) {
    SteadyTracker t;
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.0, 0.625), false));
    const Rectangle shifted = rectOn(2.0, 0.4, 0.0, 1.0, 0.625);
    EXPECT_EQ(t.update(seen(wallAt(2.0), shifted, false)), SteadyEvent::Moved);
    EXPECT_NEAR((t.target().center() - shifted.center()).norm(), 0.0, 1e-9);
}

TEST(SteadyTracker, KeepsThePictureThroughMissedFramesThenGivesUp) {
    SteadyConfig cfg;
    cfg.hold_frames = 3;
    SteadyTracker t(cfg);
    t.update(seen(wallAt(2.0), rectOn(2.0, 0.0, 0.0, 1.0, 0.625), false));
    SteadyMeasurement nothing;
    nothing.held_usable = true;
    EXPECT_EQ(t.update(nothing), SteadyEvent::Kept);  // detector failed, the place is still fine
    nothing.held_usable = false;
    for (int i = 0; i < cfg.hold_frames; ++i) EXPECT_EQ(t.update(nothing), SteadyEvent::Held);
    EXPECT_EQ(t.update(nothing), SteadyEvent::Lost);
    EXPECT_FALSE(t.hasTarget());
}

TEST(SteadyTracker, FitsProjectorChecksEveryCornerAgainstTheFramebuffer) {
    Projector p;  // contract defaults: 1280x800, 39.3 x 24 deg, lens 12 cm below the camera
    p.origin = Eigen::Vector3d(0.0, 0.12, 0.0);
    p.direction = Eigen::Vector3d(0.0, 0.0, 1.0);
    // At 2 m the footprint is about 1.43 m x 0.85 m around (0, 0.12).
    const Rectangle inside = rectOn(2.0, 0.0, 0.12, 1.2, 0.75);
    EXPECT_TRUE(fitsProjector(p, inside));
    EXPECT_FALSE(fitsProjector(p, rectOn(2.0, 0.2, 0.12, 1.2, 0.75)));         // right edge out
    EXPECT_FALSE(fitsProjector(p, rectOn(2.0, 0.0, 0.12, 1.2, 0.75), 200.0));  // margin too big
    EXPECT_FALSE(fitsProjector(p, rectOn(-2.0, 0.0, 0.12, 1.2, 0.75)));        // behind the lens
}
