// Blanking what stands in the beam (contract "Blanking"): a person walks into the
// beam of a placed picture; no lit pixel may fall on them, the rest of the picture stays lit,
// and sensor noise on an empty wall blanks (almost) nothing.
#include <gtest/gtest.h>

#include <cstdio>

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/people/beam_blanking.hpp"
#include "eval/demo/walk_in.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/render/test_card.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf::eval;  // the evaluation under test

using namespace projsurf;

namespace {

struct Placed {
    sim::Scenario scenario;
    Detection detection;
    cv::Mat framebuffer;  ///< the corrected picture, before any blanking
};

/// A frame of `scene` through the independent-noise model (kinect1 = false) or a realistic
/// Kinect v1 unit.
sim::RgbdFrame look(const sim::Scene &scene, bool kinect1, unsigned seed) {
    if (!kinect1) return sim::renderFrame(scene, sim::SensorModel(), seed);
    return sim::renderSensorFrame(scene, sim::makeDepthSensor(sim::SensorKind::Kinect1, 1), seed, std::nullopt, false);
}

/// Detects on the empty scene and corrects the test card into the framebuffer.
Placed placePicture(double distance, double angle, bool kinect1) {
    Placed p;
    p.scenario = sim::makeScenario("wall", distance, angle);
    const Projector projector = sim::exampleProjector();
    const sim::RgbdFrame frame = look(p.scenario.scene, kinect1, 5);
    p.detection = detectSurface(frame.cloud, projector, DetectorConfig{}, p.scenario.gravity);
    if (!p.detection.found) return p;
    const KeystoneResult k = computeKeystone(projector, p.detection.rectangle, cv::Size(1280, 800));
    if (k.keystone) p.framebuffer = warpToFramebuffer(frontend::testCard(cv::Size(1280, 800)), *k.keystone);
    return p;
}

}  // namespace

TEST(Blanking, PointsBehindThePlaneOrNearItBlankNothing) {
    const Projector projector = sim::exampleProjector();
    const Plane wall = makePlane(Eigen::Vector3d(0, 0, -1), 2.0);  // z = 2
    Cloud cloud;
    cloud.width = 40;
    cloud.height = 40;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x)
            cloud.points.emplace_back(-0.2f + 0.01f * x, -0.2f + 0.01f * y, 1.96f);  // 4 cm proud
    BeamBlanker blanker(projector);
    EXPECT_EQ(cv::countNonZero(blanker.compute(cloud, wall)), 0);
    for (auto &p : cloud.points) p.z() = 2.3f;  // behind the wall
    EXPECT_EQ(cv::countNonZero(blanker.compute(cloud, wall)), 0);
    for (auto &p : cloud.points) p.z() = 1.5f;  // a 40 x 40 cm board half a metre in front
    const cv::Mat &mask = blanker.compute(cloud, wall);
    EXPECT_GT(blanker.blankedPixels(), 0);
    EXPECT_EQ(blanker.blankedPixels(), cv::countNonZero(mask));
    // Every pixel whose ray passes through the board is blanked; a pixel 10 cm (on the board)
    // outside it is not.
    const auto board = [&](double x, double y) { return *projector.toPixel(Eigen::Vector3d(x, y, 1.5)); };
    for (double x = -0.2; x <= 0.19; x += 0.013)
        for (double y = -0.2; y <= 0.19; y += 0.013) {
            const Eigen::Vector2d px = board(x, y);
            EXPECT_EQ(mask.at<uchar>(static_cast<int>(std::lround(px.y())), static_cast<int>(std::lround(px.x()))), 255)
                << x << ", " << y;
        }
    const Eigen::Vector2d off = board(0.30, 0.0);
    EXPECT_EQ(mask.at<uchar>(static_cast<int>(std::lround(off.y())), static_cast<int>(std::lround(off.x()))), 0);
    // One stray reading is noise, not an obstruction.
    for (auto &p : cloud.points) p.z() = 2.0f;
    cloud.points[20 * 40 + 20].z() = 1.2f;
    blanker.compute(cloud, wall);
    EXPECT_EQ(blanker.blankedPixels(), 0);
    BlankingOptions raw;
    raw.filter_noise = false;
    BeamBlanker every_point(projector, raw);
    every_point.compute(cloud, wall);
    EXPECT_GT(every_point.blankedPixels(), 0);
}

