#include "projsurf/sim/calibration_captures.hpp"

#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/calibration_picture.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::sim {

std::vector<RgbdFrame> renderCalibrationCaptures(const Projector &projector, const SensorModel &sensor, int count,
                                                 unsigned seed, double roll_deg, double pitch_deg) {
    if (count < 1) throw std::invalid_argument("calibration captures: count must be at least 1");
    const cv::Mat disc = calibrationPicture(projector.width, projector.height);
    const double angles[] = {0.0, 10.0, -10.0, 20.0, -20.0};  // deg, robot turned a little
    std::vector<RgbdFrame> frames;
    frames.reserve(count);
    for (int k = 0; k < count; ++k) {
        const double d = count > 1 ? 1.2 + 1.8 * k / (count - 1) : 1.2;  // m, 1.2-3.0 m
        Scenario wall = makeScenario("wall", d, angles[k % 5]);
        if (pitch_deg != 0.0) pitchCamera(wall, pitch_deg);
        if (roll_deg != 0.0) rollCamera(wall, roll_deg);
        frames.push_back(
            renderFrame(wall.scene, sensor, seed + 1000u + static_cast<unsigned>(k), Projection{projector, disc}));
    }
    return frames;
}

std::vector<PatternCapture> renderPatternCaptures(const Projector &projector, const SensorModel &sensor,
                                                  const std::vector<PatternPose> &poses, unsigned seed,
                                                  const PatternCameraModel &model) {
    const auto patterns = grayPatterns(projector.width, projector.height);
    std::vector<PatternCapture> out;
    Lighting light;
    light.ambient = model.ambient;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const PatternPose &pose = poses[k];
        Scenario sc = makeScenario(pose.scenario, pose.distance, pose.angle_deg);
        if (pose.pitch_deg != 0.0) pitchCamera(sc, pose.pitch_deg);
        if (pose.roll_deg != 0.0) rollCamera(sc, pose.roll_deg);
        // The depth once per position; the patterns through the light transport, which is what
        // renderFrame's colour is without its noise, cast once for all of them.
        const unsigned pose_seed = seed + 100u * static_cast<unsigned>(k);
        PatternCapture cap;
        cap.depth = renderFrame(sc.scene, sensor, pose_seed).depth;
        const LightTransport transport = lightTransport(sc.scene, cameraView(sensor.camera), projector, light);
        const double sensor_sigma = sensor.noise ? sensor.rgb_noise : 0.0;  // grey levels
        cv::RNG rng(pose_seed + 7u);
        for (const auto &pattern : patterns) {
            cv::Mat fb;
            cv::cvtColor(grayPatternImage(pattern, projector.width, projector.height), fb, cv::COLOR_GRAY2BGR);
            cv::Mat img = litBy(transport, fb) * 255.0;
            cv::Mat noise(img.size(), CV_32FC3);
            if (sensor_sigma > 0) {
                rng.fill(noise, cv::RNG::NORMAL, 0.0, sensor_sigma);
                img += noise;
            }
            img.convertTo(img, CV_8UC3);  // the sensor's own 8-bit image
            img.convertTo(img, CV_32FC3);
            if (model.blur_sigma_px > 0) cv::GaussianBlur(img, img, cv::Size(0, 0), model.blur_sigma_px);
            rng.fill(noise, cv::RNG::NORMAL, 0.0, model.noise_sigma);
            img += noise;
            img.convertTo(img, CV_8UC3);
            cap.colour.push_back(img);
        }
        out.push_back(std::move(cap));
    }
    return out;
}

std::vector<CaptureImages> captureImages(const std::vector<RgbdFrame> &frames) {
    std::vector<CaptureImages> out;
    out.reserve(frames.size());
    for (const auto &f : frames) out.push_back(CaptureImages{f.rgb, f.depth});
    return out;
}

}  // namespace projsurf::sim
