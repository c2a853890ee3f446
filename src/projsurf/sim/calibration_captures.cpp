#include "projsurf/sim/calibration_captures.hpp"

#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/calibration_picture.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/sim/scenarios.hpp"

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
        PatternCapture cap;
        cv::RNG rng(seed + 100u * static_cast<unsigned>(k) + 7u);
        for (std::size_t i = 0; i < patterns.size(); ++i) {
            cv::Mat fb;
            cv::cvtColor(grayPatternImage(patterns[i], projector.width, projector.height), fb, cv::COLOR_GRAY2BGR);
            RgbdFrame f =
                renderFrame(sc.scene, sensor, seed + 100u * static_cast<unsigned>(k) + static_cast<unsigned>(i),
                            Projection{projector, fb}, light);
            if (i == 0) cap.depth = f.depth;
            cv::Mat img;
            f.rgb.convertTo(img, CV_32FC3);
            if (model.blur_sigma_px > 0) cv::GaussianBlur(img, img, cv::Size(0, 0), model.blur_sigma_px);
            cv::Mat noise(img.size(), CV_32FC3);
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
