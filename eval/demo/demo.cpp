#include "eval/demo/demo.hpp"

#include <chrono>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "projsurf/frontend/render/test_card.hpp"
#include "projsurf/sim/ray_cast.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

DemoResult runDemo(const DemoOptions &o) {
    DemoResult res;
    const auto t_all = Clock::now();
    auto t = Clock::now();
    res.scenario = makeScenario(o.scenario, o.distance, o.angle_deg);
    res.true_projector = exampleProjector();
    const Projector &real = res.true_projector;
    const SensorModel sensor;  // Kinect v1 class, noisy

    // 1. Calibrate from simulated captures of the disc (paper 3.1).
    res.calibration = calibrateFromSimulation(real, sensor, o.captures, o.seed);
    res.stage_ms.emplace_back("calibration (render " + std::to_string(o.captures) + " captures + calibrate)",
                              msSince(t));
    const Projector believed = res.calibration.ok ? res.calibration.projector : real;

    // 2. Look at the scene.
    t = Clock::now();
    res.frame = renderFrame(res.scenario.scene, sensor, o.seed);
    res.stage_ms.emplace_back("render the RGB-D frame", msSince(t));

    // 3. Detect with the calibrated projector, and score against ground truth.
    res.config = o.config;
    res.config.seed = o.seed;
    res.picture = o.picture.empty() ? frontend::testCard(cv::Size(real.width, real.height)) : o.picture;
    res.config.aspect = static_cast<double>(res.picture.cols) / res.picture.rows;
    res.detection = detectSurface(res.frame.cloud, believed, res.config, res.scenario.gravity);
    res.stage_ms.emplace_back("detect",
                              res.detection.timing_ms.count("total") ? res.detection.timing_ms.at("total") : 0.0);
    t = Clock::now();
    TruthOptions topt;
    topt.aspect = res.config.aspect;
    res.truth = computeGroundTruth(res.scenario.scene, sensor, real, res.scenario.gravity, topt);
    res.score = scoreDetection(res.detection, res.truth, real, res.scenario.gravity, res.config.aspect);
    res.stage_ms.emplace_back("ground truth + score", msSince(t));

    // 4. Correct the picture (paper 3.3) with the calibrated projector.
    t = Clock::now();
    res.framebuffer = cv::Mat(believed.height, believed.width, CV_8UC3, cv::Scalar::all(0));
    if (res.detection.found) {
        const KeystoneResult k = computeKeystone(believed, res.detection.rectangle, res.picture.size());
        if (k.keystone) {
            res.keystone = k.keystone;
            res.framebuffer = warpToFramebuffer(res.picture, *k.keystone);
        } else {
            res.keystone_problem = k.problem;
        }
    } else {
        res.keystone_problem = "nothing to correct: " + res.detection.reason;
    }
    res.stage_ms.emplace_back("correct (eq. 7, homography, warp)", msSince(t));

    // 5. Where the pictures land on the real wall (through the TRUE projector) and eq. 8.
    if (res.keystone) res.corrected_on_wall = framebufferOnWall(real, res.scenario.scene, res.keystone->picture_px);
    res.uncorrected_on_wall = framebufferOnWall(real, res.scenario.scene, real.framebufferCorners());

    // 6. What the audience sees: the picture as is, and corrected (Fig 1).
    t = Clock::now();
    cv::Mat as_is;
    cv::resize(res.picture, as_is, cv::Size(real.width, real.height), 0, 0, cv::INTER_AREA);
    Eigen::Vector3d target = res.scenario.wall.project(real.origin + 2.0 * real.direction);
    if (const auto hit = intersectRay(res.scenario.wall, real.origin, real.direction)) target = *hit;
    const double view_distance = std::max(2.5, 1.3 * o.distance);  // m, a person facing the wall
    const PinholeView viewer = facingView(res.scenario.wall, target, view_distance, res.scenario.gravity,
                                          o.audience_size.width, o.audience_size.height, o.audience_hfov_deg);
    Lighting light;
    light.ambient = 0.22;  // a dim room, a little brighter than the camera's so the wall shows
    res.audience_uncorrected = renderView(res.scenario.scene, viewer, Projection{real, as_is}, light);
    res.audience_corrected = renderView(res.scenario.scene, viewer, Projection{real, res.framebuffer}, light);
    res.audience_view = viewer;
    res.audience_light = light;
    res.stage_ms.emplace_back("render the audience views", msSince(t));
    res.stage_ms.emplace_back("total", msSince(t_all));
    return res;
}

}  // namespace projsurf::eval
