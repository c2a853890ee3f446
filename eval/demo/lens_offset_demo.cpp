#include "eval/demo/lens_offset_demo.hpp"

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

LensOffsetShot showWith(const Projector &believed, const Projector &truth, const Scenario &scenario,
                        const RgbdFrame &frame, const cv::Mat &picture, const PinholeView &viewer,
                        const Lighting &light, unsigned seed) {
    LensOffsetShot s;
    s.believed = believed;
    DetectorConfig config;
    config.seed = seed;
    config.aspect = static_cast<double>(picture.cols) / picture.rows;
    s.detection = detectSurface(frame.cloud, believed, config, scenario.gravity);
    cv::Mat framebuffer(truth.height, truth.width, CV_8UC3, cv::Scalar::all(0));
    if (!s.detection.found) {
        s.problem = "nothing found: " + s.detection.reason;
    } else if (const KeystoneResult k = computeKeystone(believed, s.detection.rectangle, picture.size()); !k.keystone) {
        s.problem = k.problem;
    } else {
        framebuffer = warpToFramebuffer(picture, *k.keystone);
        s.on_wall = pictureOnWall(believed, truth, scenario.scene, s.detection.rectangle, picture.size());
        s.ok = s.on_wall.ok;
        if (!s.ok) s.problem = s.on_wall.problem;
    }
    s.audience = renderView(scenario.scene, viewer, Projection{truth, framebuffer}, light);
    return s;
}

}  // namespace

LensOffsetDemo runLensOffsetDemo(const Scenario &scenario, const cv::Mat &picture, const PinholeView &viewer,
                                 const Lighting &light, unsigned seed) {
    LensOffsetDemo d;
    d.truth = projectorRig(d.rig);
    const SensorModel sensor;
    const RgbdFrame frame = renderFrame(scenario.scene, sensor, seed);

    // The disc method knows the field of view from the spec sheet, and nothing of the offset.
    Projector spec = d.truth;
    const auto fov = fieldOfView(d.truth);
    spec.fov_h = fov[0];
    spec.fov_v = fov[1];
    const CalibrationRun disc = calibrateFromSimulation(spec, sensor, 5, seed);
    if (disc.ok) {
        d.disc = showWith(disc.projector, d.truth, scenario, frame, picture, viewer, light, seed);
    } else {
        d.disc.problem = "disc calibration failed: " + disc.message;
    }
    const ProjectorFit fit = structuredCalibration(d.truth, sensor, flatWallPoses(), seed + 1);
    if (fit.ok) {
        d.structured = showWith(fit.projector, d.truth, scenario, frame, picture, viewer, light, seed);
    } else {
        d.structured.problem = "structured-light calibration failed: " + fit.problem;
    }
    return d;
}

}  // namespace projsurf::eval
