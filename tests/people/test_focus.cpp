// Focus (contract "Focus"): depths along the projector's optical axis of the detected
// rectangle, against the simulator's truth (the same places on the real wall).
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "projsurf/detector/detector.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/people/focus.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf;

namespace {

/// Depth along the axis of the point of the real scene that the projector's ray through
/// `p` (a point the detection believes is on the wall) lights.
double trueDepth(const sim::Scene &scene, const Projector &projector, const Eigen::Vector3d &p) {
    const auto px = projector.toPixel(p);
    if (!px) return -1.0;
    const Eigen::Vector3d ray = projector.ray(*px);
    const auto hit = sim::castRay(scene, projector.origin, ray);
    if (!hit) return -1.0;
    return hit->t * ray.dot(projector.direction.normalized());
}

}  // namespace

TEST(Focus, FrontalAndTurnedRectangles) {
    Projector p;
    p.origin = {0.0, 0.12, 0.0};
    p.direction = {0.0, 0.0, 1.0};
    Rectangle r;
    r.corners = {Eigen::Vector3d(-0.5, -0.3, 2.0), Eigen::Vector3d(0.5, -0.3, 2.0), Eigen::Vector3d(0.5, 0.3, 2.0),
                 Eigen::Vector3d(-0.5, 0.3, 2.0)};
    Focus f = focusFor(p, r);
    EXPECT_NEAR(f.distance_m, 2.0, 1e-12);
    EXPECT_NEAR(f.nearest_m, 2.0, 1e-12);
    EXPECT_NEAR(f.farthest_m, 2.0, 1e-12);
    // Turn the rectangle: its right side 0.4 m farther.
    r.corners[1].z() = r.corners[2].z() = 2.4;
    f = focusFor(p, r);
    EXPECT_NEAR(f.distance_m, 2.2, 1e-12);
    EXPECT_NEAR(f.nearest_m, 2.0, 1e-12);
    EXPECT_NEAR(f.farthest_m, 2.4, 1e-12);
    // Along the axis, not the straight-line distance: a lens off the rectangle's centre line.
    p.origin = {1.0, 0.12, 0.5};
    f = focusFor(p, r);
    EXPECT_NEAR(f.distance_m, 1.7, 1e-12);
}

TEST(Focus, WithinOneCentimetreOfTheSimulatorsTruth) {
    const Projector projector = sim::exampleProjector();
    int checked = 0;
    double worst = 0.0;
    for (const double distance : {1.5, 2.5, 3.5}) {
        for (const double angle : {0.0, 17.19, 30.0}) {
            const sim::Scenario sc = sim::makeScenario("wall", distance, angle);
            const sim::RgbdFrame frame = sim::renderFrame(sc.scene, sim::SensorModel(), 7);
            DetectorConfig cfg;
            const Detection det = detectSurface(frame.cloud, projector, cfg, sc.gravity);
            ASSERT_TRUE(det.found) << distance << " m, " << angle << " deg: " << det.reason;
            const Focus f = focusFor(projector, det.rectangle);
            double near_true = 1e9, far_true = -1e9;
            for (const auto &c : det.rectangle.corners) {
                const double d = trueDepth(sc.scene, projector, c);
                ASSERT_GT(d, 0.0);
                near_true = std::min(near_true, d);
                far_true = std::max(far_true, d);
            }
            const double centre_true = trueDepth(sc.scene, projector, det.rectangle.center());
            EXPECT_NEAR(f.distance_m, centre_true, 0.01) << distance << " m, " << angle << " deg";
            EXPECT_NEAR(f.nearest_m, near_true, 0.01) << distance << " m, " << angle << " deg";
            EXPECT_NEAR(f.farthest_m, far_true, 0.01) << distance << " m, " << angle << " deg";
            worst = std::max({worst, std::abs(f.distance_m - centre_true), std::abs(f.nearest_m - near_true),
                              std::abs(f.farthest_m - far_true)});
            if (angle > 10.0) {
                EXPECT_GT(f.farthest_m - f.nearest_m, 0.1);  // a turned wall spreads the depths
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 9);
    std::printf("focus vs the simulator's truth over %d wall poses (1.5-3.5 m, 0-30 deg): worst error %.1f mm\n",
                checked, 1000.0 * worst);
}

TEST(Focus, DetectionJsonCarriesItAndTheReaderAcceptsBoth) {
    const Projector projector = sim::exampleProjector();
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 17.19);
    const sim::RgbdFrame frame = sim::renderFrame(sc.scene, sim::SensorModel(), 3);
    DetectorConfig cfg;
    const Detection det = detectSurface(frame.cloud, projector, cfg, sc.gravity);
    ASSERT_TRUE(det.found);
    const nlohmann::json with = detectionToJson(det, cfg, &projector);
    const nlohmann::json without = detectionToJson(det, cfg);
    ASSERT_TRUE(with.contains("focus"));
    EXPECT_FALSE(without.contains("focus"));
    const Focus f = focusFor(projector, det.rectangle);
    EXPECT_NEAR(with["focus"]["distance_m"].get<double>(), f.distance_m, 1e-6);
    EXPECT_NEAR(with["focus"]["nearest_m"].get<double>(), f.nearest_m, 1e-6);
    EXPECT_NEAR(with["focus"]["farthest_m"].get<double>(), f.farthest_m, 1e-6);
    // Every other key is as before.
    nlohmann::json stripped = with;
    stripped.erase("focus");
    EXPECT_EQ(stripped, without);

    const auto dir = std::filesystem::temp_directory_path() / ("people_focus_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (const auto &[name, j] : {std::pair{"with.json", with}, std::pair{"without.json", without}}) {
        std::ofstream((dir / name).string()) << j.dump(2);
        const DetectionFile file = readDetectionJson((dir / name).string());
        EXPECT_TRUE(file.found);
        EXPECT_NEAR((file.rectangle.corners[0] - det.rectangle.corners[0]).norm(), 0.0, 1e-6);
    }
    std::filesystem::remove_all(dir);

    // Nothing found: focus is null.
    Detection none;
    EXPECT_TRUE(detectionToJson(none, cfg, &projector)["focus"].is_null());
}