TEST(Blanking, PersonWalkingIntoTheBeam) {
    struct Case {
        double distance, angle;
        bool kinect1;
    };
    for (const Case c : {Case{2.5, 0.0, false}, Case{2.5, 17.19, false}, Case{2.8, 10.0, true}}) {
        const Placed placed = placePicture(c.distance, c.angle, c.kinect1);
        ASSERT_TRUE(placed.detection.found) << placed.detection.reason;
        ASSERT_FALSE(placed.framebuffer.empty());
        const Projector projector = sim::exampleProjector();
        BeamBlanker blanker(projector);
        // From outside the beam on the left to its middle, 1.4 m from the camera, arm out.
        const auto frames = eval::walkInScenes(placed.scenario.scene, -1.3, 0.1, 6, 1.4);
        for (std::size_t k = 0; k < frames.size(); ++k) {
            const sim::RgbdFrame frame = look(frames[k], c.kinect1, 100 + static_cast<unsigned>(k));
            cv::Mat fb = placed.framebuffer.clone();
            applyBlanking(fb, blanker.compute(frame.cloud, placed.detection.plane));
            const eval::BeamScore s =
                eval::scoreBlanking(frames[k], placed.scenario.wall, projector, placed.framebuffer, fb);
            std::printf(
                "walk-in %.1f m %.2f deg %s frame %zu: %ld px on the person, %ld of them lit; %ld picture px "
                "> 10 cm away, %.2f %% lit; %d px blanked\n",
                c.distance, c.angle, c.kinect1 ? "kinect1" : "K&OE", k, s.on_person, s.lit_on_person, s.far_pixels,
                100.0 * s.farLitShare(), blanker.blankedPixels());
            EXPECT_EQ(s.lit_on_person, 0) << "frame " << k;
            EXPECT_GE(s.farLitShare(), 0.95) << "frame " << k;
            if (k + 1 == frames.size()) {
                EXPECT_GT(s.on_person, 10000);  // the person did walk in
            }
        }
    }
}

TEST(Blanking, RealisticKinectNoiseOnAnEmptyWallBlanksAlmostNothing) {
    const Projector projector = sim::exampleProjector();
    BeamBlanker blanker(projector);
    const double pixels = 1280.0 * 800.0;
    for (const double distance : {2.0, 2.8, 3.5}) {
        for (const int unit : {0, 1, 2}) {
            const sim::Scenario sc = sim::makeScenario("wall", distance, 10.0);
            const sim::DepthSensor sensor = sim::makeDepthSensor(sim::SensorKind::Kinect1, unit);
            const sim::RgbdFrame first = sim::renderSensorFrame(sc.scene, sensor, 1, std::nullopt, false);
            const Detection det = detectSurface(first.cloud, projector, DetectorConfig{}, sc.gravity);
            ASSERT_TRUE(det.found) << distance << " m unit " << unit << ": " << det.reason;
            for (unsigned seed = 2; seed < 5; ++seed) {
                const sim::RgbdFrame frame = sim::renderSensorFrame(sc.scene, sensor, seed, std::nullopt, false);
                blanker.compute(frame.cloud, det.plane);
                const double share = blanker.blankedPixels() / pixels;
                if (seed == 2) {
                    std::printf("empty wall %.1f m, kinect1 unit %d: %d obstructing readings, %.3f %% blanked\n",
                                distance, unit, blanker.candidatePoints(), 100.0 * share);
                }
                EXPECT_LT(share, 0.005) << distance << " m unit " << unit << " seed " << seed;
            }
        }
    }
}
