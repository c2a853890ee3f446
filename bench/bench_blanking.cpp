#include "bench_blanking.hpp"

#include "eval/demo/walk_in.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf::eval;  // the evaluation under test

namespace projsurf::bench {

std::vector<BlankingCase> blankingCases(const std::vector<BenchFrame> &real, const Projector &projector) {
    std::vector<BlankingCase> out;
    const sim::DepthSensor kinect = sim::makeDepthSensor(sim::SensorKind::Kinect1, 0);
    const sim::Scenario sc = sim::makeScenario("wall", 2.5, 10.0);
    const sim::RgbdFrame empty = sim::renderSensorFrame(sc.scene, kinect, 1, std::nullopt, false);
    const Detection det = detectSurface(empty.cloud, projector, DetectorConfig{}, sc.gravity);
    const Plane plane = det.found ? det.plane : sc.wall;
    out.push_back({"sim: empty wall 2.5 m, Kinect v1", empty.cloud, plane});
    const auto walk = eval::walkInScenes(sc.scene, -0.6, -0.6, 1, 1.4);
    out.push_back({"sim: person in the beam, Kinect v1",
                   sim::renderSensorFrame(walk[0], kinect, 2, std::nullopt, false).cloud, plane});
    for (const auto &f : real) {
        const Detection d = detectSurface(f.cloud, projector, DetectorConfig{}, f.gravity);
        if (d.inliers > 0) out.push_back({"real: " + f.name, f.cloud, d.plane});
    }
    return out;
}

}  // namespace projsurf::bench
